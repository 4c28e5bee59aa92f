// The winding of loop classes around a periodic domain (docs/MATH.md §8.8), on hand-built medusas
// whose windings are counted on paper.
#include "medusa/persistence/class_winding.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>

using namespace medusa;

namespace {

// Static cells at `xy` (grid units) over two frames, periodic along x with period 10 (and along y
// with period 10 when `both`), with one edge cell per consecutive pair closing the ring.
Medusa ring(const std::vector<std::array<std::int64_t, 2>>& xy, bool both) {
  Medusa m;
  m.run.periodic_axes = both ? "x,y" : "x";
  m.run.periodic_lengths = {10, both ? 10 : 0, 0};
  m.input.dimension = 2;
  m.input.scale = 1;
  m.input.frame_times = {0, 100};
  for (std::size_t i = 0; i < xy.size(); ++i) {
    kinetic::Trajectory t;
    t.cell_id = static_cast<std::int64_t>(i + 1);
    t.positions = {{xy[i][0], xy[i][1], 0}, {xy[i][0], xy[i][1], 0}};
    m.input.cells.push_back(t);
    Cell v;
    v.id = static_cast<CellId>(i);
    v.vertices = {static_cast<kinetic::VertexId>(i)};
    m.cells.push_back(v);
  }
  for (std::size_t i = 0; i < xy.size(); ++i) {
    Cell e;
    e.id = static_cast<CellId>(m.cells.size());
    const auto a = static_cast<kinetic::VertexId>(i), b = static_cast<kinetic::VertexId>((i + 1) % xy.size());
    e.vertices = {std::min(a, b), std::max(a, b)};
    e.birth.time = 40.0;
    e.facets = {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)};
    m.cells.push_back(e);
  }
  return m;
}

std::vector<CellId> edges_of(const Medusa& m) {
  std::vector<CellId> out;
  for (const Cell& c : m.cells)
    if (c.dim() == 1)
      out.push_back(c.id);
  return out;
}

// Loop classes of the ring `m`, one per entry of `born`: the class born with the ring's edge
// `born[i].first` in batch `born[i].second`, essential unless listed in `finite`, each with the whole
// ring as representative (winding once along x). As a store gives them back: no filtration index.
persistence::DiagramWithClasses ring_loops(Medusa& m,
                                           const std::vector<std::pair<std::size_t, std::uint32_t>>& born,
                                           const std::vector<std::size_t>& finite = {}) {
  const std::vector<CellId> edges = edges_of(m);
  persistence::DiagramWithClasses d;
  for (std::size_t i = 0; i < born.size(); ++i) {
    m.cells[edges[born[i].first]].birth.batch = born[i].second;
    persistence::PersistencePair p;
    p.dim = 1;
    p.birth_index = 0;
    p.death_index = -1;
    p.birth_cell = edges[born[i].first];
    p.essential = std::find(finite.begin(), finite.end(), i) == finite.end();
    d.diagram.pairs.push_back(p);
    d.classes.rows.push_back(i);
    d.classes.cycles.push_back(edges);
    d.classes.clusters.push_back({});
  }
  return d;
}

} // namespace

TEST_CASE("A ring that closes across the seam winds once along x", "[persistence][periodic]") {
  // Cells at x = 1, 4, 6, 9 (y = 5) on a period of 10: the edges 1-4, 4-6, 6-9 stay inside and the
  // edge 9-1 crosses the seam (9 -> 11): one period in total.
  const Medusa m = ring({{1, 5}, {4, 5}, {6, 5}, {9, 5}}, false);
  const auto w = persistence::cycle_winding(m, persistence::CellLists::List(edges_of(m)));
  CHECK(w == std::array<std::int64_t, 3>{1, 0, 0});
  CHECK(persistence::winding_axes(w) == "x");
}

TEST_CASE("A ring inside the domain winds zero times", "[persistence][periodic]") {
  // A square of cells at (2,2), (4,2), (4,4), (2,4) on the 10 x 10 torus: no edge crosses a seam.
  const Medusa m = ring({{2, 2}, {4, 2}, {4, 4}, {2, 4}}, true);
  const auto w = persistence::cycle_winding(m, persistence::CellLists::List(edges_of(m)));
  CHECK(w == std::array<std::int64_t, 3>{0, 0, 0});
  CHECK(persistence::winding_axes(w).empty());
  // The same square placed across the corner of the torus: its cells at (9,9), (1,9), (1,1), (9,1)
  // are joined by edges across both seams, each crossed once there and once back.
  const Medusa corner = ring({{9, 9}, {1, 9}, {1, 1}, {9, 1}}, true);
  CHECK(persistence::cycle_winding(corner, persistence::CellLists::List(edges_of(corner))) ==
        std::array<std::int64_t, 3>{0, 0, 0});
}

TEST_CASE("A diagonal ring on the torus winds once along x and once along y", "[persistence][periodic]") {
  // (1,1) -> (4,4) -> (7,7) -> (11,11) = (1,1) + (10,10): the closing edge from (7,7) crosses both seams.
  const Medusa m = ring({{1, 1}, {4, 4}, {7, 7}}, true);
  const auto w = persistence::cycle_winding(m, persistence::CellLists::List(edges_of(m)));
  CHECK(w == std::array<std::int64_t, 3>{1, 1, 0});
  CHECK(persistence::winding_axes(w) == "x,y");
}

TEST_CASE("An open run has no winding", "[persistence][periodic]") {
  Medusa m = ring({{1, 5}, {4, 5}, {6, 5}, {9, 5}}, false);
  m.run.periodic_axes.clear();
  m.run.periodic_lengths = {};
  CHECK(persistence::cycle_winding(m, persistence::CellLists::List(edges_of(m))) ==
        std::array<std::int64_t, 3>{0, 0, 0});
}

TEST_CASE("Of two essential loops with the same winding only the older one wraps",
          "[persistence][periodic]") {
  // Two essential classes whose representatives both wind once along x: the younger plus the older
  // (a representative of the younger class with the same birth) winds zero times, so the younger is
  // a hole in the tissue. Listed younger first, to show the order is the birth order: that of the
  // birth cells in the filtration (their batches here), not of the rows.
  Medusa m = ring({{1, 5}, {4, 5}, {6, 5}, {9, 5}}, false);
  const persistence::DiagramWithClasses d = ring_loops(m, {{3, 9}, {1, 5}});
  CHECK(persistence::class_wrapping_axes(m, d) == std::vector<std::string>{"", "x"});
}

TEST_CASE("A diagram read from a store finds the older wrapping loop without filtration indices",
          "[persistence][periodic]") {
  // As a store gives them back: no filtration index in any pair (0, and -1 for every death), a finite
  // class among the essential ones. Three loops winding once along x, born in batches 2 (finite: it
  // died, so it neither wraps nor reduces the others), 5 and 9, listed in the opposite order: only the
  // essential one of batch 5 wraps. Ordering by the (all-zero) indices left the rows' order, and
  // marked the one of batch 9; counting the finite one as essential would have marked it instead.
  Medusa m = ring({{1, 5}, {4, 5}, {6, 5}, {9, 5}}, false);
  const persistence::DiagramWithClasses d = ring_loops(m, {{0, 9}, {1, 5}, {2, 2}}, {2});
  const std::vector<std::string> axes = persistence::class_wrapping_axes(m, d);
  CHECK(axes[0].empty());
  CHECK(axes[1] == "x");
}
