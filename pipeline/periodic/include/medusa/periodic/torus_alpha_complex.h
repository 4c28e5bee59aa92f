// The static alpha complex on the torus (or T^2 x interval, T^2 or circle x interval in the plane)
// computed from scratch with CGAL: the oracle of the periodic audit (docs/MATH.md §8.7).
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/kinetic/simplex.h"

#include <gmpxx.h>

#include <array>
#include <vector>

namespace medusa::periodic {

// Which static construction decided: CGAL's periodic Delaunay triangulation (every axis periodic with
// one period: Periodic_3_Delaunay_triangulation_3, Periodic_2_Delaunay_triangulation_2 in the plane),
// or the Delaunay triangulation of the 3^p tiled copies of the points (any other domain).
enum class TorusOracle { periodic_triangulation, tiled_copies };

struct TorusPoint {
  kinetic::VertexId id = 0;          // the cell's vertex id
  std::array<mpq_class, 3> position; // grid units, any lift (wrapped into the domain here)
};

struct TorusAlphaComplex {
  TorusOracle oracle = TorusOracle::tiled_copies;
  bool full_dimensional = true;          // false: the points span less than `dim` dimensions
  std::vector<kinetic::Simplex> complex; // sorted; vertices included; named by the points' ids
};

// Whether CGAL's periodic triangulations apply to the domain in dimension dim (2 or 3).
bool periodic_triangulation_applies(int dim, const io::PeriodicDomain& domain);

// The fixed-radius alpha complex (radius^2 = rho2, grid units) of the periodic point set on the
// domain's torus, each simplex named by the sorted ids of its vertices. Requires 4 rho below every
// period (docs/MATH.md §8.3). `force_tiled` computes it from the tiled copies even where CGAL's
// periodic triangulation applies (the two constructions check each other in the tests).
TorusAlphaComplex torus_alpha_complex(int dim, const io::PeriodicDomain& domain,
                                      const std::vector<TorusPoint>& points,
                                      const kinetic::SquaredRadius& rho2, bool force_tiled = false);

} // namespace medusa::periodic
