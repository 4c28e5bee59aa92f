#include "report_model.h"

#include "betti_frames.h"
#include "cell_type.h"
#include "class_fates.h"
#include "clusters_apart.h"
#include "comparison.h"
#include "diagram_export.h"
#include "diagram_selection.h"
#include "forward_counts.h"
#include "interrupt.h"
#include "recorded_domain.h"
#include "report_answer.h"
#include "report_classes.h"
#include "ring_fate.h"
#include "run_summary.h"
#include "sorting_export.h"
#include "wrapping_summary.h"

#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/sorting_measures.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace medusa::cli {
namespace {

using json = nlohmann::ordered_json;

std::string mcs(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

std::string type_name(const kinetic::Trajectories& input, int type) {
  if (type == persistence::all_types)
    return "all cells";
  return cell_type_name(input, type);
}

json cc3d_ids(const medusa::CellVertices& vertices, const kinetic::Trajectories& input) {
  json ids = json::array();
  for (const kinetic::VertexId v : vertices)
    ids.push_back(input.cells.at(static_cast<std::size_t>(v)).cell_id);
  return ids;
}

// One panel: the pairs of degree k of a forward diagram, each
// [birth, death or null, birth cell, death cell or null, birth CC3D ids, death CC3D ids], and for an
// essential loop or cavity (not a planar run's space-time bubble) a seventh: the time until which the ring or
// shell of cells it is listed with was whole (t_end when it still is), or null when it never was at one time.
// `seen`: per birth cell the time seen in the tissue (time_seen); a panel cut to max_bars keeps those seen
// longest, as the tables, and leaves out all its loops or cavities never whole at one time
// (never_whole_left) rather than some.
json panel(const persistence::Diagram& d, int k, std::size_t max_bars, const medusa::Medusa& medusa,
           const std::map<medusa::CellId, double>& seen) {
  std::vector<const persistence::PersistencePair*> pairs;
  for (const persistence::PersistencePair& p : d.pairs)
    if (p.dim == k && !p.zero_length)
      pairs.push_back(&p);
  const auto seen_of = [&](const persistence::PersistencePair* p) {
    const auto it = seen.find(p->birth_cell);
    if (it == seen.end())
      throw InternalError("report: no class for the pair born in medusa cell " +
                          std::to_string(p->birth_cell));
    return it->second;
  };
  const std::size_t total = pairs.size();
  std::size_t never_whole_left = 0;
  if (max_bars > 0 && pairs.size() > max_bars) {
    const auto lifetime = [](const persistence::PersistencePair* p) {
      return p->essential ? INFINITY : p->death - p->birth;
    };
    std::stable_sort(pairs.begin(), pairs.end(), [&](const auto* a, const auto* b) {
      return seen_of(a) != seen_of(b) ? seen_of(a) > seen_of(b) : lifetime(a) > lifetime(b);
    });
    // Loops and cavities never whole at one time all tie last; a few of them, the earliest born, would
    // draw a trend that is not there, so they are drawn all or none (a planar run's bubbles aside).
    const auto whole_at_some_time = [&](const auto* p) { return !never_whole(seen_of(p)); };
    const auto first_never_whole = std::find_if_not(pairs.begin(), pairs.end(), whole_at_some_time);
    const auto kept = static_cast<std::size_t>(first_never_whole - pairs.begin());
    if (k >= 1 && k < medusa.input.dimension && kept < max_bars) {
      never_whole_left = pairs.size() - kept;
      pairs.resize(kept);
    } else {
      pairs.resize(max_bars);
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto* a, const auto* b) {
    return std::make_pair(a->birth, a->essential ? INFINITY : a->death) <
           std::make_pair(b->birth, b->essential ? INFINITY : b->death);
  });
  json rows = json::array();
  for (const persistence::PersistencePair* p : pairs) {
    json row = json::array();
    row.push_back(p->birth);
    row.push_back(p->essential ? json(nullptr) : json(p->death));
    row.push_back(p->birth_cell);
    row.push_back(p->essential ? json(nullptr) : json(p->death_cell));
    row.push_back(cc3d_ids(persistence::birth_vertices(*p, medusa.cells), medusa.input));
    row.push_back(p->essential ? json::array()
                               : cc3d_ids(persistence::death_vertices(*p, medusa.cells), medusa.input));
    // A planar run's H2 classes are bubbles of space-time (docs/MATH.md §7.6), never a shell at one time.
    if (p->essential && k >= 1 && k < medusa.input.dimension) {
      const double s = seen_of(p);
      row.push_back(never_whole(s) ? json(nullptr) : json(p->birth + s));
    }
    rows.push_back(std::move(row));
  }
  return {{"label", type_label(d.cell_type)},
          {"name", type_name(medusa.input, d.cell_type)},
          {"dim", k},
          {"total", total},
          {"never_whole_left", never_whole_left},
          {"pairs", std::move(rows)}};
}

json facts(const medusa::Medusa& medusa, const std::string& store) {
  const kinetic::Trajectories& input = medusa.input;
  std::set<std::int64_t> cc3d;
  std::map<int, std::set<std::int64_t>> per_type;
  for (const kinetic::Trajectory& t : input.cells) {
    cc3d.insert(t.cell_id);
    per_type[t.type].insert(t.cell_id);
  }
  json types = json::array();
  for (const auto& [type, ids] : per_type)
    types.push_back({{"id", type}, {"name", type_name(input, type)}, {"cells", ids.size()}});
  json cells_per_dim = json::array();
  for (int k = 0; k <= input.dimension + 1; ++k)
    cells_per_dim.push_back(medusa.cells_of_dimension(k).size());
  return {{"store", store},
          {"cc3d_cells", cc3d.size()},
          {"trajectories", input.cells.size()},
          {"types", std::move(types)},
          {"frames", input.frames()},
          {"t0", input.frame_times.front()},
          {"t_end", input.frame_times.back()},
          {"dimension", input.dimension},
          {"domain", periodic_domain_text(medusa.run, input.scale)},
          {"radius", medusa.run.radius_text.empty() ? mcs(medusa.run.radius) : medusa.run.radius_text},
          {"source_files", medusa.run.source_files},
          {"input_warnings", medusa.run.input_warnings},
          {"software_version", medusa.run.software_version},
          {"command_line", medusa.run.command_line},
          {"medusa_cells_per_dimension", std::move(cells_per_dim)}};
}

} // namespace

ReportRun report_run(const std::string& store, const std::string& name, std::size_t max_bars,
                     unsigned threads) {
  const medusa::Medusa medusa = medusa::read_store(store);
  const kinetic::Trajectories& input = medusa.input;
  if (input.frames() < 2)
    throw InputError("store " + store + " has fewer than two frames; there is nothing to report over time");
  check_interrupted();
  const std::vector<int> vertex_type = vertex_types(medusa);
  const std::vector<int> types = distinct_types(vertex_type);
  // The page shows positive-length classes only, as the summary of `medusa run` does: the others are
  // dropped as each diagram is made.
  persistence::DiagramRunOptions options;
  options.threads = threads;
  options.zero_length = false;
  options.poll = check_interrupted;
  const std::vector<persistence::Diagram> diagrams =
      persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, options);
  check_interrupted();
  const std::vector<TypeSlices> slices = slices_at_frames(medusa);
  // The classical measures (docs/MATH.md §6.9) at the first and the last frame, as `medusa curves
  // --frames-only` prints them and as the clusters beside them are counted (the first frame's without
  // the cells present at t_0 alone): what a biologist compares the clusters with.
  const std::vector<medusa::SortingSample> sorting =
      frame_samples(medusa::sorting_over_time(medusa, check_interrupted), input);
  if (sorting.empty())
    throw InternalError("report: no time slice in " + store);
  const double t0 = static_cast<double>(input.frame_times.front());
  const double t_end = static_cast<double>(input.frame_times.back());

