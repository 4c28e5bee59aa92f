// Run metadata recorded in the store next to the medusa (docs/FORMAT.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa {

// What produced a medusa: the parameters and provenance a reader needs to interpret it. The grid
// scale and the dimension come with the input (kinetic::Trajectories).
struct RunInfo {
  double radius = 0.0;                   // rho, as a double (for output)
  std::string radius_text;               // rho exactly as the user gave it (decimal text)
  std::vector<std::string> source_files; // the CompuCell3D files read
  // What reading the input warned of, one line each as `medusa run` printed it (later frames missing,
  // snapshots left out, a cell split into several trajectories, ...): the results hold for what was
  // read, and a reader of the store must be able to tell so. Empty in stores written before it existed.
  std::vector<std::string> input_warnings;
  std::string command_line;
  std::string software_version;
  // Periodic lattice axes ("x,y"; empty for an open run) and their periods in grid units (0 on open
  // axes): the medusa is then the one on the torus, its positions unwrapped (docs/MATH.md §8).
  std::string periodic_axes;
  std::array<std::int64_t, 3> periodic_lengths{};
  // Where the positions came from and whether they were moved onto the grid (docs/MATH.md §1.1,
  // §1.3): every exact answer is exact for the recorded positions.
  std::string position_source;         // e.g. "csv-centres", "vtk-centroids-voxel-corner"; "" unknown
  std::string snap_policy;             // "exact" (never moved) or "nearest-ties-to-even" (policy R)
  std::uint64_t snapped_positions = 0; // positions (cell, frame) moved by snapping
  double snap_max_displacement = 0.0;  // largest move of one coordinate, grid units (<= 1/2)
  // 32 lowercase hex digits (128 random bits) naming this run; `medusa run` writes it into the store
  // and into every side output, so that files of two runs are never taken for one (docs/FORMAT.md).
  // Empty in stores written before it existed.
  std::string run_id;
};

} // namespace medusa
