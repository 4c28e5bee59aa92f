#include "medusa/kinetic/trajectories.h"

#include "medusa/core/error.h"

#include <string>

namespace medusa::kinetic {

void Trajectories::validate() const {
  if (dimension != 2 && dimension != 3)
    throw InputError("run dimension must be 2 or 3, got " + std::to_string(dimension));
  if (scale <= 0)
    throw InputError("grid scale must be positive, got " + std::to_string(scale));
  if (frame_times.empty())
    throw InputError("run has no frames");
  for (std::size_t k = 1; k < frame_times.size(); ++k)
    if (frame_times[k] <= frame_times[k - 1])
      throw InputError("frame times must increase strictly: frame " + std::to_string(k) + " has time " +
                       std::to_string(frame_times[k]) + " after " + std::to_string(frame_times[k - 1]));
  // Coordinates must stay within 2^40 grid units so that certificate filters evaluate their inputs
  // exactly in double (docs/MATH.md §1.5 assumes |X| < 2^30; we allow headroom).
  constexpr std::int64_t limit = std::int64_t(1) << 40;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Trajectory& c = cells[i];
    if (c.positions.empty())
      throw InputError("cell " + std::to_string(c.cell_id) + " has no positions");
    if (c.last_frame() >= frame_times.size())
      throw InputError("cell " + std::to_string(c.cell_id) + " is present after the last frame");
    for (std::size_t f = 0; f < c.positions.size(); ++f)
      for (int a = 0; a < 3; ++a)
        if (c.positions[f][a] >= limit || c.positions[f][a] <= -limit)
          throw InputError("cell " + std::to_string(c.cell_id) + " at frame " +
                           std::to_string(c.first_frame + f) +
                           ": coordinate out of range for the grid scale " + std::to_string(scale));
  }
}

} // namespace medusa::kinetic
