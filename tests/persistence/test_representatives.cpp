// Representatives of persistence classes on hand-built medusas (docs/MATH.md §7.11): each expected cycle
// and cluster is derived by hand in the comment above its case.
#include "cell_list.h"
#include "medusa/persistence/representatives.h"

#include <catch2/catch.hpp>

#include <map>
#include <set>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

// Cell id of the cell with these vertices (one lifetime each in these medusas).
CellId id_of(const std::vector<Cell>& cells, std::vector<kinetic::VertexId> vertices) {
  std::sort(vertices.begin(), vertices.end());
  for (const Cell& c : cells)
    if (c.vertices == vertices)
      return c.id;
  throw std::logic_error("no such cell");
}

std::set<CellId> ids_of(const std::vector<Cell>& cells,
                        const std::vector<std::vector<kinetic::VertexId>>& tuples) {
  std::set<CellId> out;
  for (const auto& t : tuples)
    out.insert(id_of(cells, t));
  return out;
}

struct Found {
  PersistencePair pair;
  std::vector<CellId> cycle;
  std::vector<CellId> cluster;
};

// The represented classes of positive length or essential, by (dim, birth cell).
std::map<std::pair<int, CellId>, Found> classes_of(const std::vector<Cell>& cells, Direction direction,
                                                   const RepresentativeOptions& options = {}) {
  const Filtration f = make_filtration(cells, direction);
  const DiagramWithClasses d = compute_diagram_with_classes(cells, f, options);
  std::map<std::pair<int, CellId>, Found> out;
  for (std::size_t i = 0; i < d.classes.size(); ++i) {
    const PersistencePair& p = d.diagram.pairs[d.classes.rows[i]];
    out[{p.dim, p.birth_cell}] = {p, d.classes.cycles[i].to_vector(), d.classes.clusters[i].to_vector()};
  }
  return out;
}

template <class Ids> std::set<CellId> as_set(const Ids& v) { return {v.begin(), v.end()}; }

// Square 0-1-2-3: vertices at t=0, edges 01, 12, 23 at t=1, 2, 3; edge 03 closes it at t=4.
std::vector<CellSpec> square(double end) {
  std::vector<CellSpec> s;
  const auto e = static_cast<std::uint64_t>(end);
  for (int v = 0; v < 4; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(e, 0, end)});
  s.push_back({{0, 1}, vt(1, 0, 1), vt(e, 0, end)});
  s.push_back({{1, 2}, vt(2, 0, 2), vt(e, 0, end)});
  s.push_back({{2, 3}, vt(3, 0, 3), vt(e, 0, end)});
  s.push_back({{0, 3}, vt(4, 0, 4), vt(e, 0, end)});
  return s;
}

// The square, filled at t=5 by the diagonal 02 and the triangles 012 and 023.
std::vector<CellSpec> filled_square() {
  auto s = square(6);
  s.push_back({{0, 2}, vt(5, 0, 5), vt(6, 0, 6)});
  s.push_back({{0, 1, 2}, vt(5, 0, 5), vt(6, 0, 6)});
  s.push_back({{0, 2, 3}, vt(5, 0, 5), vt(6, 0, 6)});
  return s;
}

// Octahedron: 0/1 = +-x, 2/3 = +-y, 4/5 = +-z. Edges: every pair but 01, 23, 45; triangles: one
// vertex from each of {0,1}, {2,3}, {4,5}. All at t=0 except the triangle 135 at t=1.
std::vector<CellSpec> hollow_octahedron(double end) {
  std::vector<CellSpec> s;
  const auto e = static_cast<std::uint64_t>(end);
  for (int v = 0; v < 6; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(e, 0, end)});
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b)
      if (b != a + 1 || a % 2 == 1)
        s.push_back({{a, b}, vt(0, 0, 0), vt(e, 0, end)});
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) {
        const bool last = x == 1 && y == 3 && z == 5;
        s.push_back({{x, y, z}, last ? vt(1, 0, 1) : vt(0, 0, 0), vt(e, 0, end)});
      }
  return s;
}

std::set<CellId> octahedron_faces(const std::vector<Cell>& cells) {
  std::set<CellId> out;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5})
        out.insert(id_of(cells, {x, y, z}));
  return out;
}

} // namespace

