// `medusa.run`: the pipeline of `medusa run` in the calling process, without the CLI's progress,
// summary and exports: CC3D run -> kinetic alpha complex -> store -> diagrams and class
// representatives in its /persistence group (docs/MATH.md §1-§7).
#pragma once

#include <string>

namespace medusa::python {

struct RunRequest {
  std::string input;           // CC3D output folder or cells.csv[.gz]
  std::string radius = "auto"; // decimal, or "auto": the equivalent radius of the median cell volume
  std::string output;          // the store to write (default: <input name>.h5 in the working folder)
  std::string source;          // "", "csv" or "vtk", as `medusa run --source`
  bool snap = true;            // VTK centroids snapped to the grid, as `medusa run`; false: --exact-vtk
  unsigned threads = 0;        // 0: one per hardware thread
  bool force = false;          // replace an existing store (as `medusa run --force`)
  bool shorten_representatives = false; // as `medusa run --shorten-representatives`
  bool periodic_as_open = false;        // as `medusa run --periodic-as-open`
  bool round_csv = false;               // as `medusa run --round-csv`
  bool skip_unreadable_frames = false;  // as `medusa run --skip-unreadable-frames`
};

// Runs the pipeline and returns the path of the complete store. A periodic run is analysed on the torus
// as by `medusa run` (docs/MATH.md §8; a radius with 4 x radius not below a period is a GeometryError
// before anything is written), or as an open run with `periodic_as_open`. An existing store is an
// InputError unless `force`. Polls cli::check_interrupted() (throws cli::Interrupted). Throws medusa::Error;
// a failed or interrupted run leaves no store (nor replaces an existing one): the store is published only
// once complete with its diagrams.
std::string run_pipeline(const RunRequest& request, const std::string& command_line);

} // namespace medusa::python
