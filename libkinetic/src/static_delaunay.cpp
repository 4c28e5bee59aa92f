// The choice of the static structure's points (frozen just after a frame, or exactly at a rational
// time) and the dispatch to the planar or 3D CGAL structures (static_delaunay_2.cpp, _3.cpp).
#include "static_delaunay.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>

namespace medusa::kinetic::detail {

std::vector<Simplex> delaunay_just_after(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                         int& dimension) {
  // docs/MATH.md §5.5, method A's practical variant: delta = 2^-k, k growing until no certificate of the
  // triangulation at u + delta has a root in (u, u + delta]. Certificates have finitely many roots,
  // so the loop ends (the cap only guards that; the bound of 5.5 is for u = 0, and at a rational u
  // it grows with u's denominator). At a frame (u = 0) the points 2^k a + b are exact doubles while
  // k is small enough, and Epick decides on them exactly; past that, and at interior rational times,
  // exact rational points.
  double amax = 1, bmax = 1;
  for (const MovingPoint& m : input.motion)
    for (int i = 0; i < 3; ++i) {
      amax = std::max(amax, std::fabs(double(m.a[i])));
      bmax = std::max(bmax, std::fabs(double(m.b[i])));
    }
  const auto exact_in_doubles = [&](int k) { return std::ldexp(amax, k) + bmax < std::ldexp(1.0, 52); };
  int k = 24;
  while (k > 0 && !exact_in_doubles(k))
    --k;
  bool holds = false;
  if (u == 0 && k >= 8)
    for (; exact_in_doubles(k); ++k) {
      std::vector<Simplex> tops = dim == 2 ? delaunay_of_scaled<2>(input, k, dimension, holds)
                                           : delaunay_of_scaled<3>(input, k, dimension, holds);
      if (holds)
        return tops;
    }
  for (k = std::max(k, 40);; k += 8) {
    if (k > 4096)
      throw InternalError("no delta found for the Delaunay triangulation just after a rational time");
    const CGAL::Gmpq at = u + CGAL::Gmpq(1, CGAL::Gmpz(1) << k);
    std::vector<Simplex> tops = dim == 2 ? delaunay_of_exact<2>(input, at, dimension, &u, &holds)
                                         : delaunay_of_exact<3>(input, at, dimension, &u, &holds);
    if (holds)
      return tops;
  }
}

std::vector<Simplex> delaunay_at(int dim, const StaticInput& input, const CGAL::Gmpq& u, int& dimension) {
  return dim == 2 ? delaunay_of_exact<2>(input, u, dimension) : delaunay_of_exact<3>(input, u, dimension);
}

std::vector<Simplex> static_alpha_complex(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                          const CGAL::Gmpq& rho2, std::vector<Simplex>& tops) {
  return dim == 2 ? alpha_complex_of_exact<2>(input, u, rho2, tops)
                  : alpha_complex_of_exact<3>(input, u, rho2, tops);
}

} // namespace medusa::kinetic::detail
