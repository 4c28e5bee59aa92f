// Certified root isolation in double interval arithmetic (docs/MATH.md §3.7, §3.8): the fast path that
// finds the next failure time of a certificate without exact arithmetic. A polynomial is given by
// an enclosure of its coefficients; every answer holds for every polynomial inside the enclosure,
// hence for the exact one. When doubles cannot decide, the answer says so and the caller falls back
// to exact isolation. Callers must hold a CGAL::Protect_FPU_rounding guard.
#pragma once

#include "interval_filter.h"

namespace medusa::kinetic {

// The first sign change of f on (start, 1).
struct FirstSignChange {
  enum class Status {
    none,     // f keeps the sign `sign` on [start, 1]
    root,     // f has the sign `sign` on [start, lo], exactly one root in (lo, hi), a simple one
    undecided // the enclosures could not decide within the subdivision depth
  };
  Status status = Status::undecided;
  int sign = 0;
  double lo = 0.0, hi = 0.0;
};

// Bernstein-Descartes isolation on dyadic pieces of [start, 1], left to right: a piece whose
// Bernstein coefficients have certified signs with no variation has no root; with exactly one
// variation it holds exactly one root, and that root is simple (Descartes' rule in the Bernstein
// basis). Pieces are halved up to `max_depth` times. f(start) must be certified non-zero, otherwise
// the answer is `undecided`.
FirstSignChange first_sign_change(const IntervalPoly& f, double start, int max_depth);

// One bisection step of an isolating interval (lo, hi) of a simple root of f, where f has the sign
// `sign_lo` at lo; when f at the midpoint has no certified sign, cuts at the quarter points instead.
// `stuck` when none of the three has a certified sign (the interval is then within a factor of four
// of as tight as doubles allow); `exact` when f vanishes exactly at a cut (lo = hi = the root).
enum class Refinement { narrowed, exact, stuck };

Refinement refine_root(const IntervalPoly& f, double& lo, double& hi, int sign_lo);

// Narrows the isolating interval (lo, hi) as refine_root does, until it is no wider than `width`
// (0: as tight as doubles allow). Safeguarded Newton steps on the midpoint polynomial propose a point and a
// bracket around the root, and certified signs there decide them, so each round gains many bits
// where bisection gains one; bisection finishes what they leave. `exact` when f vanishes exactly
// at a proposed point (lo = hi = the root). The result is an isolating interval
// whichever way the proposals go (every move is decided by a certified sign).
Refinement narrow_root(const IntervalPoly& f, double& lo, double& hi, int sign_lo, double width);

} // namespace medusa::kinetic
