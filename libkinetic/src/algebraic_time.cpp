#include "algebraic_time.h"

#include "fixed_integer.h"
#include "medusa/core/error.h"
#include "root_isolation.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Polynomial_traits_d.h>

#include <algorithm>
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

// The sign of the first derivative of f (f itself is derivative 0) that does not vanish at u, and its
// order; 0 when f is identically zero.
int first_nonzero_derivative_sign(ExactPoly f, const SlabTime& u, int& order) {
  for (order = 0; !CGAL::is_zero(f); ++order, f.diff()) {
    const CGAL::Sign s =
        u.is_rational() ? f.sign_at(u.rational()) : kernel().sign_at_1_object()(f, u.algebraic());
    if (s != CGAL::ZERO)
      return s == CGAL::POSITIVE ? 1 : -1;
  }
  return 0;
}

// The sign of f at the rational g = n / d (d > 0), from f(g) d^deg = sum f_i n^i d^(deg - i) in
// integers: no rational arithmetic, hence no gcd per operation.
int sign_at_rational(const ExactPoly& f, const Rational& g) {
  const int degree = f.degree();
  mpz_class sum(f[degree].mpz()), d_power(1);
  for (int i = degree - 1; i >= 0; --i) {
    mpz_mul(d_power.get_mpz_t(), d_power.get_mpz_t(), g.denominator().mpz());
    mpz_mul(sum.get_mpz_t(), sum.get_mpz_t(), g.numerator().mpz());
    mpz_addmul(sum.get_mpz_t(), f[i].mpz(), d_power.get_mpz_t());
  }
  return sgn(sum);
}

} // namespace

Rational value_at(const Poly<mpz_class>& f, const Rational& q) {
  Rational v(0);
  for (int i = f.degree_bound(); i >= 0; --i)
    v = v * q + Rational(to_gmpz(f[i]));
  return v;
}

ExactPoly to_exact_poly(const Poly<mpz_class>& f) {
  std::vector<CGAL::Gmpz> coefficients;
  for (int i = 0; i <= f.degree_bound(); ++i)
    coefficients.push_back(to_gmpz(f[i]));
  if (coefficients.empty())
    coefficients.push_back(CGAL::Gmpz(0));
  return ExactPoly(coefficients.begin(), coefficients.end());
}

SlabTime::SlabTime() : SlabTime(Rational(0)) {}

SlabTime::SlabTime(const Rational& u) : rational_(true), q_(u) {
  std::pair<double, double> i = CGAL::to_interval(*q_);
  lo_ = i.first;
  hi_ = i.second;
}

SlabTime::SlabTime(const AlgebraicReal& u) : rational_(false), a_(std::make_shared<AlgebraicReal>(u)) {
  // Refine the isolating interval to about 2^-60 once, so that the certified interval filters at
  // this time see a point-like enclosure (the refinement is kept by the shared representation).
  kernel().approximate_absolute_1_object()(*a_, 60);
  if (a_->low() == a_->high()) {
    rational_ = true;
    q_ = a_->low();
  }
  lo_ = CGAL::to_interval(a_->low()).first;
  hi_ = CGAL::to_interval(a_->high()).second;
}

SlabTime::SlabTime(std::shared_ptr<IsolatedRoot> root) : rational_(false), root_(std::move(root)) {}

bool SlabTime::is_rational() const {
  if (root_)
    return root_->lo == root_->hi;
  return rational_;
}

const Rational& SlabTime::rational() const {
  if (root_ && root_->lo == root_->hi && !rational_) {
    // Found exactly in doubles (refine_root hit the root): a dyadic rational.
    q_ = Rational(root_->lo);
    rational_ = true;
  }
  return *q_;
}

const AlgebraicReal& SlabTime::algebraic() const {
  if (a_)
    return *a_;
  if (root_ && root_->algebraic) {
    a_ = std::make_shared<AlgebraicReal>(*root_->algebraic);
    return *a_;
  }
  if (is_rational()) {
    a_ = std::make_shared<AlgebraicReal>(kernel().construct_algebraic_real_1_object()(rational()));
    return *a_;
  }
  // The exact root: the square-free part of the polynomial keeps the simple root, the only one in
  // the open interval (lo, hi), where the polynomial does not vanish at either end.
  using Traits = CGAL::Polynomial_traits_d<ExactPoly>;
  ExactPoly f = Traits::Make_square_free()(root_->exact_polynomial());
  root_->algebraic = AlgebraicReal(f, Rational(root_->lo), Rational(root_->hi));
  a_ = std::make_shared<AlgebraicReal>(*root_->algebraic);
  return *a_;
}

