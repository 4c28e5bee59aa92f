// Piecewise-linear trajectories of cell centres on the fixed-point grid (docs/MATH.md §1 and §2).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::kinetic {

// A grid point: physical coordinate x = X / scale, X an integer (docs/MATH.md §1.1).
using GridPoint = std::array<std::int64_t, 3>;

// One trajectory: a cell present on the consecutive frames first_frame .. first_frame+size-1.
struct Trajectory {
  std::int64_t cell_id = 0; // CompuCell3D cell id (several trajectories may share one, docs/MATH.md §2.1)
  int type = 0;             // CompuCell3D cell type (1, 2, ...; medium is never a trajectory)
  std::size_t first_frame = 0;
  std::vector<GridPoint> positions; // one per frame the cell is present

  std::size_t last_frame() const { return first_frame + positions.size() - 1; }
  bool present(std::size_t frame) const { return frame >= first_frame && frame <= last_frame(); }
  const GridPoint& at(std::size_t frame) const { return positions[frame - first_frame]; }
};

// A whole run: frame times shared by all cells, and the trajectories. Vertex id = index into cells.
struct Trajectories {
  int dimension = 3;                     // 3, or 2 for planar runs (z ignored)
  std::int64_t scale = 1000000;          // grid scale S (docs/MATH.md §1.1)
  std::vector<std::int64_t> frame_times; // strictly increasing (MCS)
  std::vector<Trajectory> cells;
  std::vector<std::string> type_names; // index = type id; may be empty

  std::size_t frames() const { return frame_times.size(); }
  // Throws InputError naming the offending frame or cell when the run is inconsistent.
  void validate() const;
};

} // namespace medusa::kinetic
