// `medusa report`: one self-contained HTML page for one or several stores: what the run was, whether and
// when each cell type's clusters joined (docs/MATH.md §6.6, §7.6), at which radii (a radius sweep read
// from `medusa sweep` or computed at report time), barcodes and diagrams with the CC3D cells behind
// each class, and distances between the runs (docs/MATH.md §7.7).
#include "atomic_file.h"
#include "commands.h"
#include "comparison.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "matrix_svg.h"
#include "radius_sweep.h"
#include "report_html.h"
#include "report_model.h"
#include "report_scale.h"

#include "medusa/core/error.h"
#include "medusa/persistence/clustering.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

namespace medusa::cli {
namespace {

struct ReportArguments {
  std::vector<std::string> stores;
  std::vector<std::string> sweeps;      // more CROCKER CSVs of `medusa sweep`
  std::vector<std::string> sweep_radii; // A:B:STEP
  bool no_sweep = false, quiet = false;
  std::size_t max_sweep_events = default_max_sweep_events;
  std::string output = "report.html";
  std::size_t max_bars = 1000;
  unsigned threads = 0;
};

// Bottleneck distances between the runs' H0 forward diagrams on normalised time, one heat map and
// dendrogram per type that every run has.
std::vector<ReportFigure> comparison_figures(const std::vector<ReportRun>& runs) {
  std::vector<ReportFigure> figures;
  if (runs.size() < 2)
    return figures;
  const ComparisonMetric metric("bottleneck", true);
  std::vector<std::string> names;
  for (const ReportRun& r : runs)
    names.push_back(r.name);
  for (const auto& [label, ignored] : runs.front().h0_points) {
    std::vector<persistence::PointDiagram> points;
    for (const ReportRun& r : runs) {
      const auto it = std::find_if(r.h0_points.begin(), r.h0_points.end(),
                                   [&](const auto& x) { return x.first == label; });
      if (it == r.h0_points.end())
        break;
      points.push_back(it->second);
    }
    // The whole tissue is one cluster in any run worth comparing; the types are what sorts.
    if (points.size() != runs.size() || label == "all")
      continue;
    check_interrupted();
    const persistence::DistanceMatrix distances = persistence::distance_matrix(
        points, [&metric](const auto& a, const auto& b) { return metric(a, b); }, 2);
    const persistence::Dendrogram dendrogram = persistence::average_linkage(distances);
    const std::string what = (label == "all" ? "all cells" : "type " + label) + ", H0 (clusters), forward";
    ReportFigure f;
    f.title = "Distances between the runs: " + what;
    f.notes.push_back(
        "Bottleneck distance between the runs' H0 diagrams (when clusters formed and joined) on "
        "normalised time (t - t0) / (t_end - t0), finite classes only (docs/MATH.md §7.7); "
        "average-linkage clustering. Runs that sort alike are close; as `medusa compare " +
        std::string("--type ") + label + " --dim 0 --ignore-essential`.");
    std::ostringstream heatmap, tree;
    write_heatmap_svg(heatmap, distances, names, what + ", bottleneck, normalised time");
    write_dendrogram_svg(tree, dendrogram, names, what + ", average linkage");
    f.svgs = {heatmap.str(), tree.str()};
    figures.push_back(std::move(f));
  }
  return figures;
}

void report_command(const ReportArguments& args) {
  check_output_path(args.output);
  const std::vector<std::string> names = run_names(args.stores);
  const unsigned threads = worker_threads(args.threads);
  std::vector<ReportRun> runs;
  for (std::size_t i = 0; i < args.stores.size(); ++i) {
    check_interrupted();
    runs.push_back(report_run(args.stores[i], names[i], args.max_bars, threads));
  }
  if (const std::string mixed = mixed_dimensions_note(runs); !mixed.empty() && !args.quiet)
    std::cerr << "medusa: warning: " << mixed << "\n";
  ScaleOptions scale;
  scale.stores = args.stores;
  scale.given = args.sweeps;
  scale.no_sweep = args.no_sweep;
  scale.max_sweep_events = args.max_sweep_events;
  for (const std::string& spec : args.sweep_radii)
    expand_range(spec, &scale.radii);
  scale.radii = sorted_radii(scale.radii);
  scale.threads = args.threads;
  scale.quiet = args.quiet;
  const ScaleSection radius = report_scale(runs, scale);
  const std::vector<ReportFigure> comparison = comparison_figures(runs);
  check_interrupted();
  write_file_atomically(args.output, [&](std::ostream& out) {
    write_report_html(out, runs, comparison, radius.figures, radius.sweeps, radius.scale);
  });
  std::cout << "wrote " << args.output << " (" << runs.size() << (runs.size() == 1 ? " run" : " runs");
  if (!radius.figures.empty())
    std::cout << ", " << radius.figures.size()
              << (radius.figures.size() == 1 ? " radius sweep" : " radius sweeps");
  std::cout << ")\n";
}

} // namespace

void add_report_command(CLI::App& app) {
  auto args = std::make_shared<ReportArguments>();
  CLI::App* report = app.add_subcommand("report", "Write a self-contained HTML report of one or several "
                                                  "stores: did the cells sort, when, at which scale");
  report->add_option("stores", args->stores, "HDF5 stores written by `medusa run`")->required();
  report->add_option("-o,--output", args->output, "HTML file to write")->capture_default_str();
  report
      ->add_option(
          "--sweep", args->sweeps,
          "the <prefix>.crocker.csv of a `medusa sweep` to show; a store's own sweep (<name>.crocker.csv "
          "next to <name>.h5) is shown without it, and is computed at report time when there is none")
      ->check(CLI::ExistingFile);
  report
      ->add_option("--sweep-radii", args->sweep_radii,
                   "radii A:B:STEP of the radius sweep computed at report time (default: nine radii from "
                   "half to one and a half times the first store's radius); may be repeated; sweep files "
                   "beside the stores are then not used; a periodic run leaves out, with a note on the page, "
                   "the radii with 4 x radius not below its shortest period")
      ->check(CLI::Validator([](std::string& value) { return expand_range(value, nullptr); }, "A:B:STEP"));
  report->add_flag("--no-sweep", args->no_sweep,
                   "compute no radius sweep: show only the sweeps of `medusa sweep` found or given");
  report
      ->add_option("--max-sweep-events", args->max_sweep_events,
                   "compute the default radius sweep only for runs of at most N event times (the sweep "
                   "reruns the kinetic stage at nine radii); larger runs get a note on the page instead "
                   "(0: every run)")
      ->capture_default_str();
  report->add_flag("-q,--quiet", args->quiet, "no progress on stderr");
  report
      ->add_option("--max-bars", args->max_bars,
                   "draw the N longest bars of each barcode (essential classes first; 0: all)")
      ->capture_default_str();
  report
      ->add_option("--threads", args->threads,
                   "threads for the filtrations, reductions and radius sweep (0: one per hardware thread)")
      ->capture_default_str();
  report->callback([args] { report_command(*args); });
}

} // namespace medusa::cli
