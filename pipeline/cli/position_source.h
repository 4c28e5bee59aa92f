// How a store's positions were obtained, in plain words (docs/MATH.md §1.2, §1.3): `medusa info` and
// the summary of `medusa run` say whether VTK centroids were snapped to the grid.
#pragma once

#include "medusa/medusa/run_info.h"

#include <string>

namespace medusa::cli {

// "CC3D centres (cells.csv), on the grid", "VTK voxel centroids snapped to the grid: ...", or the raw
// values for a source this version does not know; "not recorded" for stores that predate them.
std::string describe_positions(const medusa::RunInfo& run);

// True if the positions are VTK voxel centroids (the summary of `medusa run` mentions them).
bool positions_from_vtk(const medusa::RunInfo& run);

} // namespace medusa::cli
