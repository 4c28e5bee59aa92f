#include "report_classes.h"

#include "cell_type.h"
#include "complex_export.h"
#include "diagram_selection.h"
#include "interrupt.h"
#include "ring_fate.h"

#include "medusa/persistence/class_records.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace medusa::cli {
namespace {

using json = nlohmann::ordered_json;

// Coordinates embedded per page: beyond this many (about 7 MB of text) only every k-th frame is, and
// the page says so. large_3d (4,945 cells, 11 frames) has 163,185.
constexpr std::size_t max_embedded_coordinates = 1'000'000;

template <class Vertices> json vertex_list(const Vertices& vertices) {
  json out = json::array();
  for (kinetic::VertexId v : vertices)
    out.push_back(v);
  return out;
}

// The positions at the embedded frames, from positions_at_time as `medusa at` computes them; a
// trajectory absent on a frame is null there (positions_at_time would give its position on the next).
json frame_positions(const kinetic::Trajectories& input) {
  const std::size_t n = input.cells.size(), frames = input.frames();
  const std::size_t stride =
      std::max<std::size_t>(1, (3 * n * frames + max_embedded_coordinates - 1) / max_embedded_coordinates);
  std::vector<std::size_t> embedded;
  for (std::size_t k = 0; k < frames; k += stride)
    embedded.push_back(k);
  if (embedded.back() != frames - 1)
    embedded.push_back(frames - 1); // the run's end is always shown
  json times = json::array(), positions = json::array();
  for (std::size_t k : embedded) {
    check_interrupted();
    const double t = static_cast<double>(input.frame_times[k]);
    const auto at = positions_at_time(input, t);
    json flat = json::array();
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t a = 0; a < 3; ++a)
        flat.push_back(input.cells[v].present(k) ? json(std::round((*at[v])[a] * 1000) / 1000)
                                                 : json(nullptr));
    times.push_back(t);
    positions.push_back(std::move(flat));
  }
  return {{"times", std::move(times)}, {"frame_count", frames}, {"positions", std::move(positions)}};
}

json class_json(const persistence::ClassRecord& r, const persistence::DiagramWithClasses& found,
                std::size_t i, const medusa::Medusa& medusa) {
  // The representative's vertices are those whose CC3D ids `medusa classes` lists: the cluster for H0,
  // the cycle's cells otherwise (persistence::class_records).
  std::set<kinetic::VertexId> vertices;
  std::set<std::pair<kinetic::VertexId, kinetic::VertexId>> edges;
  std::set<std::array<kinetic::VertexId, 3>> triangles;
  for (medusa::CellId id : found.classes.cycles[i]) {
    const medusa::CellVertices& v = medusa.cell(id).vertices;
    if (r.dim == 0)
      continue;
    vertices.insert(v.begin(), v.end());
    for (std::size_t a = 0; a < v.size(); ++a)
      for (std::size_t b = a + 1; b < v.size(); ++b)
        edges.emplace(v[a], v[b]);
    if (v.size() == 3)
      triangles.insert({v[0], v[1], v[2]});
  }
  for (medusa::CellId id : found.classes.clusters[i]) {
    const medusa::CellVertices& v = medusa.cell(id).vertices;
    vertices.insert(v.begin(), v.end());
  }
  json ring = nullptr;
  if (r.essential && r.dim >= 1) {
    const RingFate fate = ring_fate(medusa, found.classes.cycles[i], medusa.cell(r.birth_cell).birth);
    ring = {{"state", ring_state_name(fate.state)},
            {"broke_at", fate.state == RingFate::State::broke ? json(fate.broke_at) : json(nullptr)}};
  }
  json e = json::array(), t = json::array();
  for (const auto& [a, b] : edges)
    e.push_back({a, b});
  for (const auto& tri : triangles)
    t.push_back({tri[0], tri[1], tri[2]});
  return {{"id", r.id},
          {"birth", r.birth},
          {"death", r.essential ? json(nullptr) : json(r.death)},
          {"birth_kind", persistence::cell_kind_name(r.birth_kind)},
          {"death_kind", r.essential ? json(nullptr) : json(persistence::cell_kind_name(r.death_kind))},
          {"ring", std::move(ring)},
          {"birth_cells", r.birth_cells},
          {"death_cells", r.death_cells},
          {"cells", r.cells},
          {"vertices", vertex_list(vertices)},
          {"edges", std::move(e)},
          {"triangles", std::move(t)},
          {"birth_simplex", vertex_list(medusa.cell(r.birth_cell).vertices)},
          {"death_simplex", r.essential ? json::array() : vertex_list(medusa.cell(r.death_cell).vertices)}};
}

} // namespace

