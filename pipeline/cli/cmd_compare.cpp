// `medusa compare`: pairwise distances between the diagrams of several runs on the normalised time
// axis (docs/MATH.md §7.7), average-linkage clustering, and their CSV/SVG exports.
#include "atomic_file.h"
#include "cell_type.h"
#include "commands.h"
#include "comparison.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "matrix_svg.h"

#include "medusa/core/error.h"
#include "medusa/persistence/clustering.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace medusa::cli {
namespace {

struct CompareArguments {
  std::vector<std::string> stores;
  std::string metric = "bottleneck";
  ComparisonSelection selection;
  bool type_given = false, dim_given = false; // either: one comparison; neither: every type, H0-H2
  bool ignore_essential = false;              // accepted for scripts; finite parts are the default
  bool essential = false;
  std::string prefix = "compare";
};

// One comparison: a cell type, a homology degree and its distance matrix.
struct Comparison {
  ComparisonSelection selection;
  std::vector<persistence::PointDiagram> points;
  persistence::DistanceMatrix distances;
  persistence::Dendrogram dendrogram;
};

std::string what_of(const ComparisonSelection& s) {
  return "type " + s.type + ", H" + std::to_string(s.dim) + ", " + s.filtration + " filtration";
}

// The classes of a homology degree in words: clusters, loops, cavities (docs/MATH.md §7.6).
std::string degree_words(int dim) {
  switch (dim) {
  case 0: return "clusters (H0)";
  case 1: return "loops (H1)";
  case 2: return "cavities (H2)";
  default: return "classes of degree " + std::to_string(dim) + " (H" + std::to_string(dim) + ")";
  }
}

// A comparison for the terminal: "type 1 loops (H1)", "all cells' clusters (H0)".
std::string words_of(const ComparisonSelection& s) {
  return (s.type == "all" ? std::string("all cells' ") : "type " + s.type + " ") + degree_words(s.dim);
}

// "bottleneck distance between their persistence diagrams (essential classes ignored)".
std::string metric_words(const ComparisonMetric& metric) {
  const std::string d = metric.description();
  const std::size_t paren = std::min(d.find(" ("), d.size());
  return d.substr(0, paren) + " distance between their persistence diagrams" + d.substr(paren);
}

// The filtration in words (docs/MATH.md §7.2, §7.3).
std::string direction_words(const std::string& filtration) {
  return filtration == "forward" ? "time running forward (forward filtration)"
                                 : "time running backward from the end (reverse filtration)";
}

// Largest and smallest distance between two different runs.
std::pair<double, double> off_diagonal_range(const persistence::DistanceMatrix& d) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < d.size; ++i)
    for (std::size_t j = i + 1; j < d.size; ++j) {
      lo = std::min(lo, d.at(i, j));
      hi = std::max(hi, d.at(i, j));
    }
  return {lo, hi};
}

// All distances zero because no diagram has a point to compare: nothing separates the runs.
bool trivially_zero(const Comparison& c, bool essential) {
  for (const persistence::PointDiagram& p : c.points)
    if (!p.finite.empty() || (essential && !p.essential.empty()))
      return false;
  return true;
}

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

void write_outputs(const Comparison& c, const std::vector<std::string>& names, const std::string& prefix,
                   const std::string& metric_text) {
  const std::string title = what_of(c.selection) + ", " + metric_text + ", normalised time";
  const std::string csv = prefix + ".distances.csv", heatmap = prefix + ".heatmap.svg",
                    dendrogram_svg = prefix + ".dendrogram.svg";
  write_file_atomically(csv, [&](std::ostream& out) { write_matrix_csv(out, c.distances, names); });
  write_file_atomically(heatmap,
                        [&](std::ostream& out) { write_heatmap_svg(out, c.distances, names, title); });
  write_file_atomically(dendrogram_svg,
                        [&](std::ostream& out) { write_dendrogram_svg(out, c.dendrogram, names, title); });
}

void print_clustering(std::ostream& out, const persistence::Dendrogram& dendrogram,
                      const std::vector<std::string>& names, const std::string& indent) {
  for (const persistence::Merge& m : dendrogram.merges)
    out << indent << cluster_name(m.first, dendrogram, names) << " + "
        << cluster_name(m.second, dendrogram, names) << " at " << short_number(m.height) << "\n";
}

