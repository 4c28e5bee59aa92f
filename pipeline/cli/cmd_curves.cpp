// `medusa curves`: simplex counts, Euler characteristic and Betti numbers of the time slices K_t
// (docs/MATH.md §6.6, §6.8), for the whole complex and for each cell type's subcomplex (7.4), and the
// classical sorting measures of the same slices (§6.9), as CSV and SVG.
#include "atomic_file.h"
#include "betti_frames.h"
#include "cell_type.h"
#include "commands.h"
#include "curve_plot.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "sorting_export.h"

#include "medusa/medusa/signatures.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/slice_signatures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace medusa::cli {
namespace {

struct CurvesArguments {
  std::string store;
  std::string prefix;
  bool frames_only = false;
  std::string method = "reduction";
};

struct TypeCurves {
  std::string label; // "all" or the type id
  std::vector<medusa::SignatureSample> samples;
};

std::string store_stem(const std::string& store) {
  const std::string suffix = ".h5";
  if (store.size() > suffix.size() && store.compare(store.size() - suffix.size(), suffix.size(), suffix) == 0)
    return store.substr(0, store.size() - suffix.size());
  return store;
}

void write_curves_csv(std::ostream& out, const std::vector<TypeCurves>& all, const TypeNames& names) {
  out << "time,type,f0,f1,f2,f3,euler,b0,b1,b2,type_name\n";
  // Every type has the same sample times: format them once.
  std::vector<std::string> times;
  if (!all.empty())
    for (const medusa::SignatureSample& s : all.front().samples)
      times.push_back(format_time(s.time));
  for (const TypeCurves& c : all) {
    const std::string name = csv_field(type_label_name(names, c.label));
    for (std::size_t i = 0; i < c.samples.size(); ++i) {
      if (i % 4096 == 0)
        check_interrupted();
      const medusa::SignatureSample& s = c.samples[i];
      const medusa::Signature& g = s.signature;
      out << (i < times.size() && s.time == all.front().samples[i].time ? times[i] : format_time(s.time))
          << ',' << c.label << ',' << g.f[0] << ',' << g.f[1] << ',' << g.f[2] << ',' << g.f[3] << ','
          << g.euler << ',' << g.betti[0] << ',' << g.betti[1] << ',' << g.betti[2] << ',' << name << '\n';
    }
  }
}

std::vector<CurvePanel> panels_of(const std::vector<TypeCurves>& all, const TypeNames& names) {
  std::vector<CurvePanel> panels;
  for (const TypeCurves& c : all) {
    const std::string title = type_label_title(names, c.label);
    CurvePanel betti{title + ": Betti numbers of K_t", {}};
    CurvePanel counts{title + ": simplices of K_t", {}};
    for (int k = 0; k <= 3; ++k) {
      Curve b{"b" + std::to_string(k), {}, {}}, f{"f" + std::to_string(k), {}, {}};
      for (const medusa::SignatureSample& s : c.samples) {
        b.times.push_back(s.time);
        b.values.push_back(static_cast<double>(s.signature.betti[static_cast<std::size_t>(k)]));
        f.times.push_back(s.time);
        f.values.push_back(static_cast<double>(s.signature.f[static_cast<std::size_t>(k)]));
      }
      if (k < 3)
        betti.curves.push_back(std::move(b));
      counts.curves.push_back(std::move(f));
    }
    panels.push_back(std::move(betti));
    panels.push_back(std::move(counts));
  }
  return panels;
}

// One sample in words: the cells and their contacts, then the Betti numbers as clusters, loops and
// cavities (docs/MATH.md §6.6, §7.6).
void describe(std::ostream& out, const medusa::SignatureSample& s) {
  const medusa::Signature& g = s.signature;
  out << "MCS " << format_time(s.time) << ": " << g.f[0] << " cells, " << g.f[1] << " contacts, " << g.f[2]
      << " triangles, " << g.f[3] << " tetrahedra; " << g.betti[0]
      << (g.betti[0] == 1 ? " cluster, " : " clusters, ") << g.betti[1]
      << (g.betti[1] == 1 ? " loop, " : " loops, ") << g.betti[2]
      << (g.betti[2] == 1 ? " cavity" : " cavities");
}

// The first slice a user compares: just after the first frame, the last sample at its time (cells
// present at t_0 alone leave in a batch of that same time, docs/MATH.md §2.4), as `--frames-only`,
// `medusa run` and the report count it.
template <class Sample> const Sample& just_after_first(const std::vector<Sample>& samples) {
  std::size_t k = 0;
  while (k + 1 < samples.size() && samples[k + 1].time == samples.front().time)
    ++k;
  return samples[k];
}

void curves_command(const CurvesArguments& args) {
  const std::string prefix = args.prefix.empty() ? store_stem(args.store) : args.prefix;
  check_output_prefix(prefix, prefix + ".curves.csv");
  const medusa::Medusa medusa = medusa::read_store(args.store);
  check_interrupted();
  std::vector<TypeCurves> all;
  std::vector<std::optional<int>> types{std::nullopt};
  for (int t : distinct_types(vertex_types(medusa)))
    types.emplace_back(t);
  for (const std::optional<int>& type : types) {
    check_interrupted();
    std::vector<medusa::SignatureSample> samples;
    if (args.method == "reference") {
      const medusa::ComplexIndex index(medusa, type);
      samples = medusa::signatures_over_time(index);
    } else {
      samples = persistence::signatures_by_reduction(medusa, type, check_interrupted);
    }
    if (args.frames_only)
      samples = frame_samples(samples, medusa.input);
    all.push_back({type ? std::to_string(*type) : "all", std::move(samples)});
  }
  check_interrupted();
  std::vector<medusa::SortingSample> sorting = medusa::sorting_over_time(medusa, check_interrupted);
  if (args.frames_only)
    sorting = frame_samples(sorting, medusa.input);
  check_interrupted();

  // The complex K_t of touching cells (docs/MATH.md §4.1), with its Betti numbers b0, b1, b2 in words.
  if (args.frames_only)
    std::cout << "the cells in contact (the complex K_t) at each of " << medusa.input.frames() << " frames";
  else
    std::cout << "the cells in contact (the complex K_t) after each of " << medusa.batches.size()
              << " event batches and at the end";
  std::cout << "; clusters, loops and cavities are its Betti numbers b0, b1, b2 (the columns of the CSV); "
               "first and last:\n";
  for (const TypeCurves& c : all) {
    // A type's contacts are those among its own cells (its subcomplex, docs/MATH.md §7.4).
    std::cout << type_label_title(medusa.input.type_names, c.label)
              << (c.label == "all" ? "" : ", among its cells") << ":\n  ";
    describe(std::cout, just_after_first(c.samples));
    std::cout << "\n  ";
    describe(std::cout, c.samples.back());
    std::cout << "\n";
  }
  const double t0 =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.front());
  const double t_end =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.back());
  const std::string csv = prefix + ".curves.csv", svg = prefix + ".curves.svg";
  const std::string sorting_csv = prefix + ".sorting.csv", sorting_svg = prefix + ".sorting.svg";
  std::cout
      << "sorting measures, MCS " << format_time(sorting.front().time) << " -> MCS "
      << format_time(sorting.back().time)
      << " (fraction of contacts between cells of different types; mean fraction of a cell's neighbours "
         "of its own type; clusters and the largest one's cells; README):\n";
  const medusa::SortingSample& first = just_after_first(sorting);
  for (std::size_t g = 0; g < first.measures.size(); ++g) {
    const medusa::SortingMeasures &a = first.measures[g], &b = sorting.back().measures[g];
    std::cout << "  " << (a.type ? cell_type_title(medusa.input, *a.type) : std::string("all cells")) << ": "
              << contact_fractions(a, b, " -> ") << ", clusters " << a.clusters << " -> " << b.clusters
              << ", largest cluster " << a.largest_cluster << " -> " << b.largest_cluster << " cells\n";
  }
  // All four files or none: an interrupt between two writes removes those already written.
  std::vector<std::string> written;
  try {
    write_file_atomically(csv,
                          [&](std::ostream& out) { write_curves_csv(out, all, medusa.input.type_names); });
    written.push_back(csv);
    write_file_atomically(svg, [&](std::ostream& out) {
      write_curves_svg(out, panels_of(all, medusa.input.type_names), t0, t_end);
    });
    written.push_back(svg);
    check_interrupted();
    write_file_atomically(
        sorting_csv, [&](std::ostream& out) { write_sorting_csv(out, sorting, medusa.input.type_names); });
    written.push_back(sorting_csv);
    write_file_atomically(sorting_svg, [&](std::ostream& out) {
      write_curves_svg(out, sorting_panels(sorting, t0, t_end, medusa.input.type_names), t0, t_end);
    });
    written.push_back(sorting_svg);
    check_interrupted();
  } catch (...) {
    for (const std::string& path : written)
      std::remove(path.c_str());
    throw;
  }
  std::cout << "wrote " << csv << ", " << svg << ", " << sorting_csv << ", " << sorting_svg << "\n";
}

} // namespace

