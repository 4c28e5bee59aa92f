// The choice of the static structure's points (frozen just after a frame, or exactly at a rational
// time) and the dispatch to the planar or 3D CGAL structures (static_delaunay_2.cpp, _3.cpp).
#include "static_delaunay.h"

#include <algorithm>
#include <cmath>

namespace medusa::kinetic::detail {

std::vector<Simplex> delaunay_just_after(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                         int& dimension) {
  // delta = 2^-k with the largest k <= 24 such that every coordinate 2^k a + b is an exact double;
  // invalid certificates left by a too large delta are repaired by flips at 0+ by the caller.
  double amax = 1, bmax = 1;
  for (const MovingPoint& m : input.motion)
    for (int i = 0; i < 3; ++i) {
      amax = std::max(amax, std::fabs(double(m.a[i])));
      bmax = std::max(bmax, std::fabs(double(m.b[i])));
    }
  int k = 24;
  while (k > 0 && std::ldexp(amax, k) + bmax >= std::ldexp(1.0, 52))
    --k;
  if (u == 0 && k >= 8)
    return dim == 2 ? delaunay_of_scaled<2>(input, k, dimension) : delaunay_of_scaled<3>(input, k, dimension);
  // Exact rational points at u + 2^-40 (used at interior rational times and for huge coordinates).
  return delaunay_at(dim, input, u + CGAL::Gmpq(1, CGAL::Gmpz(1) << 40), dimension);
}

std::vector<Simplex> delaunay_at(int dim, const StaticInput& input, const CGAL::Gmpq& u, int& dimension) {
  return dim == 2 ? delaunay_of_exact<2>(input, u, dimension) : delaunay_of_exact<3>(input, u, dimension);
}

std::vector<Simplex> static_alpha_complex(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                          const CGAL::Gmpq& rho2, std::vector<Simplex>& tets) {
  return dim == 2 ? alpha_complex_of_exact<2>(input, u, rho2, tets)
                  : alpha_complex_of_exact<3>(input, u, rho2, tets);
}

} // namespace medusa::kinetic::detail
