// Static Delaunay triangulations and alpha complexes computed from scratch with CGAL: the initial
// triangulation, insertions and deletions at frames (MATH.md 5.5, method A: points frozen at a small
// rational delta after the frame) and the oracle of audit().
#pragma once

#include "medusa/kinetic/moving_point.h"
#include "medusa/kinetic/simplex.h"

#include <CGAL/Gmpq.h>

#include <vector>

namespace medusa::kinetic::detail {

struct StaticInput {
  std::vector<VertexId> ids;
  std::vector<MovingPoint> motion;
};

// Tetrahedra (infinite vertex = -1) of the Delaunay triangulation of the points a + (u + delta) b
// for the rational u and a small dyadic delta > 0 chosen so that the coordinates stay exact. Returns the
// affine dimension of the point set in `dimension` (the tetrahedra are empty when it is below 3).
std::vector<Simplex> delaunay_just_after(const StaticInput& input, const CGAL::Gmpq& u, int& dimension);

// Tetrahedra of the Delaunay triangulation of the points a + u b exactly at the rational u (CGAL's
// symbolic perturbation decides among cospherical sets).
std::vector<Simplex> delaunay_at(const StaticInput& input, const CGAL::Gmpq& u, int& dimension);

// The finite simplices (all dimensions) of the fixed-radius alpha complex of the points a + u b,
// u rational, radius^2 = rho2 (grid units), computed with CGAL's Delaunay_triangulation_3 and
// Fixed_alpha_shape_3 over an exact kernel. `tets` receives the Delaunay tetrahedra (infinite = -1).
std::vector<Simplex> static_alpha_complex(const StaticInput& input, const CGAL::Gmpq& u,
                                          const CGAL::Gmpq& rho2, std::vector<Simplex>& tets);

} // namespace medusa::kinetic::detail
