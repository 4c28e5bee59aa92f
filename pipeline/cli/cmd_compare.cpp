// `medusa compare`: pairwise distances between the diagrams of several runs on the normalised time
// axis (docs/MATH.md §7.7), average-linkage clustering, and their CSV/SVG exports.
#include "atomic_file.h"
#include "commands.h"
#include "comparison.h"
#include "diagram_export.h"
#include "interrupt.h"
#include "matrix_svg.h"

#include "medusa/core/error.h"
#include "medusa/persistence/clustering.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace medusa::cli {
namespace {

struct CompareArguments {
  std::vector<std::string> stores;
  std::string metric = "bottleneck";
  ComparisonSelection selection;
  bool ignore_essential = false;
  std::string prefix = "compare";
};

std::string short_number(double d) {
  if (std::isinf(d))
    return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", d);
  return buffer;
}

// A cluster of the dendrogram in words: a run name, or {a, b, ...}.
std::string cluster_name(std::size_t cluster, const persistence::Dendrogram& dendrogram,
                         const std::vector<std::string>& names) {
  if (cluster < dendrogram.leaves)
    return names[cluster];
  const persistence::Merge& m = dendrogram.merges[cluster - dendrogram.leaves];
  std::string inner =
      cluster_name(m.first, dendrogram, names) + ", " + cluster_name(m.second, dendrogram, names);
  if (inner.front() == '{')
    inner.erase(0, 1);
  return "{" + inner + "}";
}

void write_matrix_csv(std::ostream& out, const persistence::DistanceMatrix& d,
                      const std::vector<std::string>& names) {
  out << "run";
  for (const std::string& name : names)
    out << ',' << name;
  out << '\n';
  for (std::size_t i = 0; i < d.size; ++i) {
    out << names[i];
    for (std::size_t j = 0; j < d.size; ++j)
      out << ',' << format_time(d.at(i, j));
    out << '\n';
  }
}

void print_matrix(std::ostream& out, const persistence::DistanceMatrix& d,
                  const std::vector<std::string>& names) {
  std::size_t width = 8;
  for (const std::string& name : names)
    width = std::max(width, name.size() + 2);
  auto pad = [width](const std::string& s) {
    return s + std::string(width > s.size() ? width - s.size() : 1, ' ');
  };
  out << pad("");
  for (const std::string& name : names)
    out << pad(name);
  out << '\n';
  for (std::size_t i = 0; i < d.size; ++i) {
    out << pad(names[i]);
    for (std::size_t j = 0; j < d.size; ++j)
      out << pad(short_number(d.at(i, j)));
    out << '\n';
  }
}

void compare_command(const CompareArguments& args) {
  if (args.stores.size() < 2)
    throw InputError("medusa compare needs at least two stores, got " + std::to_string(args.stores.size()));
  const ComparisonMetric metric(args.metric, args.ignore_essential);
  const std::vector<std::string> names = run_names(args.stores);
  std::vector<persistence::PointDiagram> points;
  const std::string what = "type " + args.selection.type + ", H" + std::to_string(args.selection.dim) + ", " +
                           args.selection.filtration + " filtration";
  std::cout << "comparing " << args.stores.size() << " runs: " << what << ", " << metric.description()
            << ", time normalised t -> (t - t0) / (t_end - t0)\n";
  for (std::size_t i = 0; i < args.stores.size(); ++i) {
    check_interrupted();
    ComparedDiagram d = compared_diagram(args.stores[i], args.selection);
    std::cout << "  " << names[i] << ": MCS " << short_number(d.t0) << " to " << short_number(d.t_end) << ", "
              << d.points.finite.size() << " finite points, " << d.points.essential.size()
              << " essential classes\n";
    points.push_back(std::move(d.points));
  }
  check_interrupted();
  const persistence::DistanceMatrix distances = persistence::distance_matrix(
      points, [&metric](const auto& a, const auto& b) { return metric(a, b); }, 2);
  check_interrupted();
  const persistence::Dendrogram dendrogram = persistence::average_linkage(distances);

  std::cout << "distances:\n";
  print_matrix(std::cout, distances, names);
  if (metric.largest_relative_error() > 0)
    std::cout << "some finite parts are certified approximations within a relative error of "
              << short_number(metric.largest_relative_error()) << "\n";
  std::cout << "average-linkage clustering:\n";
  for (std::size_t k = 0; k < dendrogram.merges.size(); ++k) {
    const persistence::Merge& m = dendrogram.merges[k];
    std::cout << "  " << cluster_name(m.first, dendrogram, names) << " + "
              << cluster_name(m.second, dendrogram, names) << " at " << short_number(m.height) << "\n";
  }

  const std::string title = what + ", " + metric.description() + ", normalised time";
  const std::string csv = args.prefix + ".distances.csv", heatmap = args.prefix + ".heatmap.svg",
                    dendrogram_svg = args.prefix + ".dendrogram.svg";
  write_file_atomically(csv, [&](std::ostream& out) { write_matrix_csv(out, distances, names); });
  write_file_atomically(heatmap, [&](std::ostream& out) { write_heatmap_svg(out, distances, names, title); });
  write_file_atomically(dendrogram_svg,
                        [&](std::ostream& out) { write_dendrogram_svg(out, dendrogram, names, title); });
  std::cout << "wrote " << csv << ", " << heatmap << ", " << dendrogram_svg << "\n";
}

} // namespace

void add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArguments>();
  CLI::App* compare = app.add_subcommand(
      "compare", "Distances between the persistence diagrams of several runs, with a clustering");
  compare->add_option("stores", args->stores, "HDF5 stores written by `medusa run` (two or more)")
      ->required()
      ->expected(2, CLI::detail::expected_max_vector_size);
  compare
      ->add_option(
          "--metric", args->metric,
          "bottleneck, or wasserstein:p for W_p with p >= 1 (ground metric L-infinity, docs/MATH.md §7.7)")
      ->check(CLI::Validator([](std::string& value) { return metric_spec_error(value); }, "METRIC"))
      ->capture_default_str();
  compare
      ->add_option("--type", args->selection.type,
                   "the sub-medusa of this cell type id (docs/MATH.md §7.4), or 'all' for the whole medusa")
      ->check(CLI::Validator(
          [](std::string& value) {
            return value == "all" || (!value.empty() && value.size() < 10 &&
                                      value.find_first_not_of("0123456789") == std::string::npos)
                       ? std::string()
                       : "'" + value + "' is not a type id or 'all'";
          },
          "TYPE"))
      ->capture_default_str();
  compare->add_option("--dim", args->selection.dim, "homology degree")
      ->check(CLI::Range(0, 3))
      ->capture_default_str();
  compare
      ->add_option("--filtration", args->selection.filtration, "forward or reverse (docs/MATH.md §7.2, §7.3)")
      ->check(CLI::IsMember({"forward", "reverse"}))
      ->capture_default_str();
  compare->add_flag("--ignore-essential", args->ignore_essential,
                    "compare the finite parts only (otherwise different essential counts give inf)");
  compare
      ->add_option(
          "-o,--output", args->prefix,
          "output prefix: writes <prefix>.distances.csv, <prefix>.heatmap.svg, <prefix>.dendrogram.svg")
      ->capture_default_str();
  compare->callback([args] { compare_command(*args); });
}

} // namespace medusa::cli
