#include "run_input.h"

#include "medusa/core/error.h"

#include "medusa/core/version.h"
#include "medusa/io/cell_volumes.h"

#include <cstdio>
#include <filesystem>

namespace medusa::cli {

namespace fs = std::filesystem;

std::string input_stem(const std::string& input) {
  fs::path p = fs::absolute(fs::path(input)).lexically_normal();
  if (p.filename().empty())
    p = p.parent_path();
  std::string name = p.filename().string();
  for (const std::string suffix : {".gz", ".csv"})
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      name.erase(name.size() - suffix.size());
  // CC3D writes cells.csv.gz into the run's folder: that file is named after its folder.
  if (name == "cells" && !p.parent_path().filename().empty())
    name = p.parent_path().filename().string();
  return name.empty() || name == "." ? "run" : name;
}

io::RunSource choose_source(const std::string& input, const std::string& source) {
  if (source == "vtk")
    return io::RunSource::vtk;
  if (source == "csv")
    return io::RunSource::csv;
  // Default for a CC3D folder: CC3D's own centres (cells.csv.gz) are on the 10^-6 grid, while the
  // VTK voxel centroids are not and are snapped to it (docs/MATH.md §1.2, §1.3).
  const fs::path folder(input);
  std::error_code ec;
  if (fs::is_directory(folder, ec) &&
      (fs::exists(folder / "cells.csv.gz", ec) || fs::exists(folder / "cells.csv", ec)))
    return io::RunSource::csv;
  return io::RunSource::automatic;
}

namespace {

std::pair<std::string, std::string> radius_from_volumes(const io::RunData& data) {
  const double volume = io::median_cell_volume(data.volumes);
  if (!(volume > 0))
    throw InputError((data.sources.empty() ? std::string("input") : data.sources.front()) +
                     ": the median cell volume is " + std::to_string(volume) +
                     ", so no radius can be chosen from it; give one with --radius");
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", io::equivalent_radius(volume, data.trajectories.dimension));
  char note[160];
  std::snprintf(note, sizeof note, "auto: the radius of a %s of the median cell volume, %g %s",
                data.trajectories.dimension == 2 ? "disc" : "ball", volume,
                data.trajectories.dimension == 2 ? "pixels" : "voxels");
  return {buffer, note};
}

} // namespace

std::pair<std::string, std::string> resolve_radius(const std::string& requested, io::RunData& data) {
  std::pair<std::string, std::string> radius{requested, ""};
  if (requested == "auto")
    radius = radius_from_volumes(data);
  data.volumes = io::CellVolumes{};
  return radius;
}

medusa::RunInfo run_info(const io::RunData& data, const std::string& radius,
                         const std::string& command_line) {
  medusa::RunInfo info;
  info.radius = std::stod(radius);
  info.radius_text = radius;
  info.source_files = data.sources;
  info.input_warnings = data.warnings;
  info.command_line = command_line;
  info.software_version = medusa::version;
  info.position_source = data.position_convention;
  info.snap_policy = data.snap.snapped ? "nearest-ties-to-even" : "exact";
  info.snapped_positions = static_cast<std::uint64_t>(data.snap.moved);
  info.snap_max_displacement = data.snap.max_displacement();
  return info;
}

} // namespace medusa::cli