// Forward: the loop 01+12+23+03 is born with 03 at t=4. At t=5 the diagonal 02 enters with the
// triangles 012 and 023 (batch order: dimension, then vertex tuple). 02 creates a loop killed at once
// by 012 (zero length). The column of 023, ∂ = 02+23+03, has low 02, which is 012's low: adding
// R[012] = 01+12+02 leaves 01+12+23+03, low 03. So (03, 023) is the pair, t = (4, 5), and its
// representative is exactly the square, whose last cell is the birth cell 03.
TEST_CASE("A square that closes and is then filled is represented by its four edges") {
  const auto cells = make_cells(filled_square());
  const auto classes = classes_of(cells, Direction::forward);
  const auto it = classes.find({1, id_of(cells, {0, 3})});
  REQUIRE(it != classes.end());
  CHECK(it->second.pair.birth == 4);
  CHECK(it->second.pair.death == 5);
  CHECK(it->second.pair.death_cell == id_of(cells, {0, 2, 3}));
  CHECK(it->second.cycle == std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {1, 2}),
                                                id_of(cells, {2, 3}), id_of(cells, {0, 3})});
  CHECK(it->second.cluster.empty());
  // One H1 class of positive length, none essential.
  std::size_t h1 = 0;
  for (const auto& [key, found] : classes)
    h1 += key.first == 1;
  CHECK(h1 == 1);
}

// Never filled, the loop is essential. ∂03 = 0+3: the lowest entry 3 is the pivot of edge 23 (which
// merged vertex 3, R = 2+3), leaving 0+2; then 12 (R = 1+2), leaving 0+1; then 01. Each of those
// columns is its own boundary, so W = the edge itself and z = 03+23+12+01: the square again.
TEST_CASE("A square that closes and is never filled is an essential class represented by its four edges") {
  const auto cells = make_cells(square(6));
  const auto classes = classes_of(cells, Direction::forward);
  const auto it = classes.find({1, id_of(cells, {0, 3})});
  REQUIRE(it != classes.end());
  CHECK(it->second.pair.essential);
  CHECK(it->second.cycle == std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {1, 2}),
                                                id_of(cells, {2, 3}), id_of(cells, {0, 3})});
}

// The octahedron's surface is born with its last face 135 at t=1. The only 2-cycle of the surface is
// all eight faces (H2 of a sphere), and a representative lies in the surface (it uses cells entered no
// later than 135), so it is the eight faces whether the class is essential (never filled) or killed.
TEST_CASE("A hollow octahedron of cells is an essential cavity represented by its eight faces") {
  const auto cells = make_cells(hollow_octahedron(3));
  const auto classes = classes_of(cells, Direction::forward);
  const auto it = classes.find({2, id_of(cells, {1, 3, 5})});
  REQUIRE(it != classes.end());
  CHECK(it->second.pair.essential);
  CHECK(it->second.pair.birth == 1);
  CHECK(as_set(it->second.cycle) == octahedron_faces(cells));
  CHECK(it->second.cycle.size() == 8);
  CHECK(it->second.cycle.back() == id_of(cells, {1, 3, 5}));
}

// Filled at t=2 by the axis 45, the triangles a45 and the four tetrahedra ab45 (a in {0,1}, b in
// {2,3}): the boundaries of the four tetrahedra sum to the eight faces (each triangle a45 is shared
// by two of them), so the last tetrahedron in order, 1345, kills the cavity: the pair (1, 2), with
// the surface as its representative (R[1345]).
TEST_CASE("A hollow octahedron filled later is a cavity from its closing to its filling") {
  auto s = hollow_octahedron(3);
  s.push_back({{4, 5}, vt(2, 0, 2), vt(3, 0, 3)});
  for (int a = 0; a < 4; ++a)
    s.push_back({{a, 4, 5}, vt(2, 0, 2), vt(3, 0, 3)});
  for (int x : {0, 1})
    for (int y : {2, 3})
      s.push_back({{x, y, 4, 5}, vt(2, 0, 2), vt(3, 0, 3)});
  const auto cells = make_cells(s);
  const auto classes = classes_of(cells, Direction::forward);
  const auto it = classes.find({2, id_of(cells, {1, 3, 5})});
  REQUIRE(it != classes.end());
  CHECK_FALSE(it->second.pair.essential);
  CHECK(it->second.pair.birth == 1);
  CHECK(it->second.pair.death == 2);
  CHECK(it->second.pair.death_cell == id_of(cells, {1, 3, 4, 5}));
  CHECK(as_set(it->second.cycle) == octahedron_faces(cells));
}

