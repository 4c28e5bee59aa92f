// `medusa run`: CC3D run -> trajectories -> kinetic alpha complex -> medusa store -> diagrams
// (MATH.md 1-7), with a plain-words summary on stdout.
#include "atomic_file.h"
#include "commands.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "run_summary.h"
#include "svg_plot.h"

#include "medusa/complex/medusa_builder.h"
#include "medusa/complex/store_reader.h"
#include "medusa/complex/store_writer.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/error.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace medusa::cli {
namespace {

namespace fs = std::filesystem;

struct RunArguments {
  std::string input;
  std::string output;
  std::string radius = "auto";
  std::string source;
  bool audit = false, snap = false, periodic_as_open = false, quiet = false, progress = false;
};

// Forwards the event stream to the builder; reports frames on stderr and polls for interrupts.
// libkinetic reports t_end with the batch index of the last event batch, while the builder wants
// the end strictly after every batch (MATH.md 6.2: cells alive at t_end die at the final virtual
// time); the end is then given the next batch index.
class ProgressObserver : public kinetic::Observer {
public:
  ProgressObserver(kinetic::Observer& next, std::size_t frames, bool show)
      : next_(next), frames_(frames), show_(show) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& complex) override {
    last_batch_ = t0.batch;
    next_.initial(t0, complex);
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    check_interrupted();
    last_batch_ = std::max(last_batch_, time.batch);
    next_.batch(time, steps);
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override {
    check_interrupted();
    next_.frame(k, time);
    if (show_)
      std::cerr << "\rmedusa: frame " << k + 1 << " of " << frames_ << std::flush;
  }
  void finish(const kinetic::EventTime& t_end) override {
    kinetic::EventTime end = t_end;
    end.batch = std::max(end.batch, last_batch_ + 1);
    next_.finish(end);
    if (show_)
      std::cerr << "\rmedusa: frame " << frames_ << " of " << frames_ << "\n";
  }

private:
  kinetic::Observer& next_;
  std::size_t frames_;
  bool show_;
  std::size_t last_batch_ = 0;
};

// `<input-name>` of a folder or a cells.csv[.gz] file, for the default store name.
std::string input_stem(const std::string& input) {
  fs::path p = fs::path(input).lexically_normal();
  if (p.filename().empty())
    p = p.parent_path();
  std::string name = p.filename().string();
  for (const std::string suffix : {".gz", ".csv"})
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      name.erase(name.size() - suffix.size());
  return name.empty() || name == "." ? "run" : name;
}

std::string output_stem(const std::string& output) {
  const std::string suffix = ".h5";
  if (output.size() > suffix.size() &&
      output.compare(output.size() - suffix.size(), suffix.size(), suffix) == 0)
    return output.substr(0, output.size() - suffix.size());
  return output;
}

io::RunSource choose_source(const RunArguments& args) {
  if (args.source == "vtk")
    return io::RunSource::vtk;
  if (args.source == "csv")
    return io::RunSource::csv;
  // Default for a CC3D folder: CC3D's own centres (cells.csv.gz) are on the 10^-6 grid, while the
  // VTK voxel centroids are not and would need --snap (MATH.md 1.2, 1.3).
  const fs::path folder(args.input);
  std::error_code ec;
  if (fs::is_directory(folder, ec) &&
      (fs::exists(folder / "cells.csv.gz", ec) || fs::exists(folder / "cells.csv", ec)))
    return io::RunSource::csv;
  return io::RunSource::automatic;
}

std::string radius_from_volumes(const io::RunData& data) {
  const double volume = io::median_cell_volume(data.volumes);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f", io::equivalent_radius(volume, data.trajectories.dimension));
  return buffer;
}

// Diagrams from the stored cells, so that what later commands see is what the summary describes.
void write_diagrams_and_summary(const std::string& output, const std::string& stem,
                                const kinetic::KineticStatistics& stats, const std::string& radius) {
  const complex::Medusa medusa = complex::read_store(output);
  const std::vector<int> vertex_type = vertex_types(medusa);
  std::vector<persistence::Diagram> diagrams =
      persistence::compute_medusa_diagrams(medusa.cells, vertex_type, distinct_types(vertex_type));
  // The diagrams go into the store too (group /persistence, docs/FORMAT.md), written atomically.
  persistence::write_diagrams(output, diagrams);
  check_interrupted();
  std::vector<persistence::Diagram> shown;
  for (const persistence::Diagram& d : diagrams)
    shown.push_back(persistence::without_zero_length(d));
  check_interrupted();

  const double t0 = static_cast<double>(medusa.input.frame_times.front());
  const double t_end = static_cast<double>(medusa.input.frame_times.back());
  write_file_atomically(stem + ".diagrams.csv", [&](std::ostream& out) { write_csv(out, shown); });
  write_file_atomically(stem + ".barcode.svg",
                        [&](std::ostream& out) { write_barcode_svg(out, shown, t0, t_end); });
  check_interrupted();

  write_run_summary(std::cout, medusa, stats, diagrams, radius);
  std::cout << "wrote " << output << ", " << stem << ".diagrams.csv, " << stem << ".barcode.svg\n";
}

void run_command(const RunArguments& args, const std::string& command_line) {
  const std::string input =
      args.input.empty() ? std::string(MEDUSA_SOURCE_DIR) + "/examples/sorting_3d" : args.input;
  std::error_code ec;
  if (!fs::exists(input, ec))
    throw InputError("input " + input + " does not exist");

  RunArguments resolved = args;
  resolved.input = input;
  io::RunOptions options;
  options.source = choose_source(resolved);
  options.snap = args.snap;
  options.allow_periodic_as_open = args.periodic_as_open;
  const io::RunData data = io::read_run(input, options);
  if (!args.quiet)
    for (const std::string& w : data.warnings)
      std::cerr << "medusa: warning: " << w << "\n";

  const std::string radius = args.radius == "auto" ? radius_from_volumes(data) : args.radius;
  kinetic::KineticOptions kinetic_options;
  kinetic_options.rho2 = kinetic::squared_radius_from_decimal(radius, data.trajectories.scale);
  kinetic_options.audit = args.audit;

  const std::string output = args.output.empty() ? input_stem(input) + ".h5" : args.output;
  complex::RunInfo info;
  info.radius = std::stod(radius);
  info.radius_text = radius;
  info.source_files = data.sources;
  info.command_line = command_line;
  info.software_version = MEDUSA_VERSION;

  kinetic::KineticAlphaComplex engine(data.trajectories, kinetic_options);
  {
    complex::StoreWriter writer(output);
    complex::MedusaBuilder builder(writer);
    builder.set_run(info, data.trajectories);
    const bool show = args.progress || (!args.quiet && ::isatty(STDERR_FILENO) != 0);
    ProgressObserver observer(builder, data.trajectories.frames(), show);
    engine.run(observer);
  }

  // README: an interrupted run leaves no output behind, including a store already completed.
  const std::string stem = output_stem(output);
  const std::vector<std::string> outputs = {output, stem + ".diagrams.csv", stem + ".barcode.svg"};
  try {
    check_interrupted();
    write_diagrams_and_summary(output, stem, engine.statistics(), radius);
  } catch (const Interrupted&) {
    for (const std::string& path : outputs)
      fs::remove(path, ec);
    throw;
  }
}

} // namespace

