// `medusa report`: one self-contained HTML page for one or several stores: what the run was, whether and
// when each cell type's clusters merged (docs/MATH.md §6.6, §7.6), barcodes and diagrams with the CC3D
// cells behind each class, distances between the runs (docs/MATH.md §7.7), and the CROCKER plots of
// `medusa sweep` found next to the stores.
#include "atomic_file.h"
#include "commands.h"
#include "comparison.h"
#include "crocker.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "matrix_svg.h"
#include "report_html.h"
#include "report_model.h"

#include "medusa/core/error.h"
#include "medusa/persistence/clustering.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace medusa::cli {
namespace {

namespace fs = std::filesystem;

struct ReportArguments {
  std::vector<std::string> stores;
  std::vector<std::string> sweeps; // more CROCKER CSVs of `medusa sweep`
  std::string output = "report.html";
  std::size_t max_bars = 1000;
  unsigned threads = 0;
};

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// For each type of a sweep, the smallest swept radius at which K_t is one cluster at the first and at
// the last frame. Alpha complexes grow with the radius (docs/MATH.md §4.1), so b0 does not increase
// with it and the type stays one cluster at every larger radius.
std::vector<std::string> scale_lines(const std::vector<CrockerRow>& rows) {
  std::vector<std::string> types;
  double t0 = rows.front().time, t1 = rows.front().time;
  for (const CrockerRow& r : rows) {
    if (std::find(types.begin(), types.end(), r.type) == types.end())
      types.push_back(r.type);
    t0 = std::min(t0, r.time);
    t1 = std::max(t1, r.time);
  }
  std::vector<std::string> lines;
  for (const std::string& type : types) {
    if (type == "all")
      continue;
    auto smallest = [&](double t) -> std::string {
      const CrockerRow *best = nullptr, *largest = nullptr;
      for (const CrockerRow& r : rows) {
        if (r.type != type || r.time != t)
          continue;
        if (r.betti[0] == 1 && (best == nullptr || std::stod(r.radius) < std::stod(best->radius)))
          best = &r;
        if (largest == nullptr || std::stod(r.radius) > std::stod(largest->radius))
          largest = &r;
      }
      if (best != nullptr)
        return "one cluster from radius " + best->radius + " on";
      return largest == nullptr ? "not swept"
                                : "still " + std::to_string(largest->betti[0]) + " clusters at radius " +
                                      largest->radius + ", the largest swept";
    };
    lines.push_back("radius sweep, type " + type + ": at MCS " + number(t1) + " " + smallest(t1) +
                    "; at MCS " + number(t0) + " " + smallest(t0));
  }
  return lines;
}

// b0 of each type at the first and last frames against the radius, for the page's chart.
nlohmann::ordered_json sweep_json(const std::string& name, const std::vector<CrockerRow>& rows) {
  std::vector<std::string> radii, types;
  double t0 = rows.front().time, t1 = rows.front().time;
  for (const CrockerRow& r : rows) {
    if (std::find(radii.begin(), radii.end(), r.radius) == radii.end())
      radii.push_back(r.radius);
    if (std::find(types.begin(), types.end(), r.type) == types.end())
      types.push_back(r.type);
    t0 = std::min(t0, r.time);
    t1 = std::max(t1, r.time);
  }
  std::sort(radii.begin(), radii.end(),
            [](const std::string& a, const std::string& b) { return std::stod(a) < std::stod(b); });
  nlohmann::ordered_json j = {{"name", name},
                              {"t0", t0},
                              {"t_end", t1},
                              {"radii", nlohmann::ordered_json::array()},
                              {"types", nlohmann::ordered_json::array()}};
  for (const std::string& r : radii)
    j["radii"].push_back(std::stod(r));
  for (const std::string& type : types) {
    nlohmann::ordered_json first = nlohmann::ordered_json::array(), last = nlohmann::ordered_json::array();
    for (const std::string& radius : radii) {
      nlohmann::ordered_json a = nullptr, b = nullptr;
      for (const CrockerRow& r : rows)
        if (r.type == type && r.radius == radius) {
          if (r.time == t0)
            a = r.betti[0];
          if (r.time == t1)
            b = r.betti[0];
        }
      first.push_back(a);
      last.push_back(b);
    }
    j["types"].push_back({{"label", type}, {"first", first}, {"last", last}});
  }
  return j;
}

std::string stem_of(const std::string& path, const std::string& suffix) {
  const std::string name = fs::path(path).filename().string();
  return name.size() > suffix.size() ? name.substr(0, name.size() - suffix.size()) : name;
}

// The sweeps named like the stores (`medusa sweep RUN` writes <run-name>.crocker.csv, `medusa run RUN`
// <run-name>.h5, both in the working folder) and those given, each with its plot; a store's own sweep
// adds its scale lines to that run.
std::vector<ReportFigure> crocker_figures(const std::vector<std::string>& stores,
                                          const std::vector<std::string>& given, std::vector<ReportRun>& runs,
                                          nlohmann::ordered_json& sweeps) {
  // A store's own sweep first (in the stores' order), then those given with --sweep.
  std::vector<std::string> files;
  for (const std::string& store : stores) {
    const fs::path own = fs::path(store).parent_path() / (stem_of(store, ".h5") + ".crocker.csv");
    std::error_code ec;
    if (fs::is_regular_file(own, ec) && std::find(files.begin(), files.end(), own.string()) == files.end())
      files.push_back(own.string());
  }
  for (const std::string& file : given)
    if (std::find(files.begin(), files.end(), file) == files.end())
      files.push_back(file);
  std::vector<ReportFigure> figures;
  for (const std::string& file : files) {
    check_interrupted();
    const std::vector<CrockerRow> rows = read_crocker_csv(file);
    const std::string stem = stem_of(file, ".crocker.csv");
    ReportFigure f;
    f.title = "CROCKER plot of " + stem + " (" + fs::path(file).filename().string() + ")";
    f.notes = scale_lines(rows);
    std::ostringstream svg;
    write_crocker_svg(svg, rows, stem + ": Betti numbers of K_t over time and radius");
    f.svgs.push_back(svg.str());
    sweeps.push_back(sweep_json(stem, rows));
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (stem_of(stores[i], ".h5") == stem)
        for (const std::string& line : f.notes)
          runs[i].data["scale"].push_back(line);
    figures.push_back(std::move(f));
  }
  return figures;
}

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
        "Bottleneck distance between the runs' H0 diagrams (when clusters formed and merged) on "
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
  const std::vector<std::string> names = run_names(args.stores);
  const unsigned threads = worker_threads(args.threads);
  std::vector<ReportRun> runs;
  for (std::size_t i = 0; i < args.stores.size(); ++i) {
    check_interrupted();
    runs.push_back(report_run(args.stores[i], names[i], args.max_bars, threads));
  }
  nlohmann::ordered_json sweeps = nlohmann::ordered_json::array();
  const std::vector<ReportFigure> crocker = crocker_figures(args.stores, args.sweeps, runs, sweeps);
  const std::vector<ReportFigure> comparison = comparison_figures(runs);
  check_interrupted();
  write_file_atomically(
      args.output, [&](std::ostream& out) { write_report_html(out, runs, comparison, crocker, sweeps); });
  std::cout << "wrote " << args.output << " (" << runs.size() << (runs.size() == 1 ? " run" : " runs");
  if (!crocker.empty())
    std::cout << ", " << crocker.size() << (crocker.size() == 1 ? " radius sweep" : " radius sweeps");
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
          "next to <name>.h5) is shown without it")
      ->check(CLI::ExistingFile);
  report
      ->add_option("--max-bars", args->max_bars,
                   "draw the N longest bars of each barcode (essential classes first; 0: all)")
      ->capture_default_str();
  report
      ->add_option("--threads", args->threads,
                   "threads for the filtrations and reductions (0: one per hardware thread)")
      ->capture_default_str();
  report->callback([args] { report_command(*args); });
}

} // namespace medusa::cli
