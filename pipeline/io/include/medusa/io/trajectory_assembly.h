// Grouping per-frame cell samples into trajectories (docs/MATH.md §2.1).
#pragma once

#include "medusa/io/cell_sample.h"
#include "medusa/kinetic/trajectories.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io {

struct AssembledRun {
  kinetic::Trajectories trajectories;
  // volumes[i][f] = volume of trajectory i at frame first_frame + f; empty when a sample has none.
  std::vector<std::vector<std::int64_t>> volumes;
  std::vector<std::string> warnings;
};

// Sorts the samples into trajectories, ordered by cell id then first frame (vertex id = index).
// Frame times are `frame_times` if given (they must hold every sample's MCS), else the distinct MCS of
// the samples. The order of `samples` does not matter. A cell missing from intermediate frames is split
// into several trajectories with a warning; cells present on a single frame are legal and warned
// about (docs/MATH.md §2.1). Throws InputError naming file, line and cell for a duplicate (MCS, cell) or a
// cell whose type changes. `sources[s]` names the file of samples with source == s.
AssembledRun assemble_trajectories(std::vector<CellSample> samples, const std::vector<std::string>& sources,
                                   std::int64_t scale, int dimension,
                                   std::vector<std::int64_t> frame_times = {});

} // namespace medusa::io