void add_run_command(CLI::App& app, const std::string& command_line) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* run = app.add_subcommand(
      "run", "Compute the alpha medusa of a CompuCell3D run, store it, and write its persistence diagrams");
  run->add_option("input", args->input,
                  "CC3D output folder or cells.csv[.gz] (default: the bundled examples/sorting_3d)");
  run->add_option("-o,--output", args->output, "HDF5 store to write (default: <input-name>.h5 here)");
  run->add_option("--radius", args->radius,
                  "alpha radius rho in lattice units (decimal), or 'auto' = "
                  "equivalent-sphere radius of the median cell volume")
      ->capture_default_str();
  run->add_option("--source", args->source,
                  "positions from 'csv' (cells.csv.gz, CC3D centres; default for a folder that has it) or "
                  "'vtk' (exact voxel centroids; these lie off the 10^-6 grid, so they need --snap)")
      ->check(CLI::IsMember({"csv", "vtk"}));
  run->add_flag("--snap", args->snap, "snap VTK centroids to the 10^-6 grid (recorded in the store)");
  run->add_flag("--periodic-as-open", args->periodic_as_open,
                "read a periodic run as if its boundaries were open");
  run->add_flag("--audit", args->audit,
                "check the kinetic structure against static CGAL computations (slow)");
  run->add_flag("--progress", args->progress, "report frames on stderr even when it is not a terminal");
  run->add_flag("-q,--quiet", args->quiet, "no warnings and no progress on stderr");
  run->callback([args, command_line] { run_command(*args, command_line); });
}

} // namespace medusa::cli
