// Certified sign filters on interval polynomials (docs/MATH.md §3.8). They decide "no root" or "sign at a
// point" without exact arithmetic whenever the enclosures allow it; otherwise they answer 0 and the
// caller falls back to exact arithmetic. Callers must hold a CGAL::Protect_FPU_rounding guard.
#pragma once

#include "polynomial.h"

#include <CGAL/Interval_nt.h>

#include <array>
#include <optional>

namespace medusa::kinetic {

using Interval = CGAL::Interval_nt_advanced;
using IntervalPoly = Poly<Interval>;

// +1 / -1 when the enclosure x excludes zero on that side, 0 otherwise.
inline int certified_sign(const Interval& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }

// The Bernstein coefficients of f on [lo, hi], each multiplied by a positive binomial (so with the
// signs of the true coefficients), in beta[0..n]; returns n, the degree of f (-1 if f is empty).
// beta[0] encloses f(lo) and beta[n] encloses f(hi).
// Plain doubles with an a-priori error bound first; interval arithmetic when they leave a sign open.
int bernstein_coefficients(const IntervalPoly& f, double lo, double hi,
                           std::array<Interval, IntervalPoly::max_degree + 1>& beta);
// Its first stage alone: false when some sign stays open (beta is then unspecified); exposed so that
// tests check its error bound.
bool bernstein_coefficients_from_doubles(const IntervalPoly& f, double lo, double hi,
                                         std::array<Interval, IntervalPoly::max_degree + 1>& beta);

// +1 if f > 0 on [lo, hi], -1 if f < 0 on [lo, hi], 0 if the Bernstein enclosures do not decide.
// lo < hi are doubles (any double is an exact dyadic rational).
int bernstein_sign(const IntervalPoly& f, double lo, double hi = 1.0);

// As bernstein_sign on [lo, 1], subdividing up to `depth` times where the enclosures are too wide:
// +1 / -1 when every piece has that sign, 0 otherwise (docs/MATH.md §3.8, de Casteljau subdivision).
int bernstein_sign_subdivided(const IntervalPoly& f, double lo, int depth);

// An enclosure of f(x) at the double x, valid for every polynomial with coefficients in f's
// intervals. Plain doubles with an a-priori error bound first (a few times cheaper than interval
// Horner); when that enclosure holds zero, interval Horner, which is tighter and is [0, 0] exactly
// when every step was exact (a proof that f vanishes at x).
Interval value_at_point(const IntervalPoly& f, double x);
// Its first stage alone (nullopt when not finite); exposed so that tests check its error bound.
std::optional<Interval> value_at_point_from_doubles(const IntervalPoly& f, double x);

// +1 / -1 if f keeps that sign on the whole interval [lo, hi], 0 if undecided.
int interval_sign(const IntervalPoly& f, double lo, double hi);

// For f and u^shift g known to be the same polynomial up to a non-zero factor c: the sign of c, read
// off the first coefficient whose enclosures exclude zero in both; 0 if none does.
int proportionality_sign(const IntervalPoly& f, const IntervalPoly& g, int shift = 0);

} // namespace medusa::kinetic
