// The planar static structures behind static_delaunay.h (CGAL's Delaunay_triangulation_2 and
// Alpha_shape_2): the same contracts, with the points' x and y.
#pragma once

#include "static_delaunay.h"

#include <vector>

namespace medusa::kinetic::detail {

// Triangles of the Delaunay triangulation of the points 2^k a + b (the points a + 2^-k b scaled by
// 2^k, exact in doubles), with exact predicates.
std::vector<Simplex> delaunay_2_scaled(const StaticInput& input, int k, int& dimension);

// Triangles of the Delaunay triangulation of the points a + u b exactly at the rational u.
std::vector<Simplex> delaunay_2_at(const StaticInput& input, const CGAL::Gmpq& u, int& dimension);

// The planar alpha complex: CGAL's Alpha_shape_2 in GENERAL mode over an exact kernel.
std::vector<Simplex> static_alpha_complex_2(const StaticInput& input, const CGAL::Gmpq& u,
                                            const CGAL::Gmpq& rho2, std::vector<Simplex>& triangles);

} // namespace medusa::kinetic::detail
