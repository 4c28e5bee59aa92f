// The signs just after a rational time u that decide whether a static triangulation built at
// u + delta is Del(u+) (MATH.md 5.5, method A): each a certificate polynomial of MATH.md 3.1, its
// value on u's enclosure when that excludes zero (then it is the sign on (u, u + eps) too), else
// sign^+_u of the exact polynomial.
#include "static_delaunay.h"

#include "medusa/kinetic/algebraic_time.h"
#include "medusa/kinetic/certificate_polynomials.h"

#include <CGAL/FPU.h>

namespace medusa::kinetic::detail {

namespace {

template <class Build> int sign_just_after(Build&& build, const Rational& u) {
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const std::pair<double, double> e = CGAL::to_interval(u);
    const Interval at(e.first, e.second);
    const int s = certified_sign(build(
        [at](const MovingPoint* p) {
          return certificate::PointAtTime{p, at};
        },
        Interval())[0]);
    if (s != 0)
      return s;
  }
  return sign_plus(to_exact_poly(build([](const MovingPoint* p) { return *p; }, mpz_class())), SlabTime(u));
}

} // namespace

int orientation_just_after(const std::vector<const MovingPoint*>& p, const Rational& u) {
  return sign_just_after(
      [&](auto at, auto nt) {
        using NT = decltype(nt);
        return p.size() == 3 ? certificate::orientation_2<NT>(at(p[0]), at(p[1]), at(p[2]))
                             : certificate::orientation<NT>(at(p[0]), at(p[1]), at(p[2]), at(p[3]));
      },
      u);
}

int in_sphere_just_after(const std::vector<const MovingPoint*>& p, const MovingPoint& y, const Rational& u) {
  return sign_just_after(
      [&](auto at, auto nt) {
        using NT = decltype(nt);
        return p.size() == 3 ? certificate::in_circle<NT>(at(p[0]), at(p[1]), at(p[2]), at(&y))
                             : certificate::in_sphere<NT>(at(p[0]), at(p[1]), at(p[2]), at(p[3]), at(&y));
      },
      u);
}

} // namespace medusa::kinetic::detail