void add_curves_command(CLI::App& app) {
  auto args = std::make_shared<CurvesArguments>();
  CLI::App* curves = app.add_subcommand(
      "curves", "Simplex counts, Euler characteristic, Betti numbers and sorting measures of K_t over time "
                "(CSV and SVG)");
  curves->add_option("store", args->store, "HDF5 store written by `medusa run`")->required();
  curves->add_option(
      "-o,--output", args->prefix,
      "output prefix: writes <prefix>.curves.csv (time,type,f0,f1,f2,f3,euler,b0,b1,b2,type_name), "
      "<prefix>.curves.svg, <prefix>.sorting.csv (heterotypic contacts, same-type neighbour "
      "fractions and clusters per type; README) and <prefix>.sorting.svg (default: the store "
      "name without .h5)");
  curves->add_flag(
      "--frames-only", args->frames_only,
      "one row per input frame (the state reported at the frame, docs/MATH.md §6.6) instead of one per "
      "event batch");
  // Not in the help: the per-batch recomputation of docs/MATH.md §6.6, kept as the oracle of the
  // single-reduction method of §6.8.
  curves->add_option("--method", args->method, "")
      ->check(CLI::IsMember({"reduction", "reference"}))
      ->group("");
  curves->callback([args] { curves_command(*args); });
}

} // namespace medusa::cli
