// Exact event times inside a slab: real algebraic numbers u in [0, 1], compared exactly
// (docs/MATH.md §3.7), through CGAL's Algebraic_kernel_d_1 over Gmpz (Descartes isolation, MPFI).
// Heavy header: include it only in the few translation units that need exact times.
#pragma once

#include "interval_filter.h"
#include "polynomial.h"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace medusa::kinetic {

using AlgebraicKernel = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using AlgebraicReal = AlgebraicKernel::Algebraic_real_1;
using ExactPoly = AlgebraicKernel::Polynomial_1;
using Rational = CGAL::Gmpq;

ExactPoly to_exact_poly(const Poly<mpz_class>& f);

// f(q), exactly (Horner in rationals): the audit's and the repairs' checks at a rational time.
Rational value_at(const Poly<mpz_class>& f, const Rational& q);

// A root of a certificate polynomial isolated in doubles (root_isolation.h): exactly one root of the
// polynomial lies in the open interval (lo, hi), and it is simple. The exact polynomial is computed
// only when two times cannot be told apart in doubles (docs/MATH.md §3.7: isolating intervals first,
// refinement when they overlap, exact comparison last). Shared by every copy of the time, so a
// refinement made once serves every later comparison.
struct IsolatedRoot {
  virtual ~IsolatedRoot() = default;
  // The exact polynomial (any non-zero multiple of it): IsolatedRootOf below holds what computes
  // it, in the same allocation (every scheduled event has one of these).
  virtual ExactPoly exact() const = 0;
  // exact(), computed once: a root that needs it for its sharp enclosure often needs it again for
  // its algebraic real.
  const ExactPoly& exact_polynomial() const {
    if (!exact_memo)
      exact_memo = std::make_unique<const ExactPoly>(exact());
    return *exact_memo;
  }

  IntervalPoly enclosure; // encloses the coefficients of the polynomial divided by u^shift
  int shift = 0;          // (a root of multiplicity shift at the slab start divided out)
  bool wide = false;      // enclosure from plain doubles: SlabTime::sharpen replaces it before reporting
  // The sign of the exact polynomial just left of the root (0: not yet known), which a time's
  // rounding compares with its sign at each grid point it tries (SlabTime::side_of).
  mutable signed char exact_sign_left = 0;
  double lo = 0.0, hi = 0.0; // lo < root < hi, or lo == hi == root once found exactly
  int sign_lo = 0;           // sign of the polynomial at lo
  // The right end of the piece that isolated the root: the polynomial has no root in (root,
  // clear_hi] and its sign there, -sign_lo, was certified at clear_hi. Certificates built on the
  // same points at this root (a flip's new interior facets) start their search for the next root
  // there, where the enclosures still decide (docs/MATH.md §3.8, caching).
  double clear_hi = 0.0;
  std::array<std::int32_t, 6> key{{-1, -1, -1, -1, -1, -1}}; // which polynomial (-1: unknown) ...
  std::size_t slab = 0;                   // ... in which slab: equal (key, slab), same polynomial
  std::optional<AlgebraicReal> algebraic; // the exact root, built on first need
  // The exact polynomial rounded to intervals and oriented like `enclosure` (sign_lo at lo), built
  // when bisection on the enclosure is stuck (SlabTime::sharpen_from_exact). Kept apart from
  // `enclosure`, whose coefficients other code reads against the certificate's (shift, sign).
  // Held by pointer: every scheduled event has an IsolatedRoot, few ever need this.
  std::unique_ptr<const IntervalPoly> sharp;
  mutable std::unique_ptr<const ExactPoly> exact_memo; // exact_polynomial()
  // The polynomial that bisection and narrowing evaluate: the sharp one once it exists.
  const IntervalPoly& bisection_polynomial() const { return sharp ? *sharp : enclosure; }
  // Whether other's polynomial is this one's up to a non-zero factor, known without computing either
  // (the same certificate on translated points, docs/MATH.md §3.7); false when not known.
  virtual bool same_polynomial_as(const IsolatedRoot& other) const = 0;
};

namespace internal {
template <class S, class = void> struct knows_translates : std::false_type {};
template <class S>
struct knows_translates<
    S, std::void_t<decltype(std::declval<const S&>().translate_of(std::declval<const S&>()))>>
    : std::true_type {};
} // namespace internal

// An isolated root whose exact polynomial is source() (a callable returning ExactPoly). A source with
// `bool translate_of(const Source&) const` says when two sources are one polynomial on translated
// points.
template <class Source> struct IsolatedRootOf final : IsolatedRoot {
  explicit IsolatedRootOf(Source s) : source(std::move(s)) {}
  ExactPoly exact() const override { return source(); }
  bool same_polynomial_as(const IsolatedRoot& other) const override {
    if constexpr (internal::knows_translates<Source>::value) {
      const auto* o = dynamic_cast<const IsolatedRootOf*>(&other);
      return o != nullptr && source.translate_of(o->source);
    } else {
      return false;
    }
  }
  Source source;
};

template <class Source> std::shared_ptr<IsolatedRootOf<Source>> make_isolated_root(Source source) {
  return std::make_shared<IsolatedRootOf<Source>>(std::move(source));
}

// A time inside a slab: the parameter u, rational (frames, audits) or algebraic (events).
class SlabTime {
public:
  SlabTime(); // u = 0
  explicit SlabTime(const Rational& u);
  explicit SlabTime(const AlgebraicReal& u);
  explicit SlabTime(std::shared_ptr<IsolatedRoot> root);

