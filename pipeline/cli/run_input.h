// Choosing what `medusa run` and `medusa sweep` read from a CC3D run, and the names they derive from it.
#pragma once

#include "medusa/io/run_reader.h"
#include "medusa/medusa/run_info.h"

#include <string>
#include <utility>

namespace medusa::cli {

// `<input-name>` of a folder or a name.csv[.gz] file, for default output names ("run" if none);
// CC3D's own dir/cells.csv.gz is named after dir.
std::string input_stem(const std::string& input);

// `source` is "csv", "vtk" or empty; empty picks CC3D's own centres (cells.csv.gz) for a folder that
// has them, else lets the reader decide (VTK centroids are snapped to the grid, docs/MATH.md §1.3).
io::RunSource choose_source(const std::string& input, const std::string& source);

// The radius of `--radius requested` as decimal text, and how it was chosen, for the summary (empty
// unless chosen). "auto" (docs/MATH.md §7.10) is the equivalent-sphere (disc in 2D) radius of the
// median cell volume, with 6 digits. The volumes serve nothing else: they are let go here, before the
// kinetic stage, whose peak they would add to (a value per cell and frame).
std::pair<std::string, std::string> resolve_radius(const std::string& requested, io::RunData& data);

// What the store records of a run read as `data` at radius `radius` (decimal text): radius, sources,
// positions and their snapping, command line and version. The caller adds the run id and the periodic
// axes when there are any.
medusa::RunInfo run_info(const io::RunData& data, const std::string& radius, const std::string& command_line);

} // namespace medusa::cli