json report_classes(const std::string& store, const medusa::Medusa& medusa, std::size_t top,
                    TimesSeen& times_seen) {
  const kinetic::Trajectories& input = medusa.input;
  json cells = {{"cc3d", json::array()}, {"type", json::array()}};
  for (const kinetic::Trajectory& c : input.cells) {
    cells["cc3d"].push_back(c.cell_id);
    cells["type"].push_back(c.type);
  }
  // Periodic axes' lengths in lattice units (0: not periodic), as `medusa at` wraps with.
  json periodic = json::array();
  for (std::int64_t length : medusa.run.periodic_lengths)
    periodic.push_back(static_cast<double>(length) / static_cast<double>(input.scale));
  json sections = json::array();
  for (int type : persistence::sub_medusa_types(distinct_types(vertex_types(medusa)))) {
    check_interrupted();
    const persistence::DiagramWithClasses found = persistence::diagram_with_classes(
        store, medusa, persistence::Direction::forward, type, persistence::RepresentativeOptions{});
    // Records are built for the classes shown only: a record holds its representative's cells, and a
    // large run has millions of classes.
    const double t_end = static_cast<double>(input.frame_times.back());
    std::vector<double> lifetime(found.classes.size()), seen(found.classes.size());
    for (std::size_t i = 0; i < lifetime.size(); ++i) {
      lifetime[i] = persistence::class_lifetime(found, i);
      const persistence::PersistencePair& p = found.diagram.pairs[found.classes.rows[i]];
      const double whole =
          p.essential ? essential_order(medusa, p.dim, found.classes.cycles[i], p.birth_cell, p.birth) : 0.0;
      seen[i] = time_seen(p.essential, lifetime[i], whole, p.birth, t_end);
      times_seen[type][p.birth_cell] = seen[i];
    }
    for (int k = 0; k <= 2; ++k) {
      // Represented classes, those seen longest in the tissue first, as `medusa classes --sort seen`
      // lists them: a ring that broke open soon after it formed is not what a reader of the table
      // looks for, though its class lives on in the space-time medusa.
      std::vector<std::size_t> order;
      for (std::size_t i = 0; i < found.classes.size(); ++i)
        if (found.diagram.pairs[found.classes.rows[i]].dim == k)
          order.push_back(i);
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return seen[a] != seen[b] ? seen[a] > seen[b] : lifetime[a] > lifetime[b];
      });
      const std::size_t total = order.size();
      if (top > 0 && order.size() > top)
        order.resize(top);
      json classes = json::array();
      for (std::size_t i : order)
        classes.push_back(class_json(persistence::class_record(medusa, found, i), found, i, medusa));
      sections.push_back(
          {{"label", type_label(type)},
           {"name", type == persistence::all_types ? std::string() : cell_type_name(input, type)},
           {"dim", k},
           {"total", total},
           {"classes", std::move(classes)}});
    }
  }
  return {{"top", top},
          {"periodic_lengths", std::move(periodic)},
          {"cells", std::move(cells)},
          {"frames", frame_positions(input)},
          {"sections", std::move(sections)}};
}

} // namespace medusa::cli
