// The periodic axes of a CompuCell3D lattice in grid units, and the integer arithmetic of the torus
// they span (docs/MATH.md §8.1, §8.2).
#pragma once

#include "medusa/io/cc3d_xml.h"
#include "medusa/kinetic/trajectories.h"

#include <array>
#include <cstdint>
#include <string>

namespace medusa::io {

struct PeriodicDomain {
  std::array<bool, 3> periodic{};        // <Boundary_x>Periodic</Boundary_x> etc.
  std::array<std::int64_t, 3> origin{};  // grid units: the domain is [origin, origin + period)
  std::array<std::int64_t, 3> period{};  // grid units (S * spacing * lattice length); 0 on open axes
  std::array<std::int64_t, 3> lattice{}; // lattice length in voxels; 0 on open axes

  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  std::string axes() const; // "x", "x,y", ...; empty if none
};

// The periodic axes of `sim` with voxel (i,j,k) at origin + spacing * (i,j,k), all in grid units.
PeriodicDomain periodic_domain(const Cc3dSimulation& sim, const std::array<std::int64_t, 3>& origin,
                               const std::array<std::int64_t, 3>& spacing);

// d reduced modulo `period` into [-period/2, period/2): the minimum image of a difference.
std::int64_t minimum_image(std::int64_t d, std::int64_t period);

// x reduced modulo `period` into [origin, origin + period).
std::int64_t wrap_coordinate(std::int64_t x, std::int64_t origin, std::int64_t period);

// p with every periodic coordinate wrapped into the domain; open coordinates unchanged.
kinetic::GridPoint wrap_into_domain(const PeriodicDomain& domain, kinetic::GridPoint p);

} // namespace medusa::io
