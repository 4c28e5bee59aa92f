// The two constructions of the static alpha complex on the torus, per dimension
// (torus_alpha_complex_2.cpp, torus_alpha_complex_3.cpp; docs/MATH.md §8.7). The points are wrapped
// into the domain. With `integral`, every coordinate (and period) is an integer below 2^50 in
// magnitude: doubles hold the points and their tiled copies exactly, and Epick decides.
#pragma once

#include "medusa/periodic/torus_alpha_complex.h"

namespace medusa::periodic::detail {

// CGAL's periodic Delaunay triangulation of the points on the cube (square) of side L.
template <int D>
std::vector<kinetic::Simplex> periodic_triangulation_alpha(const io::PeriodicDomain& domain,
                                                           const std::vector<TorusPoint>& points,
                                                           const mpq_class& rho2, bool integral);
// CGAL's Delaunay triangulation of the 3^p copies of the points shifted by -1, 0, 1 periods along the
// p periodic axes; `full_dimensional` false when they span fewer than D dimensions.
template <int D>
std::vector<kinetic::Simplex> tiled_copies_alpha(const io::PeriodicDomain& domain,
                                                 const std::vector<TorusPoint>& points, const mpq_class& rho2,
                                                 bool integral, bool& full_dimensional);

template <>
std::vector<kinetic::Simplex> periodic_triangulation_alpha<2>(const io::PeriodicDomain&,
                                                              const std::vector<TorusPoint>&,
                                                              const mpq_class&, bool);
template <>
std::vector<kinetic::Simplex> periodic_triangulation_alpha<3>(const io::PeriodicDomain&,
                                                              const std::vector<TorusPoint>&,
                                                              const mpq_class&, bool);
template <>
std::vector<kinetic::Simplex> tiled_copies_alpha<2>(const io::PeriodicDomain&, const std::vector<TorusPoint>&,
                                                    const mpq_class&, bool, bool&);
template <>
std::vector<kinetic::Simplex> tiled_copies_alpha<3>(const io::PeriodicDomain&, const std::vector<TorusPoint>&,
                                                    const mpq_class&, bool, bool&);

} // namespace medusa::periodic::detail
