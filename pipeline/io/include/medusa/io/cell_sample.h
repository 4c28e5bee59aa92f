// One observation of one cell at one frame, as a reader produces it before the trajectories are
// assembled (docs/MATH.md §2.1).
#pragma once

#include "medusa/kinetic/trajectories.h"

#include <cstdint>

namespace medusa::io {

struct CellSample {
  std::int64_t mcs = 0;
  std::int64_t cell_id = 0;
  int type = 0;
  kinetic::GridPoint position{}; // grid integers (docs/MATH.md §1.1)
  std::int64_t volume = -1;      // voxels; -1 when the source does not give it
  std::size_t source = 0;        // index into the list of source files
  std::int64_t line = 0;         // line in that file (0: the whole file, e.g. a VTK snapshot)
};

} // namespace medusa::io