double SlabTime::approx() const {
  if (root_)
    return 0.5 * (root_->lo + root_->hi);
  if (rational_)
    return CGAL::to_double(*q_);
  return CGAL::to_double(kernel().approximate_relative_1_object()(*a_, 53).first);
}

namespace {
thread_local TimeComparisonCounts comparison_counts;
} // namespace

int SlabTime::side_of(const Rational& g) const {
  const std::pair<double, double> around = CGAL::to_interval(g);
  if (root_) {
    if (root_->lo == root_->hi) {
      const Rational u(root_->lo);
      return u < g ? -1 : (g < u ? 1 : 0);
    }
    if (around.second <= root_->lo)
      return 1;
    if (around.first >= root_->hi)
      return -1;
    if (root_->lo < around.first && around.second < root_->hi) {
      CGAL::Protect_FPU_rounding<true> guard;
      const int s = interval_sign(root_->bisection_polynomial(), around.first, around.second);
      if (s != 0)
        return s == root_->sign_lo ? 1 : -1; // one simple root in (lo, hi), where the sign changes
    }
  } else if (rational_) {
    return *q_ < g ? -1 : (g < *q_ ? 1 : 0);
  }
  ++comparison_counts.reported_exactly;
  if (root_) {
    // Exactly, without the algebraic real: the exact polynomial's only root in (lo, hi) is simple
    // and is this time (SlabTime::algebraic), so the sign there at g, against its sign just left of
    // the root (at lo, or opposite at hi, where it does not vanish; at u = 0 the division by u^m may
    // change the sign), says on which side g lies.
    const Rational lo(root_->lo), hi(root_->hi);
    if (g <= lo)
      return 1;
    if (hi <= g)
      return -1;
    const ExactPoly& p = root_->exact_polynomial();
    const int at_g = sign_at_rational(p, g);
    if (at_g == 0)
      return 0;
    if (root_->exact_sign_left == 0)
      root_->exact_sign_left =
          static_cast<signed char>(root_->lo > 0.0 ? sign_at_rational(p, lo) : -sign_at_rational(p, hi));
    return at_g == root_->exact_sign_left ? 1 : -1;
  }
  const AlgebraicReal& a = algebraic();
  const AlgebraicReal b = kernel().construct_algebraic_real_1_object()(g);
  return a < b ? -1 : (b < a ? 1 : 0);
}

namespace {

// floor(u span 2^bits) for a double u in [0, 1] and span >= 1, exactly: u = m 2^(e - 53) with an
// integer m < 2^53, so the value is floor(m span / 2^(53 - e - bits)), and m span < 2^116.
template <unsigned bits> Int128 scaled_floor(double u, std::int64_t span) {
  if (!(u > 0.0))
    return 0;
  int e = 0;
  const double f = std::frexp(u, &e);
  const Int128 product = static_cast<Int128>(static_cast<std::int64_t>(std::ldexp(f, 53))) * span;
  const int shift = 53 - e - static_cast<int>(bits);
  static_assert(bits < 53, "u <= 1 then needs a right shift");
  return shift >= 120 ? 0 : product >> shift;
}

} // namespace

double SlabTime::reported_time(std::int64_t t0, std::int64_t t1) const {
  if (t1 == t0)
    return static_cast<double>(t0);
  if (t1 < t0)
    throw InternalError("reported time: a slab ends before it starts");
  // With c = floor((t - t0) 2^33), found by bisection over the cells [k 2^-33, (k + 1) 2^-33) past t0
  // that the enclosure [lo, hi] of u spans (usually one), the time is t0 + floor((c + 1) / 2) 2^-32:
  // t rounded half up to the 2^-32 grid, which t0 is on. The cells are counted in 128-bit integers,
  // exactly; a rational is made only for a grid point that the enclosure does not place.
  constexpr unsigned bits = 33;
  const std::int64_t span = t1 - t0;
  auto point = [&](Int128 k) { // u at t = t0 + k 2^-33
    mpq_class u(to_mpz(k), mpz_class(span) << bits);
    u.canonicalize();
    return Rational(u.get_mpq_t());
  };
  double lo = 0.0, hi = 0.0;
  enclosure(lo, hi);
  Int128 c = scaled_floor<bits>(std::max(lo, 0.0), span), last = scaled_floor<bits>(std::min(hi, 1.0), span);
  while (c < last) {
    const Int128 k = (c + last + 1) / 2; // both non-negative: the floor
    if (side_of(point(k)) >= 0)
      c = k;
    else
      last = k - 1;
  }
  const Int128 grid = static_cast<Int128>(t0) * (Int128{1} << (bits - 1)) + (c + 1) / 2;
  constexpr Int128 exact_below = Int128{1} << 53;
  // Beyond 2^53 the conversion truncates, as GMP's does (the time is then past 2^21 MCS).
  const double g =
      grid > -exact_below && grid < exact_below ? static_cast<double>(grid) : to_mpz(grid).get_d();
  return std::ldexp(g, -static_cast<int>(bits - 1));
}