  bool is_rational() const;
  const Rational& rational() const; // only when is_rational()
  const AlgebraicReal& algebraic() const;
  // The isolated root behind an algebraic time found in doubles, or null.
  const IsolatedRoot* isolated() const { return root_.get(); }
  // Replaces a wide enclosure of the isolated root's polynomial by a tighter one of the same
  // polynomial: the isolating interval stays valid, and refinement then reaches the precision the
  // reported double value needs.
  void sharpen(const IntervalPoly& tighter) const;
  double approx() const;
  // The time reported for u in the slab [t0, t1] (events' times in the store): t = t0 + u (t1 - t0)
  // rounded to the nearest multiple of 2^-32 MCS, exactly (docs/MATH.md §3.12). A function of t alone,
  // not of how far u's interval was refined, so equal times are reported equal by any engine and in
  // any copy of a periodic run, reported times never decrease as t grows, and times on the grid
  // (whole MCS among them) are reported exactly.
  double reported_time(std::int64_t t0, std::int64_t t1) const;
  // An isolating interval [lo, hi] of u as doubles rounded outward (lo == hi for exact doubles).
  void enclosure(double& lo, double& hi) const;
  // Narrows the enclosure of an isolated root as far as doubles allow.
  void tighten() const;

  // -1, 0, +1: exact comparison, in doubles whenever the enclosures separate.
  friend int compare(const SlabTime& x, const SlabTime& y);
  friend bool operator<(const SlabTime& x, const SlabTime& y) { return compare(x, y) < 0; }
  friend bool operator==(const SlabTime& x, const SlabTime& y) { return compare(x, y) == 0; }

private:
  // One bisection step of an isolated root; false when doubles cannot narrow it further. The caller
  // holds a CGAL::Protect_FPU_rounding guard (once for a whole refinement loop).
  bool refine_once() const;
  // Gives an isolated root the exact polynomial rounded to intervals (IsolatedRoot::sharp), so that
  // bisection can go on where its enclosure (from plain doubles, or from interval arithmetic on the
  // points) left a sign open; false for a rational time, a root found exactly, a root that has it
  // already, or when it cannot be oriented.
  // About 60 us for the exact polynomial (kept for the algebraic real, should one still be needed)
  // against about 110 us for the comparison of two algebraic reals it usually saves.
  bool sharpen_from_exact() const;
  // sign(u - g) for a rational g, exactly; the isolating polynomial decides when it can.
  int side_of(const Rational& g) const;

  mutable bool rational_;             // set lazily when an isolated root turns out to be a dyadic rational
  mutable std::optional<Rational> q_; // set iff rational_ (no allocation for isolated roots)
  std::shared_ptr<IsolatedRoot> root_;
  mutable std::shared_ptr<AlgebraicReal> a_; // built on first need
  double lo_ = 0.0, hi_ = 0.0;               // enclosure of rational or CGAL-built times
};

// Event-time comparisons that the isolating intervals alone did not decide (docs/MATH.md §3.7), counted
// per thread since it started; KineticStatistics reports the difference over a run.
struct TimeComparisonCounts {
  std::uint64_t sharpened = 0;        // isolated roots given their exact polynomial rounded to intervals
  std::uint64_t algebraic = 0;        // comparisons decided on CGAL's algebraic reals
  std::uint64_t proportional = 0;     // decided on one exact polynomial shared up to a factor (§3.7)
  std::uint64_t reported_exactly = 0; // grid points of a reported time decided exactly (§3.12)
};
TimeComparisonCounts time_comparison_counts();

// sign^+_u(f): the sign of f on (u, u + eps) (docs/MATH.md §3.7); 0 iff f is identically zero.
int sign_plus(const ExactPoly& f, const SlabTime& u);

// sign^-_u(f): the sign of f on (u - eps, u); 0 iff f is identically zero. With sign_plus it tells a
// root at u where f changes sign (odd multiplicity) from one where it only touches zero.
int sign_minus(const ExactPoly& f, const SlabTime& u);

// The roots of f (not identically zero) in the open interval (u, 1) where f changes sign (odd
// multiplicity), in increasing order. Roots of even multiplicity are not events (docs/MATH.md §3.9).
std::vector<AlgebraicReal> sign_changes_after(const ExactPoly& f, const SlabTime& u);

// A rational strictly between a < b.
Rational rational_between(const SlabTime& a, const SlabTime& b);

// A rational r with a < r < b and r - a <= (b - a) / 4 (requires a < b): repeated, it closes in on a
// at a proven rate. rational_between promises only some rational in between (CGAL's bound_between_1
// returns a short dyadic between the two refined isolating intervals), so a loop that retries with it
// has no bound on its number of steps.
Rational rational_closer_after(const SlabTime& a, const Rational& b);

} // namespace medusa::kinetic

namespace medusa::kinetic {
// The sign of f at u itself (not one-sided).
int sign_at(const ExactPoly& f, const SlabTime& u);
} // namespace medusa::kinetic

namespace medusa::kinetic {

// All real roots of a polynomial with their multiplicities, in increasing order. Computed once per
// polynomial and slab and cached by the engine (docs/MATH.md §3.8, caching).
struct RealRoots {
  std::vector<std::pair<AlgebraicReal, int>> roots;
};
RealRoots real_roots(const ExactPoly& f);

// sign^+_u(f) from the roots of f (f not identically zero); when `changes` is given it receives the
// roots of odd multiplicity in (u, 1), in increasing order.
int sign_plus_from_roots(const ExactPoly& f, const RealRoots& r, const SlabTime& u,
                         std::vector<AlgebraicReal>* changes);

} // namespace medusa::kinetic
