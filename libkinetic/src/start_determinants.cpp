// Static determinants at a slab start through CGAL's exact filtered predicates (start_determinants.h).
#include "start_determinants.h"

#include "medusa/core/error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>

namespace medusa::kinetic::detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Grid coordinates below 2^40 are exact doubles.
K::Point_3 at_start_3(const MovingPoint& m) {
  return {static_cast<double>(m.a[0]), static_cast<double>(m.a[1]), static_cast<double>(m.a[2])};
}
K::Point_2 at_start_2(const MovingPoint& m) {
  return {static_cast<double>(m.a[0]), static_cast<double>(m.a[1])};
}

} // namespace

bool orientation_vanishes_at_start(const MovingPoint* const* p, std::size_t count) {
  // The static filters' error bounds are for rounding to nearest; callers run with rounding upwards
  // (interval arithmetic). A filter misled by the mode could only fail to certify, never report a
  // false zero, but the predicates are meant to run in the mode they were written for.
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  return orientation_vanishes_at_start_in_nearest(p, count);
}

bool orientation_vanishes_at_start_in_nearest(const MovingPoint* const* p, std::size_t count) {
  CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_TONEAREST);
  if (count == 4)
    return CGAL::orientation(at_start_3(*p[0]), at_start_3(*p[1]), at_start_3(*p[2]), at_start_3(*p[3])) ==
           CGAL::COPLANAR;
  if (count == 3)
    return CGAL::orientation(at_start_2(*p[0]), at_start_2(*p[1]), at_start_2(*p[2])) == CGAL::COLLINEAR;
  throw InternalError("an orientation has 3 or 4 points");
}

bool in_sphere_vanishes_at_start(const MovingPoint* const* p, std::size_t count) {
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST); // as above
  // CGAL's side_of_oriented_sphere (circle) is the sign of det[(p_i - t, |p_i - t|^2)], the
  // determinant of InS (InC) with its rows permuted; it states no precondition on the points' own
  // orientation in its code, and a zero determinant reads as ON_ORIENTED_BOUNDARY.
  if (count == 5)
    return CGAL::side_of_oriented_sphere(at_start_3(*p[0]), at_start_3(*p[1]), at_start_3(*p[2]),
                                         at_start_3(*p[3]), at_start_3(*p[4])) == CGAL::ON_ORIENTED_BOUNDARY;
  if (count == 4)
    return CGAL::side_of_oriented_circle(at_start_2(*p[0]), at_start_2(*p[1]), at_start_2(*p[2]),
                                         at_start_2(*p[3])) == CGAL::ON_ORIENTED_BOUNDARY;
  throw InternalError("an in-sphere test has 4 or 5 points");
}

} // namespace medusa::kinetic::detail
