// Exact event times inside a slab: real algebraic numbers u in [0, 1], compared exactly
// (MATH.md 3.7), through CGAL's Algebraic_kernel_d_1 over Gmpz (Descartes isolation, MPFI).
// Heavy header: include it only in the few translation units that need exact times.
#pragma once

#include "medusa/kinetic/polynomial.h"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <gmpxx.h>

#include <vector>

namespace medusa::kinetic {

using AlgebraicKernel = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using AlgebraicReal = AlgebraicKernel::Algebraic_real_1;
using ExactPoly = AlgebraicKernel::Polynomial_1;
using Rational = CGAL::Gmpq;

ExactPoly to_exact_poly(const Poly<mpz_class>& f);

// A time inside a slab: the parameter u, rational (frames, audits) or algebraic (events).
class SlabTime {
public:
  SlabTime(); // u = 0
  explicit SlabTime(const Rational& u);
  explicit SlabTime(const AlgebraicReal& u);

  bool is_rational() const { return rational_; }
  const Rational& rational() const { return q_; }
  const AlgebraicReal& algebraic() const { return a_; }
  double approx() const;
  // An isolating interval [lo, hi] of u as doubles rounded outward (lo == hi for exact doubles).
  void enclosure(double& lo, double& hi) const;

  friend bool operator<(const SlabTime& x, const SlabTime& y) { return x.a_ < y.a_; }
  friend bool operator==(const SlabTime& x, const SlabTime& y) { return x.a_ == y.a_; }

private:
  bool rational_;
  Rational q_;
  AlgebraicReal a_;
};

// sign^+_u(f): the sign of f on (u, u + eps) (MATH.md 3.7); 0 iff f is identically zero.
int sign_plus(const ExactPoly& f, const SlabTime& u);

// The roots of f (not identically zero) in the open interval (u, 1) where f changes sign (odd
// multiplicity), in increasing order. Roots of even multiplicity are not events (MATH.md 3.9).
std::vector<AlgebraicReal> sign_changes_after(const ExactPoly& f, const SlabTime& u);

// A rational strictly between a < b.
Rational rational_between(const SlabTime& a, const SlabTime& b);

} // namespace medusa::kinetic

namespace medusa::kinetic {
// The sign of f at u itself (not one-sided).
int sign_at(const ExactPoly& f, const SlabTime& u);
} // namespace medusa::kinetic

namespace medusa::kinetic {

// All real roots of a polynomial with their multiplicities, in increasing order. Computed once per
// polynomial and slab and cached by the engine (MATH.md 3.8, caching).
struct RealRoots {
  std::vector<std::pair<AlgebraicReal, int>> roots;
};
RealRoots real_roots(const ExactPoly& f);

// sign^+_u(f) from the roots of f (f not identically zero); when `changes` is given it receives the
// roots of odd multiplicity in (u, 1), in increasing order.
int sign_plus_from_roots(const ExactPoly& f, const RealRoots& r, const SlabTime& u,
                         std::vector<AlgebraicReal>* changes);

} // namespace medusa::kinetic
