// Static Delaunay triangulations and alpha complexes computed from scratch with CGAL: the initial
// triangulation, insertions and deletions at frames (docs/MATH.md §5.5, method A: points frozen at a small
// rational delta after the frame) and the oracle of audit(). `dim` is the dimension of the run: 3
// (Delaunay_triangulation_3, Fixed_alpha_shape_3) or 2 (the points' x and y; Delaunay_triangulation_2,
// Alpha_shape_2 in GENERAL mode).
#pragma once

#include "medusa/kinetic/simplex.h"
#include "moving_point.h"

#include <CGAL/Gmpq.h>

#include <vector>

namespace medusa::kinetic::detail {

struct StaticInput {
  std::vector<VertexId> ids;
  std::vector<MovingPoint> motion;
};

// Top simplices (tetrahedra, triangles in 2D; infinite vertex = -1) of Del(u+), the Delaunay
// triangulation of the points a + (u + eps) b for every small eps > 0 (docs/MATH.md §5.5, method A): CGAL's
// triangulation of the points at u + delta for a dyadic delta, accepted when no certificate it rests
// on has a root in (u, u + delta] (just_after_holds, static_cgal.h), and built again with a smaller
// delta otherwise. Returns the affine dimension of the point set in `dimension` (the result is empty
// when it is below dim).
std::vector<Simplex> delaunay_just_after(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                         int& dimension);

// Whether the orientation of the points p (three: planar, four: 3D), or the in-circle / in-sphere test
// of p and y (certificate_polynomials.h), has no root in (u, u + delta]; identically zero has none.
bool orientation_keeps_sign(const std::vector<const MovingPoint*>& p, const CGAL::Gmpq& u,
                            const CGAL::Gmpq& delta);
bool in_sphere_keeps_sign(const std::vector<const MovingPoint*>& p, const MovingPoint& y, const CGAL::Gmpq& u,
                          const CGAL::Gmpq& delta);
// Whether the points span fewer than dim dimensions at every time of the slab (docs/MATH.md §5.7).
bool flat_for_good(int dim, const StaticInput& input);

// Top simplices of the Delaunay triangulation of the points a + u b exactly at the rational u
// (CGAL's symbolic perturbation decides among cospherical sets).
std::vector<Simplex> delaunay_at(int dim, const StaticInput& input, const CGAL::Gmpq& u, int& dimension);

// The finite simplices (all dimensions) of the fixed-radius alpha complex of the points a + u b,
// u rational, radius^2 = rho2 (grid units), computed with CGAL's Delaunay_triangulation_3 and
// Fixed_alpha_shape_3 (2D: Delaunay_triangulation_2 and Alpha_shape_2) over an exact kernel. `tops`
// receives the Delaunay top simplices (infinite = -1).
std::vector<Simplex> static_alpha_complex(int dim, const StaticInput& input, const CGAL::Gmpq& u,
                                          const CGAL::Gmpq& rho2, std::vector<Simplex>& tops);

// The same per dimension D = dim, specialised in static_delaunay_2.cpp and static_delaunay_3.cpp (the
// functions above choose the points and dispatch): Delaunay top simplices of the points 2^k a + b
// (exact in doubles; `holds`: Del(0+), delta = 2^-k), of the points a + u b exactly (given `after`,
// `holds`: Del(after+), delta = u - after), and the alpha complex at u.
template <int D>
std::vector<Simplex> delaunay_of_scaled(const StaticInput& input, int k, int& dimension, bool& holds);
template <int D>
std::vector<Simplex> delaunay_of_exact(const StaticInput& input, const CGAL::Gmpq& u, int& dimension,
                                       const CGAL::Gmpq* after = nullptr, bool* holds = nullptr);
template <int D>
std::vector<Simplex> alpha_complex_of_exact(const StaticInput& input, const CGAL::Gmpq& u,
                                            const CGAL::Gmpq& rho2, std::vector<Simplex>& tops);
template <> std::vector<Simplex> delaunay_of_scaled<2>(const StaticInput&, int, int&, bool&);
template <> std::vector<Simplex> delaunay_of_scaled<3>(const StaticInput&, int, int&, bool&);
template <>
std::vector<Simplex> delaunay_of_exact<2>(const StaticInput&, const CGAL::Gmpq&, int&, const CGAL::Gmpq*,
                                          bool*);
template <>
std::vector<Simplex> delaunay_of_exact<3>(const StaticInput&, const CGAL::Gmpq&, int&, const CGAL::Gmpq*,
                                          bool*);
template <>
std::vector<Simplex> alpha_complex_of_exact<2>(const StaticInput&, const CGAL::Gmpq&, const CGAL::Gmpq&,
                                               std::vector<Simplex>&);
template <>
std::vector<Simplex> alpha_complex_of_exact<3>(const StaticInput&, const CGAL::Gmpq&, const CGAL::Gmpq&,
                                               std::vector<Simplex>&);

} // namespace medusa::kinetic::detail