void SlabTime::enclosure(double& lo, double& hi) const {
  if (root_) {
    lo = root_->lo;
    hi = root_->hi;
    return;
  }
  lo = lo_;
  hi = hi_;
}

bool SlabTime::refine_once() const {
  if (!root_ || root_->lo == root_->hi)
    return false;
  return refine_root(root_->bisection_polynomial(), root_->lo, root_->hi, root_->sign_lo) !=
         Refinement::stuck;
}

void SlabTime::sharpen(const IntervalPoly& tighter) const {
  if (root_ && root_->wide) {
    root_->enclosure = tighter;
    root_->wide = false;
  }
}

TimeComparisonCounts time_comparison_counts() { return comparison_counts; }

bool SlabTime::sharpen_from_exact() const {
  if (!root_ || root_->sharp || root_->lo == root_->hi)
    return false;
  // exact() is the polynomial up to a non-zero factor, with u^m divided out: the same roots in
  // (0, 1]. Its sign at lo (or, opposite, at hi) orients it like the enclosure: the polynomial does
  // not vanish at either end, so its rounding usually certifies one of them. At u = 0 the division by
  // u^m may change the sign, so lo = 0 is not used.
  const ExactPoly& p = root_->exact_polynomial();
  IntervalPoly t = IntervalPoly::zero_of_degree(p.degree());
  for (int i = 0; i <= p.degree(); ++i) {
    const std::pair<double, double> c = CGAL::to_interval(p[i]);
    t[i] = Interval(c.first, c.second);
  }
  int s = root_->lo > 0.0 ? certified_sign(value_at_point(t, root_->lo)) : 0;
  if (s == 0)
    s = -certified_sign(value_at_point(t, root_->hi));
  if (s == 0)
    return false;
  root_->sharp = std::make_unique<const IntervalPoly>(s == root_->sign_lo ? t : -t);
  ++comparison_counts.sharpened;
  return true;
}

void SlabTime::tighten() const {
  if (!root_ || root_->lo == root_->hi)
    return;
  CGAL::Protect_FPU_rounding<true> guard;
  narrow_root(root_->bisection_polynomial(), root_->lo, root_->hi, root_->sign_lo, 0.0);
}

namespace {

// Whether f = c g for a non-zero rational c: the same roots.
bool proportional(const ExactPoly& f, const ExactPoly& g) {
  if (f.degree() != g.degree())
    return false;
  const CGAL::Gmpz &a = f.lcoeff(), &b = g.lcoeff();
  for (int i = 0; i <= f.degree(); ++i)
    if (f[i] * b != g[i] * a)
      return false;
  return true;
}

// Two isolated roots whose exact polynomials are proportional, compared as roots of one polynomial
// (the reasoning of compare below, on the exact polynomial evaluated exactly at the intersection's
// ends): -1, 0 or 1, or 2 when the polynomials differ or an end is a root. A certificate on translated
// copies of its cells has the same exact polynomial, up to sign, as the original's (docs/MATH.md
// §8.6): its copies' event times are equal, and told so here without algebraic reals.
int compare_as_one_polynomial(const IsolatedRoot& x, const IsolatedRoot& y) {
  const ExactPoly& f = x.exact_polynomial();
  if (!proportional(f, y.exact_polynomial()))
    return 2;
  const double xl = x.lo, xh = x.hi, yl = y.lo, yh = y.hi;
  if ((yl <= xl && xh <= yh) || (xl <= yl && yh <= xh))
    return 0;
  const CGAL::Sign s_lo = f.sign_at(Rational(std::max(xl, yl))), s_hi = f.sign_at(Rational(std::min(xh, yh)));
  if (s_lo == CGAL::ZERO || s_hi == CGAL::ZERO)
    return 2;
  return s_lo != s_hi ? 0 : (xl < yl ? -1 : 1);
}

} // namespace

