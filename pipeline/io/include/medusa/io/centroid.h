// VTK centroids X / n on the grid (docs/MATH.md §1.3): exact when n divides X, otherwise snapped to the
// nearest grid point (policy R) unless the caller asks for exact positions.
#pragma once

#include "medusa/kinetic/trajectories.h"

#include <array>
#include <cstdint>

namespace medusa::io {

// What policy R did to a run (written into output headers by the caller, docs/MATH.md §1.1): VTK
// centroids snapped to the grid, or CSV centres rounded to it on request.
struct SnapReport {
  bool snapped = false;       // policy R was in force (the caller did not ask for exact positions)
  std::int64_t positions = 0; // positions (cell, frame) read under policy R
  std::int64_t moved = 0;     // of these, positions with at least one coordinate moved
  // Largest displacement of one coordinate, in grid units, as the exact fraction num / den (<= 1/2).
  std::int64_t max_displacement_num = 0;
  std::int64_t max_displacement_den = 1;
  double max_displacement() const { return double(max_displacement_num) / double(max_displacement_den); }
  // Keeps num / den (den > 0) as the largest displacement if it is larger.
  void widen(std::int64_t num, std::int64_t den) {
    __extension__ using Wide = __int128; // exact cross-multiplication of two int64 fractions
    if (static_cast<Wide>(num) * max_displacement_den > static_cast<Wide>(max_displacement_num) * den) {
      max_displacement_num = num;
      max_displacement_den = den;
    }
  }
};

// True if n divides every component of X (the centroid X / n is a grid point).
bool centroid_on_grid(const std::array<std::int64_t, 3>& scaled_sum, std::int64_t n);

// X / n rounded per coordinate to the nearest integer, ties to even (policy R); records the move
// in `report`. n must be positive.
kinetic::GridPoint snap_centroid(const std::array<std::int64_t, 3>& scaled_sum, std::int64_t n,
                                 SnapReport& report);

} // namespace medusa::io