// Cluster A = {0,1,2} (edges 01, 12 at t=0), cluster B = {3,4} (edge 34 at t=0), grown by vertex 5
// and edge 45 at t=1; edge 23 joins them at t=2. Oldest vertices: 0 for A, 3 for B (same batch,
// vertex order), so B dies: pair (3, 23) from 0 to 2, cycle 0+3, cluster {3, 4, 5}. The survivor is
// essential: cycle 0, cluster all six vertices.
TEST_CASE("Two clusters merging: the younger one is the class's cluster and its oldest cell its birth") {
  std::vector<CellSpec> s;
  for (int v = 0; v < 5; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(3, 0, 3)});
  s.push_back({{5}, vt(1, 0, 1), vt(3, 0, 3)});
  s.push_back({{0, 1}, vt(0, 0, 0), vt(3, 0, 3)});
  s.push_back({{1, 2}, vt(0, 0, 0), vt(3, 0, 3)});
  s.push_back({{3, 4}, vt(0, 0, 0), vt(3, 0, 3)});
  s.push_back({{4, 5}, vt(1, 0, 1), vt(3, 0, 3)});
  s.push_back({{2, 3}, vt(2, 0, 2), vt(3, 0, 3)});
  const auto cells = make_cells(s);
  const auto classes = classes_of(cells, Direction::forward);
  const auto merged = classes.find({0, id_of(cells, {3})});
  REQUIRE(merged != classes.end());
  CHECK(merged->second.pair.birth == 0);
  CHECK(merged->second.pair.death == 2);
  CHECK(merged->second.pair.death_cell == id_of(cells, {2, 3}));
  CHECK(merged->second.cycle == std::vector<CellId>{id_of(cells, {0}), id_of(cells, {3})});
  CHECK(as_set(merged->second.cluster) == ids_of(cells, {{3}, {4}, {5}}));
  const auto survivor = classes.find({0, id_of(cells, {0})});
  REQUIRE(survivor != classes.end());
  CHECK(survivor->second.pair.essential);
  CHECK(survivor->second.cycle == std::vector<CellId>{id_of(cells, {0})});
  CHECK(as_set(survivor->second.cluster) == ids_of(cells, {{0}, {1}, {2}, {3}, {4}, {5}}));
  // Vertex 5 merged into B at once (zero length): not represented by default.
  CHECK(classes.size() == 2);
}

// Options: zero-length pairs on request, and degrees above max_dim left out.
TEST_CASE("Representatives follow the options for zero-length pairs and degrees") {
  const auto cells = make_cells(filled_square());
  const Filtration f = make_filtration(cells, Direction::forward);
  RepresentativeOptions all;
  all.zero_length = true;
  const DiagramWithClasses every = compute_diagram_with_classes(cells, f, all);
  CHECK(every.classes.size() == every.diagram.pairs.size());
  for (std::size_t i = 0; i < every.classes.size(); ++i) {
    const PersistencePair& p = every.diagram.pairs[every.classes.rows[i]];
    if (p.dim == 1 && p.zero_length) // 02 killed by 012 at once: R[012] = 01+12+02
      CHECK(as_set(every.classes.cycles[i]) == ids_of(cells, {{0, 1}, {1, 2}, {0, 2}}));
  }
  RepresentativeOptions h0;
  h0.max_dim = 0;
  const DiagramWithClasses low = compute_diagram_with_classes(cells, f, h0);
  for (std::size_t r : low.classes.rows)
    CHECK(low.diagram.pairs[r].dim == 0);
  CHECK(low.classes.size() == 4); // three merges of positive length and the survivor
}

namespace {

RepresentativeOptions shortened() {
  RepresentativeOptions o;
  o.shorten = true;
  return o;
}

// Square 0-1-2-3 with the chord 02 from the start: vertices at t=0; edges 01, 02, 12, 23 at t=1 (12
// closes the triangle loop 0-1-2); 03 at t=2 closes the square; the triangle 012 fills the triangle
// loop at t=3; at t=4 the edge 13 and the triangles 013, 123.
std::vector<CellSpec> square_with_chord() {
  std::vector<CellSpec> s;
  for (int v = 0; v < 4; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(5, 0, 5)});
  for (std::vector<kinetic::VertexId> e : {std::vector<kinetic::VertexId>{0, 1}, {0, 2}, {1, 2}, {2, 3}})
    s.push_back({e, vt(1, 0, 1), vt(5, 0, 5)});
  s.push_back({{0, 3}, vt(2, 0, 2), vt(5, 0, 5)});
  s.push_back({{0, 1, 2}, vt(3, 0, 3), vt(5, 0, 5)});
  s.push_back({{1, 3}, vt(4, 0, 4), vt(5, 0, 5)});
  s.push_back({{0, 1, 3}, vt(4, 0, 4), vt(5, 0, 5)});
  s.push_back({{1, 2, 3}, vt(4, 0, 4), vt(5, 0, 5)});
  return s;
}

} // namespace

