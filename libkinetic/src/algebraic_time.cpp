#include "medusa/kinetic/algebraic_time.h"

#include <CGAL/Interval_nt.h>

#include <cmath>

namespace medusa::kinetic {

namespace {

const AlgebraicKernel& kernel() {
  static const AlgebraicKernel ak;
  return ak;
}

CGAL::Gmpz to_gmpz(const mpz_class& x) { return CGAL::Gmpz(x.get_mpz_t()); }

// Sign of the first non-zero derivative of f at the rational u (f not identically zero).
int sign_plus_rational(ExactPoly f, const Rational& u) {
  while (!CGAL::is_zero(f)) {
    CGAL::Sign s = f.sign_at(u);
    if (s != CGAL::ZERO)
      return s == CGAL::POSITIVE ? 1 : -1;
    f.diff();
  }
  return 0;
}

} // namespace

ExactPoly to_exact_poly(const Poly<mpz_class>& f) {
  std::vector<CGAL::Gmpz> coefficients;
  for (int i = 0; i <= f.degree_bound(); ++i)
    coefficients.push_back(to_gmpz(f[i]));
  if (coefficients.empty())
    coefficients.push_back(CGAL::Gmpz(0));
  return ExactPoly(coefficients.begin(), coefficients.end());
}

SlabTime::SlabTime()
    : rational_(true), q_(0), a_(kernel().construct_algebraic_real_1_object()(CGAL::Gmpz(0))) {}

SlabTime::SlabTime(const Rational& u)
    : rational_(true), q_(u), a_(kernel().construct_algebraic_real_1_object()(u)) {}

SlabTime::SlabTime(const AlgebraicReal& u) : rational_(false), q_(0), a_(u) {
  // Refine the isolating interval to about 2^-60 once, so that the certified interval filters at
  // this time see a point-like enclosure (the refinement is kept by the shared representation).
  kernel().approximate_absolute_1_object()(a_, 60);
  if (a_.low() == a_.high()) {
    rational_ = true;
    q_ = a_.low();
  }
}

double SlabTime::approx() const {
  if (rational_)
    return CGAL::to_double(q_);
  return CGAL::to_double(kernel().approximate_relative_1_object()(a_, 53).first);
}

void SlabTime::enclosure(double& lo, double& hi) const {
  if (rational_) {
    std::pair<double, double> i = CGAL::to_interval(q_);
    lo = i.first;
    hi = i.second;
    return;
  }
  lo = CGAL::to_interval(a_.low()).first;
  hi = CGAL::to_interval(a_.high()).second;
}

int sign_plus(const ExactPoly& f, const SlabTime& u) {
  if (CGAL::is_zero(f))
    return 0;
  if (u.is_rational())
    return sign_plus_rational(f, u.rational());
  // Algebraic u: the sign of the first derivative that does not vanish at u.
  ExactPoly g = f;
  while (!CGAL::is_zero(g)) {
    CGAL::Sign s = kernel().sign_at_1_object()(g, u.algebraic());
    if (s != CGAL::ZERO)
      return s == CGAL::POSITIVE ? 1 : -1;
    g.diff();
  }
  return 0;
}

std::vector<AlgebraicReal> sign_changes_after(const ExactPoly& f, const SlabTime& u) {
  std::vector<std::pair<AlgebraicReal, AlgebraicKernel::Multiplicity_type>> roots;
  kernel().solve_1_object()(f, std::back_inserter(roots));
  const AlgebraicReal one = kernel().construct_algebraic_real_1_object()(CGAL::Gmpz(1));
  std::vector<AlgebraicReal> result;
  for (const auto& [root, multiplicity] : roots) {
    if (multiplicity % 2 == 0 || !(u.algebraic() < root) || !(root < one))
      continue;
    result.push_back(root);
  }
  return result;
}

Rational rational_between(const SlabTime& a, const SlabTime& b) {
  return kernel().bound_between_1_object()(a.algebraic(), b.algebraic());
}

} // namespace medusa::kinetic

namespace medusa::kinetic {
int sign_at(const ExactPoly& f, const SlabTime& u) {
  if (CGAL::is_zero(f))
    return 0;
  CGAL::Sign s =
      u.is_rational() ? f.sign_at(u.rational()) : AlgebraicKernel().sign_at_1_object()(f, u.algebraic());
  return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0);
}
} // namespace medusa::kinetic

namespace medusa::kinetic {

RealRoots real_roots(const ExactPoly& f) {
  RealRoots r;
  AlgebraicKernel().solve_1_object()(f, std::back_inserter(r.roots));
  return r;
}

int sign_plus_from_roots(const ExactPoly& f, const RealRoots& r, const SlabTime& u,
                         std::vector<AlgebraicReal>* changes) {
  const AlgebraicKernel ak;
  std::size_t j = 0;
  while (j < r.roots.size() && !(u.algebraic() < r.roots[j].first))
    ++j;
  // A rational q in (u, next root): f has no root there, so sign f(q) = sign^+_u f.
  Rational q = j < r.roots.size() ? ak.bound_between_1_object()(u.algebraic(), r.roots[j].first)
                                  : (u.is_rational() ? u.rational() : u.algebraic().high()) + Rational(1);
  if (changes) {
    const AlgebraicReal one = ak.construct_algebraic_real_1_object()(CGAL::Gmpz(1));
    for (std::size_t i = j; i < r.roots.size() && r.roots[i].first < one; ++i)
      if (r.roots[i].second % 2 == 1)
        changes->push_back(r.roots[i].first);
  }
  CGAL::Sign s = f.sign_at(q);
  return s == CGAL::POSITIVE ? 1 : (s == CGAL::NEGATIVE ? -1 : 0);
}

} // namespace medusa::kinetic
