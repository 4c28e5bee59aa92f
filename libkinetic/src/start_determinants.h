// Exact zero tests of the determinant certificates at a slab start (u = 0; docs/MATH.md §3.1, §5.5).
// There every point sits at its grid position a, so an orientation or in-sphere certificate is a
// static determinant of those positions. CGAL's filtered predicates decide its sign exactly
// (Epick: exact on double inputs, and every coordinate is an integer below 2^40,
// Trajectories::validate). The same value through Poly<mpz_class> costs an allocation per operation:
// on CC3D runs, whose frames are full of cospherical lattice sets, that was a tenth of the run.
#pragma once

#include "moving_point.h"

#include <cstddef>

namespace medusa::kinetic::detail {

// Whether O(p0, p1, p2, p3) (count 4) or O2(p0, p1, p2) (count 3, x and y only) is zero at u = 0.
// Runs CGAL's predicate rounding to nearest, the mode its static filter's error bound assumes, in
// whatever mode the caller is.
bool orientation_vanishes_at_start(const MovingPoint* const* p, std::size_t count);
// The same for a caller that already rounds to nearest (a CGAL::Protect_FPU_rounding guard set to
// CGAL_FE_TONEAREST over a loop of tests): switching the mode twice per test costs more than the test.
bool orientation_vanishes_at_start_in_nearest(const MovingPoint* const* p, std::size_t count);

// Whether InS(p0, .., p3; p4) (count 5) or InC(p0, p1, p2; p3) (count 4, x and y only) is zero at
// u = 0. A permutation of the points changes at most the determinant's sign, so the order does not
// matter.
bool in_sphere_vanishes_at_start(const MovingPoint* const* p, std::size_t count);

} // namespace medusa::kinetic::detail