void compare_command(const CompareArguments& args) {
  if (args.stores.size() < 2)
    throw InputError("medusa compare needs at least two stores, got " + std::to_string(args.stores.size()));
  if (args.essential && args.ignore_essential)
    throw CLI::ParseError("--essential and --ignore-essential exclude each other", 2);
  const ComparisonMetric metric(args.metric, !args.essential);
  check_output_prefix(args.prefix, args.prefix + ".distances.csv");
  const std::vector<std::string> names = run_names(args.stores);
  const bool single = args.type_given || args.dim_given;

  // Each run's cells and radius first: a type the runs lack is refused before anything is printed.
  std::vector<RunFacts> runs;
  for (const std::string& store : args.stores) {
    check_interrupted();
    runs.push_back(read_run_facts(store));
  }
  // What to compare: the one (type, degree) asked for, or every cell type of the runs in H0-H2.
  std::vector<ComparisonSelection> selections;
  if (single) {
    for (std::size_t i = 0; i < runs.size(); ++i)
      resolve_cell_type(args.selection.type, runs[i].input, args.stores[i]);
    selections.push_back(args.selection);
  } else {
    std::vector<int> types = cell_types(runs.front().input);
    for (std::size_t i = 1; i < runs.size(); ++i) {
      const std::vector<int> other = cell_types(runs[i].input);
      std::vector<int> common;
      std::set_intersection(types.begin(), types.end(), other.begin(), other.end(),
                            std::back_inserter(common));
      types = common;
    }
    if (types.empty())
      throw InputError("medusa compare: the runs share no cell type; compare them with --type all");
    for (int type : types)
      for (int k = 0; k <= 2; ++k) {
        ComparisonSelection s = args.selection;
        s.type = std::to_string(type);
        s.dim = k;
        selections.push_back(s);
      }
  }
  std::vector<Comparison> comparisons(selections.size());
  for (std::size_t c = 0; c < selections.size(); ++c)
    comparisons[c].selection = selections[c];

  std::cout << "comparing " << args.stores.size() << " runs: "
            << (single ? words_of(selections.front())
                       : "clusters, loops and cavities (H0, H1, H2) of each cell type")
            << ", " << direction_words(args.selection.filtration) << "; " << metric_words(metric)
            << "; each run's time rescaled to 0..1, t -> (t - t0) / (t_end - t0)\n"
            << "classes: finite = ended (a cluster joined another, a loop or cavity was filled), essential = "
               "never ended\n";
  std::vector<int> dimensions;
  for (std::size_t i = 0; i < args.stores.size(); ++i) {
    check_interrupted();
    std::vector<ComparedDiagram> d = compared_diagrams(args.stores[i], selections);
    dimensions.push_back(d.front().dimension);
    std::cout << "  " << names[i] << ": MCS " << short_number(d.front().t0) << " to "
              << short_number(d.front().t_end) << ", radius " << runs[i].radius;
    for (std::size_t c = 0; c < d.size(); ++c) {
      if (!single)
        std::cout << (c % 3 == 0
                          ? "\n    " + cell_type_title(runs[i].input, std::stoi(selections[c].type)) + ":"
                          : ",")
                  << " " << degree_words(selections[c].dim);
      const std::size_t finite = d[c].points.finite.size(), essential = d[c].points.essential.size();
      std::cout << (single ? ", " : " ") << finite << " finite" << (single ? ", " : " + ") << essential
                << " essential";
      comparisons[c].points.push_back(std::move(d[c].points));
    }
    std::cout << "\n";
  }
  for (Comparison& c : comparisons) {
    check_interrupted();
    c.distances = persistence::distance_matrix(
        c.points,
        [&metric](const auto& a, const auto& b) {
          // Both workers poll before each pair, so an interrupt stops the whole matrix at the next pair.
          check_interrupted();
          return metric(a, b);
        },
        2);
    c.dendrogram = persistence::average_linkage(c.distances);
  }
  check_interrupted();

  std::vector<std::string> warnings = comparability_warnings(names, runs, selections);
  if (const std::string mixed = mixed_dimensions_note(names, dimensions); !mixed.empty())
    warnings.push_back(mixed);
  for (const Comparison& c : comparisons)
    if (trivially_zero(c, args.essential))
      warnings.push_back("every distance of " + words_of(c.selection) + " is 0: no run has a " +
                         (args.essential ? "class" : "class that ended") + " there (" +
                         (c.selection.dim == 0 && c.selection.type == "all"
                              ? "the whole tissue is one cluster throughout"
                              : "every diagram is empty") +
                         "), so it cannot separate the runs");

  if (single) {
    const Comparison& c = comparisons.front();
    std::cout << "distances (" << metric.reading() << "):\n";
    print_matrix(std::cout, c.distances, names);
    if (metric.largest_relative_error() > 0)
      std::cout << "some finite parts are certified approximations within a relative error of "
                << short_number(metric.largest_relative_error()) << "\n";
    std::cout << "runs grouped by distance, closest first (average linkage):\n";
    print_clustering(std::cout, c.dendrogram, names, "  ");
    write_outputs(c, names, args.prefix, metric.description());
    std::cout << "wrote " << args.prefix << ".distances.csv, " << args.prefix << ".heatmap.svg, "
              << args.prefix << ".dendrogram.svg\n";
  } else {
    // Which comparisons separate the runs: the spread of the distances between different runs (the
    // largest over the smallest), highest first, with the clustering it gives.
    std::vector<std::size_t> order(comparisons.size());
    for (std::size_t c = 0; c < order.size(); ++c)
      order[c] = c;
    const auto spread = [&](std::size_t c) {
      const auto [lo, hi] = off_diagonal_range(comparisons[c].distances);
      return hi == 0 ? 0.0 : lo == 0 ? std::numeric_limits<double>::infinity() : hi / lo;
    };
    // Two runs have one distance per comparison, which has no spread and no grouping: the largest first.
    const bool pair = names.size() == 2;
    const auto largest = [&](std::size_t c) { return off_diagonal_range(comparisons[c].distances).second; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pair ? largest(a) > largest(b) : spread(a) > spread(b);
    });
    std::cout << "distances: " << metric.reading() << "\n";
    if (pair) {
      std::cout << "the distance between the two runs, largest first (the comparisons that separate them "
                   "most):\n";
      for (std::size_t c : order)
        std::cout << "  " << words_of(comparisons[c].selection) << ": " << short_number(largest(c)) << "\n";
    } else {
      std::cout
          << "which comparisons separate the runs (distances between different runs: smallest, largest, "
             "and their ratio; highest ratio first, then the runs grouped by distance):\n";
      for (std::size_t c : order) {
        const Comparison& x = comparisons[c];
        const auto [lo, hi] = off_diagonal_range(x.distances);
        std::cout << "  " << words_of(x.selection) << ": " << short_number(lo) << " to " << short_number(hi)
                  << ", ratio " << (hi == 0 ? std::string("-") : short_number(spread(c)));
        if (hi > 0 && !x.dendrogram.merges.empty()) {
          std::cout << "; grouped:";
          std::string sep = " ";
          for (const persistence::Merge& m : x.dendrogram.merges) {
            std::cout << sep << cluster_name(m.first, x.dendrogram, names) << " + "
                      << cluster_name(m.second, x.dendrogram, names) << " at " << short_number(m.height);
            sep = "; ";
          }
        }
        std::cout << "\n";
      }
    }
    std::string written;
    for (const Comparison& c : comparisons) {
      const std::string prefix =
          args.prefix + ".type" + c.selection.type + ".h" + std::to_string(c.selection.dim);
      write_outputs(c, names, prefix, metric.description());
      written += (written.empty() ? "" : ", ") + prefix + ".*";
    }
    std::cout << "wrote " << written << " (distances.csv, heatmap.svg, dendrogram.svg each)\n";
  }
  // A distance says how far apart two runs' classes are, not which run sorted.
  std::cout << "whether and when each run sorts: medusa report";
  for (const std::string& store : args.stores)
    std::cout << " " << store;
  std::cout << "\n";
  for (const std::string& w : warnings)
    std::cerr << "medusa: warning: " << w << "\n";
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
  CLI::Option* type =
      compare
          ->add_option("--type", args->selection.type,
                       "compare the sub-medusa of this cell type, by id or name as `medusa info` lists them "
                       "(docs/MATH.md §7.4), or 'all' for the whole medusa (default without --type and "
                       "--dim: every cell type of the runs, in H0, H1 and H2)")
          ->check(type_validator());
  CLI::Option* dim = compare
                         ->add_option("--dim", args->selection.dim,
                                      "compare this homology degree only (with --type alone: 0; --dim alone: "
                                      "type all)")
                         ->check(CLI::Range(0, 3));
  compare
      ->add_option("--filtration", args->selection.filtration, "forward or reverse (docs/MATH.md §7.2, §7.3)")
      ->check(CLI::IsMember({"forward", "reverse"}))
      ->capture_default_str();
  compare->add_flag(
      "--essential", args->essential,
      "compare the essential classes too (different essential counts give inf); by default only "
      "the finite parts are compared");
  compare->add_flag("--ignore-essential", args->ignore_essential,
                    "compare the finite parts only (the default)");
  compare
      ->add_option(
          "-o,--output", args->prefix,
          "output prefix: writes <prefix>.distances.csv, <prefix>.heatmap.svg, <prefix>.dendrogram.svg for "
          "one comparison, <prefix>.type<T>.h<k>.* for each of several")
      ->capture_default_str();
  compare->callback([args, type, dim] {
    args->type_given = type->count() > 0;
    args->dim_given = dim->count() > 0;
    compare_command(*args);
  });
}

} // namespace medusa::cli
