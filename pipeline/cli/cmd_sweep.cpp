// `medusa sweep`: the kinetic stage and the medusa for each of several radii, in parallel, and the
// CROCKER data of the run (Betti numbers of K_t over time and radius, docs/MATH.md §6.6) as CSV and SVG,
// with a one-line summary of the forward diagrams per radius (docs/MATH.md §7.6).
#include "atomic_file.h"
#include "commands.h"
#include "crocker.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "radius_sweep.h"
#include "run_input.h"

#include "medusa/core/error.h"
#include "medusa/core/version.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/periodic/periodic_cover.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace medusa::cli {
namespace {

namespace fs = std::filesystem;

struct SweepArguments {
  std::string input;
  std::vector<std::string> ranges; // A:B:STEP
  std::vector<std::string> radii;  // single radii
  std::string prefix;
  std::string source;
  unsigned threads = 0;
  bool snap = false, exact_vtk = false, round_csv = false, periodic_as_open = false, quiet = false;
};

// The radii in increasing order, each once (compared by exact decimal value).
std::vector<std::string> all_radii(const SweepArguments& args) {
  std::vector<std::string> texts = args.radii;
  for (const std::string& spec : args.ranges)
    expand_range(spec, &texts);
  try {
    return sorted_radii(texts);
  } catch (const InputError& e) {
    throw InputError(std::string("medusa sweep: ") + e.what());
  }
}

std::string summary_line(const RadiusResult& r, int dimension) {
  std::ostringstream out;
  out << "radius " << r.radius << ":";
  bool first = true;
  for (const auto& [label, c] : r.counts) {
    // The clusters are those of K_t at the first and last frames, as `medusa run` and `medusa report`
    // count them (the essential H0 classes would also drop the clusters that touched and separated).
    const auto slice = std::find_if(r.slices.begin(), r.slices.end(),
                                    [&label = label](const TypeSlices& s) { return s.label == label; });
    if (slice == r.slices.end() || slice->at_frame.empty())
      throw InternalError("sweep: no Betti numbers at the frames for " + label);
    const std::size_t start = slice->at_frame.front().betti[0], end = slice->at_frame.back().betti[0];
    out << (first ? " " : "; ") << (label == "all" ? "all cells" : "type " + label) << " " << start << " -> "
        << end << (end == 1 ? " cluster" : " clusters") << ", " << c.loops
        << (c.loops == 1 ? " loop (" : " loops (") << c.loops_filled << " filled), " << c.cavities
        << (dimension == 2 ? (c.cavities == 1 ? " space-time bubble" : " space-time bubbles")
                           : (c.cavities == 1 ? " cavity (" : " cavities (") +
                                 std::to_string(c.cavities_filled) + " filled)");
    first = false;
  }
  return out.str();
}

// Why a radius shows nothing of the sorting, or an empty string.
std::string radius_warning(const RadiusResult& r) {
  if (!r.edges)
    return "radius " + r.radius +
           ": no two cells are ever within the radius (K_t has no edge at any time), "
           "so every cell stays a cluster of its own; try a larger radius";
  for (const TypeSlices& s : r.slices)
    for (const Signature& g : s.at_frame)
      if (g.betti[0] != 1 || g.betti[1] != 0 || g.betti[2] != 0)
        return "";
  return "radius " + r.radius +
         ": from the first frame on, the whole complex and each type's subcomplex "
         "are one cluster without loops or cavities, so the radius is too large to show sorting; try a "
         "smaller radius";
}

void sweep_command(const SweepArguments& args) {
  const std::string prefix = args.prefix.empty() ? input_stem(args.input) : args.prefix;
  check_output_prefix(prefix, prefix + ".crocker.csv");
  const std::vector<std::string> radii = all_radii(args);
  if (radii.empty())
    throw CLI::RequiredError("--radii A:B:STEP or --radius R");
  std::error_code ec;
  if (!fs::exists(args.input, ec))
    throw InputError("input " + args.input + " does not exist");
  io::RunOptions options;
  options.source = choose_source(args.input, args.source);
  options.snap = !args.exact_vtk; // as `medusa run`: VTK centroids snapped unless --exact-vtk
  options.round_csv = args.round_csv;
  options.allow_periodic_as_open = args.periodic_as_open;
  options.read_periodic = !args.periodic_as_open;
  const io::RunData data = io::read_run(args.input, options);
  if (!args.quiet) {
    for (const std::string& w : data.warnings)
      std::cerr << "medusa: warning: " << w << "\n";
    for (const std::string& n : data.notes)
      std::cerr << "medusa: " << n << "\n";
  }
  // Bad radius text, and on a periodic run a radius too large for the period (docs/MATH.md §8.3),
  // fail here, before any work.
  for (const std::string& r : radii) {
    const kinetic::SquaredRadius rho2 = kinetic::squared_radius_from_decimal(r, data.trajectories.scale);
    if (data.domain.any() && !args.periodic_as_open)
      periodic::check_periodic_radius(data.domain, rho2, r);
  }
  const io::PeriodicDomain domain = args.periodic_as_open ? io::PeriodicDomain{} : data.domain;
  medusa::RunInfo info;
  info.source_files = data.sources;
  info.input_warnings = data.warnings;
  info.software_version = medusa::version;
  const unsigned workers = worker_threads(args.threads);
  if (!args.quiet)
    std::cerr << "medusa sweep: " << radii.size() << (radii.size() == 1 ? " radius" : " radii") << " on "
              << std::min<std::size_t>(workers, radii.size()) << " thread(s)\n";
  std::vector<RadiusResult> results;
  try {
    results = sweep_radii(data.trajectories, info, domain, radii, workers, true,
                          [&args](const std::string& radius, std::size_t, std::size_t) {
                            if (!args.quiet)
                              std::cerr << "medusa sweep: radius " << radius << " done\n";
                          });
  } catch (const GeometryError& e) {
    throw GeometryError(args.input + ": " + e.what()); // collisions name cells and times, not the file
  }
  const std::vector<CrockerRow> rows = crocker_rows(results, data.trajectories.frame_times);
  std::ostringstream summary;
  summary << "sweep of " << args.input << ": " << data.trajectories.cells.size() << " trajectories, "
          << data.trajectories.frames() << " frames, " << radii.size()
          << (radii.size() == 1 ? " radius;" : " radii;")
          << " clusters of K_t at the first -> the last frame; loops and cavities that appeared, from the "
             "forward diagrams (docs/MATH.md §7.6)\n";
  std::vector<std::string> warnings;
  for (const RadiusResult& r : results) {
    summary << summary_line(r, data.trajectories.dimension) << "\n";
    const std::string w = radius_warning(r);
    if (!w.empty()) {
      warnings.push_back(w);
      summary << "  warning: " << w << "\n";
    }
  }
  const std::vector<std::string> outputs = {prefix + ".crocker.csv", prefix + ".crocker.svg",
                                            prefix + ".sweep.txt"};
  try {
    write_file_atomically(outputs[0], [&](std::ostream& out) { write_crocker_csv(out, rows); });
    check_interrupted();
    write_file_atomically(outputs[1], [&](std::ostream& out) {
      write_crocker_svg(out, rows, "CROCKER plot of " + input_stem(args.input) + ": Betti numbers of K_t",
                        data.trajectories.dimension == 2 ? 1 : 2);
    });
    check_interrupted();
    write_file_atomically(outputs[2], [&](std::ostream& out) { out << summary.str(); });
    check_interrupted();
  } catch (...) {
    for (const std::string& path : outputs)
      fs::remove(path, ec);
    throw;
  }
  std::cout << summary.str();
  if (!args.quiet)
    for (const std::string& w : warnings)
      std::cerr << "medusa: warning: " << w << "\n";
  std::cout << "wrote " << outputs[0] << ", " << outputs[1] << ", " << outputs[2] << "\n";
}

} // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArguments>();
  CLI::App* sweep = app.add_subcommand("sweep", "Compute the medusa at several radii and write CROCKER data "
                                                "(Betti numbers of K_t over time and radius)");
  sweep->add_option("input", args->input, "CC3D output folder or cells.csv[.gz]")->required();
  sweep
      ->add_option("--radii", args->ranges,
                   "radii A:B:STEP (decimal, A to B inclusive in exact steps); may be repeated")
      ->check(CLI::Validator([](std::string& value) { return expand_range(value, nullptr); }, "A:B:STEP"));
  sweep->add_option("--radius", args->radii, "one more radius (decimal); may be repeated")
      ->check(CLI::Validator([](std::string& value) { return radius_error(value); }, "RADIUS"));
  sweep->add_option("-o,--output", args->prefix,
                    "output prefix: writes <prefix>.crocker.csv (radius,time,type,b0,b1,b2 at each frame), "
                    "<prefix>.crocker.svg and <prefix>.sweep.txt (default: <input-name>)");
  sweep->add_option("--source", args->source, "positions from 'csv' or 'vtk', as for `medusa run`")
      ->check(CLI::IsMember({"csv", "vtk"}));
  sweep->add_flag("--exact-vtk", args->exact_vtk,
                  "refuse VTK centroids off the 10^-6 grid instead of snapping them, as for `medusa run`");
  sweep->add_flag("--snap", args->snap, "snap VTK centroids to the 10^-6 grid (the default)");
  sweep->add_flag("--round-csv", args->round_csv,
                  "round CSV centres with more than 6 decimals to the 10^-6 grid (nearest, ties to even, "
                  "docs/MATH.md §1.2) instead of refusing them");
  sweep->add_flag("--periodic-as-open", args->periodic_as_open,
                  "read a periodic run as if its boundaries were open");
  sweep->add_option("--threads", args->threads, "radii computed at once (0 = one per hardware thread)")
      ->capture_default_str();
  sweep->add_flag("-q,--quiet", args->quiet, "no warnings and no progress on stderr");
  sweep->callback([args] {
    if (args->snap && args->exact_vtk)
      throw CLI::ValidationError("--exact-vtk", "contradicts --snap: give one of them");
    sweep_command(*args);
  });
}

} // namespace medusa::cli
