// `medusa info`: what a store holds (docs/FORMAT.md).
#include "cell_type.h"
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "position_source.h"
#include "recorded_domain.h"
#include "side_outputs.h"

#include "medusa/medusa/store_reader.h"

#include <iostream>
#include <memory>

namespace medusa::cli {
namespace {

// Open, or periodic along which axes with which periods (docs/MATH.md §8).
std::string describe_domain(const medusa::Medusa& medusa) {
  const std::string periodic = periodic_domain_text(
      medusa.run, medusa.input.scale,
      "; loops that close through the boundary: column 'wraps' of `medusa classes --dim 1`");
  return periodic.empty() ? "open (no periodic boundary)" : periodic;
}

void info_command(const std::string& path) {
  const medusa::Medusa medusa = medusa::read_store(path);
  check_side_outputs(path, medusa.run.run_id);
  const kinetic::Trajectories& input = medusa.input;
  std::cout
      << "store: " << path << "\n"
      << "run id: " << (medusa.run.run_id.empty() ? "none" : medusa.run.run_id) << "\n"
      << "software version: " << medusa.run.software_version << "\n"
      << "command line: " << medusa.run.command_line << "\n"
      << "radius: " << medusa.run.radius_text << "\n"
      << "contacts: two cells touch when their balls of radius " << medusa.run.radius_text
      << " lattice units overlap inside their Voronoi regions (about: centres at most twice that apart; "
         "docs/MATH.md §4.1)\n"
      << "source files: " << medusa.run.source_files.size() << "\n";
  for (const std::string& f : medusa.run.source_files)
    std::cout << "  " << f << "\n";
  // What reading the input warned of: the results hold for what was read (docs/FORMAT.md).
  std::cout << "input warnings: " << medusa.run.input_warnings.size() << "\n";
  for (const std::string& w : medusa.run.input_warnings)
    std::cout << "  " << w << "\n";
  std::cout << "dimension: " << input.dimension << "\n"
            << "grid scale: " << input.scale << "\n"
            << "positions: " << describe_positions(medusa.run) << "\n"
            << "domain: " << describe_domain(medusa) << "\n"
            << "cells: " << input.cells.size() << "\n"
            << "frames: " << input.frames() << "\n";
  if (!input.frame_times.empty())
    std::cout << "MCS: " << input.frame_times.front() << " to " << input.frame_times.back() << "\n";
  std::cout << "batches: " << medusa.batches.size() << "\n"
            << "medusa cells: " << medusa.cells.size() << "\n";
  // Space-time cells go up to one dimension above space (a 2-3 flip in 3D, a 2-2 flip in the plane).
  for (int k = 0; k <= input.dimension + 1; ++k)
    std::cout << "  dimension " << k << ": " << medusa.cells_of_dimension(k).size() << "\n";
  const std::vector<int> types = vertex_types(medusa);
  std::cout << "cell types:";
  for (int t : distinct_types(types)) {
    std::size_t count = 0;
    for (int v : types)
      count += v == t ? 1 : 0;
    const std::string name = cell_type_name(input, t);
    std::cout << " " << t << (name.empty() ? "" : " (" + name + ")") << ": " << count << ";";
  }
  std::cout << "\n";
}

} // namespace

void add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* info = app.add_subcommand("info", "Describe what a medusa store holds");
  info->add_option("store", *path, "HDF5 store written by `medusa run`")->required();
  info->callback([path] { info_command(*path); });
}

} // namespace medusa::cli
