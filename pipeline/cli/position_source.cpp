#include "position_source.h"

#include <cstdio>

namespace medusa::cli {

bool positions_from_vtk(const medusa::RunInfo& run) { return run.position_source.rfind("vtk", 0) == 0; }

std::string describe_positions(const medusa::RunInfo& run) {
  if (run.position_source.empty())
    return "not recorded";
  std::string what;
  if (run.position_source == "csv-centres")
    what = "CC3D centres (cells.csv)";
  else if (run.position_source == "vtk-centroids-voxel-corner")
    what = "VTK voxel centroids";
  else
    what = run.position_source;
  if (run.snap_policy == "exact")
    return what + ", exact on the grid";
  // VTK centroids are snapped (docs/MATH.md §1.3), CSV centres rounded on request (§1.2).
  const bool vtk = positions_from_vtk(run);
  if (run.snapped_positions == 0)
    return what + ", all on the grid (none " + (vtk ? "snapped" : "rounded") + ")";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2g", run.snap_max_displacement);
  return what + (vtk ? " snapped" : " rounded") + " to the grid (" + run.snap_policy +
         "): " + std::to_string(run.snapped_positions) + " moved, at most " + buffer +
         " grid units per coordinate; exact results are for the " + (vtk ? "snapped" : "rounded") +
         " positions (docs/MATH.md " + (vtk ? "§1.3" : "§1.2") + ")";
}

} // namespace medusa::cli
