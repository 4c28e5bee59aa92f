// The tests that decide whether a static triangulation built at u + delta is Del(u+) (docs/MATH.md §5.5,
// method A): no certificate of docs/MATH.md §3.1 that it rests on has a root in (u, u + delta], and the
// points are not flat at u + delta alone.
#include "static_delaunay.h"

#include "algebraic_time.h"
#include "certificate_polynomials.h"
#include "start_determinants.h"

#include <CGAL/FPU.h>
#include <CGAL/Gmpz.h>

#include <utility>

namespace medusa::kinetic::detail {

namespace {

Interval enclosure(const mpz_class& x) { return Interval(CGAL::to_interval(CGAL::Gmpz(x.get_mpz_t()))); }

// Whether the polynomial that build(NT tag) gives has no root in (u, u + delta] (identically zero
// counts as none). Cheapest first: the Bernstein filter on [u, u + delta], which proves f has no
// root there; at u = 0 with f(0) = 0 (lattice starts, told by the static determinant
// `vanishes_at_start`), the same on f / u from its enclosure; then on f / u^m from its exact
// coefficients; last, f's real roots, compared exactly with u and u + delta.
template <class Build, class AtStart>
bool keeps_sign(Build&& build, AtStart&& vanishes_at_start, const Rational& u, const Rational& delta) {
  const std::pair<double, double> ue = CGAL::to_interval(u), de = CGAL::to_interval(delta);
  {
    CGAL::Protect_FPU_rounding<true> guard; // rounds upwards: hi encloses u + delta
    const double hi = ue.second + de.second;
    const IntervalPoly f = build(Interval());
    if (ue.first < hi && bernstein_sign(f, ue.first, hi) != 0)
      return true;
    if (u == 0 && de.first > 0 && f.degree_bound() >= 1 && vanishes_at_start()) {
      // f = u h exactly, and h's coefficients are f's from the first on.
      if (bernstein_sign(f.shifted_down(1), 0.0, de.second) != 0)
        return true;
    }
  }
  const Poly<mpz_class> exact = build(mpz_class());
  const int degree = exact.degree_bound();
  int m = 0;
  while (m <= degree && exact[m] == 0)
    ++m;
  if (m > degree)
    return true;
  if (u == 0 && m > 0 && de.first > 0) {
    CGAL::Protect_FPU_rounding<true> guard;
    IntervalPoly g = IntervalPoly::zero_of_degree(degree - m);
    for (int i = m; i <= degree; ++i)
      g[i - m] = enclosure(exact[i]);
    if (bernstein_sign(g, 0.0, de.second) != 0)
      return true;
  }
  const SlabTime from(u), to(u + delta);
  for (const auto& root : real_roots(to_exact_poly(exact)).roots) {
    const SlabTime r(root.first);
    if (from < r && !(to < r))
      return false;
  }
  return true;
}

} // namespace

bool orientation_keeps_sign(const std::vector<const MovingPoint*>& p, const CGAL::Gmpq& u,
                            const CGAL::Gmpq& delta) {
  return keeps_sign(
      [&](auto nt) {
        using NT = decltype(nt);
        return p.size() == 3 ? certificate::orientation_2<NT>(*p[0], *p[1], *p[2])
                             : certificate::orientation<NT>(*p[0], *p[1], *p[2], *p[3]);
      },
      [&] { return orientation_vanishes_at_start(p.data(), p.size()); }, u, delta);
}

bool in_sphere_keeps_sign(const std::vector<const MovingPoint*>& p, const MovingPoint& y, const CGAL::Gmpq& u,
                          const CGAL::Gmpq& delta) {
  return keeps_sign(
      [&](auto nt) {
        using NT = decltype(nt);
        return p.size() == 3 ? certificate::in_circle<NT>(*p[0], *p[1], *p[2], y)
                             : certificate::in_sphere<NT>(*p[0], *p[1], *p[2], *p[3], y);
      },
      [&] {
        const MovingPoint* all[5] = {p[0], p[1], p[2], p.size() == 3 ? &y : p[3], &y};
        return in_sphere_vanishes_at_start(all, p.size() + 1);
      },
      u, delta);
}

// docs/MATH.md §5.7: the points span fewer than dim dimensions at every time of the slab iff, for a pair
// (3D: a triple) that spans a line (a plane) at some time, every orientation with another point
// vanishes identically; when every pair (triple) is degenerate for good the set is flat anyway.
bool flat_for_good(int dim, const StaticInput& input) {
  const std::vector<MovingPoint>& m = input.motion;
  const auto zero = [](const Poly<mpz_class>& f) {
    for (int i = 0; i <= f.degree_bound(); ++i)
      if (f[i] != 0)
        return false;
    return true;
  };
  if (m.size() < static_cast<std::size_t>(dim) + 1)
    return true;
  std::size_t third = 1; // 3D: a point not on the line of m[0] and m[1] for good
  if (dim == 3) {
    for (third = 2; third < m.size(); ++third) {
      const auto n = certificate::cross(certificate::difference<mpz_class>(m[0], m[1]),
                                        certificate::difference<mpz_class>(m[0], m[third]));
      if (!zero(n[0]) || !zero(n[1]) || !zero(n[2]))
        break;
    }
    if (third == m.size())
      return true; // all on one line for good
  }
  for (std::size_t x = 2; x < m.size(); ++x) {
    if (x == third)
      continue;
    const Poly<mpz_class> o = dim == 2 ? certificate::orientation_2<mpz_class>(m[0], m[1], m[x])
                                       : certificate::orientation<mpz_class>(m[0], m[1], m[third], m[x]);
    if (!zero(o))
      return false;
  }
  return true;
}

} // namespace medusa::kinetic::detail