  ReportRun run;
  run.name = name;
  run.dimension = input.dimension;
  run.event_times = medusa.batches.size();
  run.input = input;
  run.run_info = medusa.run;
  json& j = run.data;
  j["name"] = name;
  j["facts"] = facts(medusa, store);
  j["frame_times"] = input.frame_times;
  json slice_rows = json::array();
  for (const TypeSlices& s : slices) {
    json b[3] = {json::array(), json::array(), json::array()};
    for (const Signature& g : s.at_frame)
      for (std::size_t k = 0; k < 3; ++k)
        b[k].push_back(g.betti[k]);
    const int type = s.label == "all" ? persistence::all_types : std::stoi(s.label);
    slice_rows.push_back(
        {{"label", s.label}, {"name", type_name(input, type)}, {"b0", b[0]}, {"b1", b[1]}, {"b2", b[2]}});
  }
  j["slices"] = std::move(slice_rows);

  // A handful per type and degree: the page's tables stay short, the rest is in `medusa classes`.
  TimesSeen seen;
  j["classes"] = report_classes(store, medusa, 5, seen);

  std::ostringstream summary;
  json headlines = json::array();
  std::vector<TypeVerdictInput> verdict_types;
  json panels = json::array();
  for (const persistence::Diagram& d : diagrams) {
    if (d.direction != persistence::Direction::forward)
      continue;
    const std::string label = type_label(d.cell_type);
    const std::string tname = type_name(input, d.cell_type);
    const bool whole = d.cell_type == persistence::all_types;
    const std::string title =
        whole ? "all cells" : "type " + label + (tname.empty() ? "" : " (" + tname + ")");
    summary << title << ":\n";
    describe_forward_diagram(summary, medusa, diagrams, d);
    const auto s =
        std::find_if(slices.begin(), slices.end(), [&](const TypeSlices& x) { return x.label == label; });
    std::vector<std::size_t> b0;
    for (const Signature& g : s->at_frame)
      b0.push_back(g.betti[0]);
    const TypeCourse course =
        type_course(input.frame_times, b0, forward_counts(d).merge_times,
                    clusters_joined_at_first(d, medusa::frame_batch(medusa, 0), b0.front()));
    const auto measures_of = [&](const medusa::SortingSample& sample) {
      const auto m =
          std::find_if(sample.measures.begin(), sample.measures.end(), [&](const medusa::SortingMeasures& x) {
            return whole ? !x.type.has_value() : x.type.has_value() && *x.type == d.cell_type;
          });
      if (m == sample.measures.end())
        throw InternalError("report: no sorting measures for " + label);
      return *m;
    };
    const medusa::SortingMeasures first = measures_of(sorting.front()), last = measures_of(sorting.back());
    headlines.push_back({{"label", label},
                         {"name", tname},
                         {"text", course.text},
                         {"contacts", contact_fractions(first, last, " \u2192 ") + ", " +
                                          largest_cluster_share(first, last, " \u2192 ") + " (MCS " +
                                          format_time(sorting.front().time) + " \u2192 " +
                                          format_time(sorting.back().time) + ")"},
                         {"gathered_at", course.gathered_at ? json(*course.gathered_at) : json(nullptr)}});
    if (!whole)
      verdict_types.push_back({title, course, heterotypic_contacts(first, last, " \u2192 "),
                               clusters_apart_text(clusters_apart(medusa, input.frames() - 1, d.cell_type))});
    for (int k = 0; k <= 2; ++k)
      panels.push_back(panel(d, k, max_bars, medusa, seen[d.cell_type]));
    run.h0_points.emplace_back(
        label, persistence::normalise_time(persistence::to_points(d, 0), d.direction, t0, t_end));
    check_interrupted();
  }
  write_wrapping_loops(summary, medusa, store);
  j["summary"] = summary.str();
  j["headlines"] = std::move(headlines);
  j["verdict"] = run_verdict(verdict_types, j["facts"]["radius"].get<std::string>());
  j["panels"] = std::move(panels);
  return run;
}

std::string mixed_dimensions_note(const std::vector<ReportRun>& runs) {
  std::vector<std::string> names;
  std::vector<int> dimensions;
  for (const ReportRun& r : runs) {
    names.push_back(r.name);
    dimensions.push_back(r.dimension);
  }
  return mixed_dimensions_note(names, dimensions);
}

} // namespace medusa::cli