int compare(const SlabTime& x, const SlabTime& y) {
  if (x.root_ && x.root_ == y.root_)
    return 0;
  if (!x.root_ && !y.root_ && x.rational_ && y.rational_)
    return *x.q_ < *y.q_ ? -1 : (*y.q_ < *x.q_ ? 1 : 0);
  // Two roots of one polynomial (a certificate rebuilt on the same points, e.g. a facet whose
  // neighbourhood changed): each open interval holds exactly one root of it, so nested intervals mean
  // the same root. Overlapping ones (narrowed at different points, narrow_root) share a root iff
  // the polynomial changes sign across their intersection, which lies in both and so holds at most
  // one root; otherwise each root lies in its own interval outside the intersection.
  // (Closed containment is enough: the polynomial does not vanish at the ends of an open isolating
  // interval, and an interval shrunk to a point is the root itself.)
  double xl, xh, yl, yh;
  // -1 or 1 when the current enclosures separate x and y, 0 while they overlap.
  auto separated = [&] {
    x.enclosure(xl, xh);
    y.enclosure(yl, yh);
    return xh < yl ? -1 : (yh < xl ? 1 : 0);
  };
  if (const int order = separated(); order != 0)
    return order;
  // Overlapping enclosures (rare in a queue of isolated roots): decide whether both are roots of one
  // polynomial, then narrow the wider isolated root, then the other one.
  const bool same_polynomial =
      x.root_ && y.root_ && x.root_->slab == y.root_->slab &&
      ((x.root_->key[0] >= 0 && x.root_->key == y.root_->key) || x.root_->same_polynomial_as(*y.root_));
  {
    CGAL::Protect_FPU_rounding<true> guard;
    for (;;) {
      if (same_polynomial) {
        if ((yl <= xl && xh <= yh) || (xl <= yl && yh <= xh))
          return 0;
        const double lo = std::max(xl, yl), hi = std::min(xh, yh);
        for (const IsolatedRoot* r : {x.root_.get(), y.root_.get()}) {
          const int s_lo = interval_sign(r->enclosure, lo, lo), s_hi = interval_sign(r->enclosure, hi, hi);
          if (s_lo != 0 && s_hi != 0)
            return s_lo != s_hi ? 0 : (xl < yl ? -1 : 1);
        }
      }
      const bool x_first = (xh - xl) >= (yh - yl);
      const SlabTime& a = x_first ? x : y;
      const SlabTime& b = x_first ? y : x;
      // Stuck in doubles: go on with the exact polynomials rounded to intervals before turning to
      // algebraic reals.
      if (!a.refine_once() && !b.refine_once() && !a.sharpen_from_exact() && !b.sharpen_from_exact())
        break;
      if (const int order = separated(); order != 0)
        return order;
    }
  }
  if (x.root_ && y.root_ && x.root_->sharp && y.root_->sharp) {
    if (const int order = compare_as_one_polynomial(*x.root_, *y.root_); order != 2) {
      ++comparison_counts.proportional;
      return order;
    }
  }
  ++comparison_counts.algebraic;
  const AlgebraicReal& a = x.algebraic();
  const AlgebraicReal& b = y.algebraic();
  return a < b ? -1 : (b < a ? 1 : 0);
}

int sign_plus(const ExactPoly& f, const SlabTime& u) {
  if (CGAL::is_zero(f))
    return 0;
  if (u.is_rational())
    return sign_plus_rational(f, u.rational());
  int order;
  return first_nonzero_derivative_sign(f, u, order);
}

// Taylor at u: f(u - e) has the sign of (-1)^k f^(k)(u) for the first k with f^(k)(u) != 0.
int sign_minus(const ExactPoly& f, const SlabTime& u) {
  int order;
  const int s = first_nonzero_derivative_sign(f, u, order);
  return order % 2 == 0 ? s : -s;
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

// With lo <= a <= hi < b and hi - lo <= (b - hi) / 8, r = hi + (b - hi) / 8 lies in (a, b) and
// r - a <= (hi - lo) + (b - hi) / 8 <= (b - hi) / 4 <= (b - a) / 4. Refining a's isolating interval
// makes hi tend to a < b, so the condition is met after finitely many refinements.
Rational rational_closer_after(const SlabTime& a, const Rational& b) {
  if (!(a < SlabTime(b)))
    throw InternalError("rational_closer_after needs a < b");
  if (a.is_rational())
    return a.rational() + (b - a.rational()) / 4;
  for (int precision = 16;; precision += 16) {
    const auto [lo, hi] = kernel().approximate_absolute_1_object()(a.algebraic(), precision);
    if (hi < b && (hi - lo) * 8 <= b - hi)
      return hi + (b - hi) / 8;
  }
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