// In square_with_chord the loop born with 03 (t=2) dies at t=4: 13 is killed at once by 013 (low 13),
// and ∂123 = 12+13+23 has low 13, so adding R[013] = 01+03+13 leaves 01+12+23+03, low 03: the reduced
// column is the square. The triangle 012 entered before the death and its edges before 03; it shares
// 01 and 12 with the square, so adding its boundary 01+02+12 leaves 02+23+03 (three edges). Then no
// triangle entered before 123 with all edges before 03 shares two edges with it (013 has the edge 13,
// entered after 03; 123 is the death cell): the shortened cycle is 02+23+03.
TEST_CASE("A loop is shortened through a filled triangle whose edges entered before its birth") {
  const auto cells = make_cells(square_with_chord());
  const CellId birth = id_of(cells, {0, 3});
  const auto plain = classes_of(cells, Direction::forward).at({1, birth});
  CHECK(plain.pair.death_cell == id_of(cells, {1, 2, 3}));
  CHECK(plain.cycle ==
        std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {1, 2}), id_of(cells, {2, 3}), birth});
  const auto shorter = classes_of(cells, Direction::forward, shortened()).at({1, birth});
  CHECK(shorter.pair.death_cell == id_of(cells, {1, 2, 3}));
  CHECK(shorter.cycle == std::vector<CellId>{id_of(cells, {0, 2}), id_of(cells, {2, 3}), birth});
  // The triangle loop's representative R[012] is its boundary already.
  CHECK(classes_of(cells, Direction::forward, shortened()).at({1, id_of(cells, {1, 2})}).cycle ==
        std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {0, 2}), id_of(cells, {1, 2})});
}

// Vertices at t=0; edges 01, 12, 23 at t=1 (a path), the chord 02 at t=2, 03 at t=3, the triangle 012
// at t=4, and nothing fills the rest. The loop born with 03 is essential; its cycle from the columns
// (03 + W(23) + W(12) + W(01), each W the edge itself) is the square. Adding ∂012 = 01+12+02 (012
// enters after 03, but every edge of it before) leaves 02+23+03, in filtration order 23, 02, 03.
TEST_CASE("An essential loop is shortened through a triangle entered after its birth") {
  std::vector<CellSpec> s;
  for (int v = 0; v < 4; ++v)
    s.push_back({{v}, vt(0, 0, 0), vt(5, 0, 5)});
  for (std::vector<kinetic::VertexId> e : {std::vector<kinetic::VertexId>{0, 1}, {1, 2}, {2, 3}})
    s.push_back({e, vt(1, 0, 1), vt(5, 0, 5)});
  s.push_back({{0, 2}, vt(2, 0, 2), vt(5, 0, 5)});
  s.push_back({{0, 3}, vt(3, 0, 3), vt(5, 0, 5)});
  s.push_back({{0, 1, 2}, vt(4, 0, 4), vt(5, 0, 5)});
  const auto cells = make_cells(s);
  const CellId birth = id_of(cells, {0, 3});
  const auto plain = classes_of(cells, Direction::forward).at({1, birth});
  REQUIRE(plain.pair.essential);
  CHECK(plain.cycle ==
        std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {1, 2}), id_of(cells, {2, 3}), birth});
  const auto shorter = classes_of(cells, Direction::forward, shortened()).at({1, birth});
  CHECK(shorter.cycle == std::vector<CellId>{id_of(cells, {2, 3}), id_of(cells, {0, 2}), birth});
}

// In the square filled at t=5 (first case above) the only triangles sharing two edges with the square
// use the diagonal 02, which enters after the birth cell 03: the square stays as it is.
TEST_CASE("A loop is not shortened through edges entered after its birth") {
  const auto cells = make_cells(filled_square());
  const auto shorter = classes_of(cells, Direction::forward, shortened()).at({1, id_of(cells, {0, 3})});
  CHECK(shorter.cycle == std::vector<CellId>{id_of(cells, {0, 1}), id_of(cells, {1, 2}), id_of(cells, {2, 3}),
                                             id_of(cells, {0, 3})});
}

// Shortening stored cycles afterwards gives what shortening while computing them gives, and marks them.
TEST_CASE("Shortening computed representatives afterwards equals shortening them at once") {
  const auto cells = make_cells(square_with_chord());
  const Filtration f = make_filtration(cells, Direction::forward);
  DiagramWithClasses plain = compute_diagram_with_classes(cells, f);
  const DiagramWithClasses at_once = compute_diagram_with_classes(cells, f, shortened());
  CHECK_FALSE(plain.classes.options.shorten);
  shorten_representatives(cells, f, plain.diagram, plain.classes);
  CHECK(plain.classes.options.shorten);
  CHECK(plain.classes.rows == at_once.classes.rows);
  CHECK(plain.classes.cycles == at_once.classes.cycles);
  CHECK(plain.classes.clusters == at_once.classes.clusters);
}
