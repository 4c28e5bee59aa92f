// The covering space of a periodic run: every cell (the "originals", unwrapped trajectories) and its
// periodic copies ("ghosts") wherever they come near the originals (docs/MATH.md §8.3-§8.4).
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/kinetic/simplex.h"
#include "medusa/kinetic/trajectories.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::periodic {

// Covering vertex v is original `original` translated by offset[a] periods along each axis a
// (offset 0 on open axes; all zero for the originals), or a sentinel (no cell).
struct CoverVertex {
  kinetic::VertexId original = 0; // -1 for a sentinel
  std::array<std::int64_t, 3> offset{};
  bool is_sentinel() const { return original < 0; }
  bool is_original() const { return !is_sentinel() && offset[0] == 0 && offset[1] == 0 && offset[2] == 0; }
};

struct PeriodicCover {
  // Originals first, with their vertex ids (0 .. originals-1), then the ghosts, then the sentinels. A
  // ghost carries its original's cell id and type, and is present on the frames where it may come
  // within 2 rho of an original (several trajectories when those frames are not consecutive). A
  // sentinel is a static point (cell id -1) more than 2 rho from every other point at every time, on
  // a box around them all: the covering space's convex hull is theirs (docs/MATH.md §8.4).
  kinetic::Trajectories trajectories;
  std::vector<CoverVertex> vertices; // per covering vertex
  std::size_t originals = 0, sentinels = 0;
  std::size_t ghosts() const { return vertices.size() - originals - sentinels; }
};

// The first periodic axis (0 x, 1 y, 2 z) whose period is at most 4 rho, or -1 when 4 rho is below every
// period: the condition under which the quotient of the covering complex is the alpha complex on the
// torus (docs/MATH.md §8.3). Exact.
int axis_too_short_for_radius(const io::PeriodicDomain& domain, const kinetic::SquaredRadius& rho2);

// Throws GeometryError unless 4 rho is below every period, the condition under which the quotient of
// the covering complex is the alpha complex on the torus (docs/MATH.md §8.3). `radius_text` is rho as
// the user gave it, for the message.
void check_periodic_radius(const io::PeriodicDomain& domain, const kinetic::SquaredRadius& rho2,
                           const std::string& radius_text);

// The originals (unwrapped, docs/MATH.md §8.2) and the ghosts needed for slab s: every copy whose position
// at frame s lies within 2 rho + 2 D_s of the bounding box of the originals at frame s along every
// periodic axis, D_s the largest coordinate displacement of any cell over slab s; and for every
// frame, the copies within 2 rho of that frame's box (docs/MATH.md §8.4); and the sentinels around them.
PeriodicCover cover_trajectories(const kinetic::Trajectories& originals, const io::PeriodicDomain& domain,
                                 const kinetic::SquaredRadius& rho2);

} // namespace medusa::periodic
