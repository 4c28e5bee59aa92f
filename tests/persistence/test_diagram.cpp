// Diagrams of hand-derived small medusas (docs/MATH.md §7.2-§7.6): every expected pair is derived by hand in
// the comment above its case.
#include "cell_list.h"
#include "medusa/core/error.h"
#include "medusa/persistence/degree_check.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/diagram_store.h"
#include "medusa/persistence/diagram_text.h"
#include "medusa/persistence/euler.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <catch2/catch.hpp>
#include <phat/algorithms/chunk_reduction.h>
#include <phat/algorithms/row_reduction.h>
#include <phat/algorithms/standard_reduction.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <tuple>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

const double inf = std::numeric_limits<double>::infinity();

// (dim, birth, death) of the pairs of positive length and the essential classes, sorted.
std::vector<std::tuple<int, double, double>> points_of(const Diagram& d) {
  std::vector<std::tuple<int, double, double>> result;
  for (const auto& p : d.pairs)
    if (!p.zero_length)
      result.emplace_back(p.dim, p.birth, p.death);
  std::sort(result.begin(), result.end());
  return result;
}

std::size_t zero_length_count(const Diagram& d) {
  std::size_t n = 0;
  for (const auto& p : d.pairs)
    n += p.zero_length;
  return n;
}

Diagram forward_diagram(const std::vector<Cell>& cells) {
  const Filtration f = make_filtration(cells, Direction::forward);
  Diagram d = compute_diagram(cells, f);
  check_euler(d, f);
  return d;
}

Diagram reverse_diagram(const std::vector<Cell>& cells) {
  const Filtration f = make_filtration(cells, Direction::reverse);
  Diagram d = compute_diagram(cells, f);
  check_euler(d, f);
  return d;
}

} // namespace

// Forward: vertices 0,1,2 at t=0. Edge ab (t=1) kills the younger of a, b: b, pair (0,1); bc (t=2)
// kills c, pair (0,2); a is essential (0,+inf). Edge ca (t=3) closes a loop filled by abc (t=4):
// H1 pair (3,4). Reverse: every cell dies at t=5, so everything enters in one batch: all pairs have
// zero length and one essential H0 class is born at 5 with death -inf.
TEST_CASE("A filled triangle appearing over time has the hand-derived forward and reverse diagrams") {
  const auto cells = filled_triangle();
  const Diagram f = forward_diagram(cells);
  CHECK(points_of(f) ==
        std::vector<std::tuple<int, double, double>>{{0, 0, 1}, {0, 0, 2}, {0, 0, inf}, {1, 3, 4}});
  CHECK(zero_length_count(f) == 0);
  const auto h1 = pairs_in_dimension(f, 1);
  REQUIRE(h1.size() == 1);
  CHECK(birth_vertices(h1[0], cells) == std::vector<kinetic::VertexId>{0, 2});
  CHECK(death_vertices(h1[0], cells) == std::vector<kinetic::VertexId>{0, 1, 2});
  CHECK(h1[0].birth_cell == 1000 + 7 * 5);
  CHECK(h1[0].death_cell == 1000 + 7 * 6);
  CHECK(h1[0].birth_time == vt(3, 0, 3));
  CHECK(h1[0].death_time == vt(4, 0, 4));

  const Diagram r = reverse_diagram(cells);
  CHECK(points_of(r) == std::vector<std::tuple<int, double, double>>{{0, 5, -inf}});
  CHECK(zero_length_count(r) == 3);
  CHECK(without_zero_length(r).pairs.size() == 1);
}

// Boundary of the tetrahedron abcd: vertices and edges at t=0; triangles abc, abd, acd, bcd at t=1..4;
// the interior abcd at t=6; everything dies at t=10. Forward: three of the six edges kill vertices
// (zero length), the other three open loops at 0 that abc, abd, acd fill at 1, 2, 3. bcd closes the
// sphere at 4 and abcd fills it at 6: H2 pair (4, 6), born by triangle bcd, killed by abcd.
TEST_CASE("A sphere whose interior fills later has an H2 class from its closing to its filling") {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1}, vt(0, 0, 0), vt(6, 0, 10));
  add_closure(s, {0, 2}, vt(0, 0, 0), vt(6, 0, 10));
  add_closure(s, {0, 3}, vt(0, 0, 0), vt(6, 0, 10));
  add_closure(s, {1, 2}, vt(0, 0, 0), vt(6, 0, 10));
  add_closure(s, {1, 3}, vt(0, 0, 0), vt(6, 0, 10));
  add_closure(s, {2, 3}, vt(0, 0, 0), vt(6, 0, 10));
  s.push_back({{0, 1, 2}, vt(1, 0, 1), vt(6, 0, 10)});
  s.push_back({{0, 1, 3}, vt(2, 0, 2), vt(6, 0, 10)});
  s.push_back({{0, 2, 3}, vt(3, 0, 3), vt(6, 0, 10)});
  s.push_back({{1, 2, 3}, vt(4, 0, 4), vt(6, 0, 10)});
  s.push_back({{0, 1, 2, 3}, vt(5, 0, 6), vt(6, 0, 10)});
  const auto cells = make_cells(s);
  const Diagram f = forward_diagram(cells);
  CHECK(points_of(f) == std::vector<std::tuple<int, double, double>>{
                            {0, 0, inf}, {1, 0, 1}, {1, 0, 2}, {1, 0, 3}, {2, 4, 6}});
  CHECK(zero_length_count(f) == 3);
  const auto h2 = pairs_in_dimension(f, 2);
  REQUIRE(h2.size() == 1);
  CHECK(birth_vertices(h2[0], cells) == std::vector<kinetic::VertexId>{1, 2, 3});
  CHECK(death_vertices(h2[0], cells) == std::vector<kinetic::VertexId>{0, 1, 2, 3});
  CHECK(euler_characteristic(make_filtration(cells, Direction::forward)) == 1);
}

// Square a=0,b=1,c=2,d=3 with edges ab, bc, cd at t=0; da closes the circle at t=3; the diagonal ac and
// the triangle abc enter together at t=5 (ac's loop dies at once: zero length); acd fills the circle
// at t=7. Forward H1: (3, 7) plus the zero-length (5, 5). All die at t=10.
TEST_CASE("A circle that closes and later fills has an H1 class from closing to filling") {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1}, vt(0, 0, 0), vt(4, 0, 10));
  add_closure(s, {1, 2}, vt(0, 0, 0), vt(4, 0, 10));
  add_closure(s, {2, 3}, vt(0, 0, 0), vt(4, 0, 10));
  s.push_back({{0, 3}, vt(1, 0, 3), vt(4, 0, 10)});
  s.push_back({{0, 2}, vt(2, 0, 5), vt(4, 0, 10)});
  s.push_back({{0, 1, 2}, vt(2, 0, 5), vt(4, 0, 10)});
  s.push_back({{0, 2, 3}, vt(3, 0, 7), vt(4, 0, 10)});
  const auto cells = make_cells(s);
  const Diagram f = forward_diagram(cells);
  CHECK(points_of(f) == std::vector<std::tuple<int, double, double>>{{0, 0, inf}, {1, 3, 7}});
  const auto all_h1 = pairs_in_dimension(f, 1, true);
  REQUIRE(all_h1.size() == 2);
  CHECK(all_h1[1].zero_length);
  CHECK(all_h1[1].birth == 5);
  CHECK(all_h1[1].death == 5);
  CHECK(birth_vertices(all_h1[1], cells) == std::vector<kinetic::VertexId>{0, 2});
  CHECK(pairs_in_dimension(f, 1).size() == 1);
}

// Time-symmetric on [0, 10]: vertices and edges ab, bc live [0,10], edge ca [2,8], triangle abc [4,6];
// t -> 10 - t maps the set of lifetimes onto itself. Forward H1 (2, 4); the reverse diagram is the
// forward one with t -> 10 - t: H1 (8, 6) and the essential H0 class born at 10.
TEST_CASE("Forward and reverse filtrations of a time-symmetric medusa give mirrored diagrams") {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1}, vt(0, 0, 0), vt(5, 0, 10));
  add_closure(s, {1, 2}, vt(0, 0, 0), vt(5, 0, 10));
  s.push_back({{0, 2}, vt(1, 0, 2), vt(4, 0, 8)});
  s.push_back({{0, 1, 2}, vt(2, 0, 4), vt(3, 0, 6)});
  const auto cells = make_cells(s);
  const Diagram f = forward_diagram(cells);
  const Diagram r = reverse_diagram(cells);
  CHECK(points_of(f) == std::vector<std::tuple<int, double, double>>{{0, 0, inf}, {1, 2, 4}});
  CHECK(points_of(r) == std::vector<std::tuple<int, double, double>>{{0, 10, -inf}, {1, 8, 6}});
  auto mirrored = points_of(f);
  for (auto& [dim, b, d] : mirrored) {
    b = 10 - b;
    d = 10 - d;
  }
  std::sort(mirrored.begin(), mirrored.end());
  CHECK(mirrored == points_of(r));
}

// docs/MATH.md §B (one 2-3 flip): a..e = 0..4, t* = 96.7774 is batch 1 rank 1, t_end = 100 is
// batch 2. Forward: one essential H0 class at 0, all other pairs zero length; at t* de opens a loop
// killed by ade, bde and cde open H2 classes killed by abde and acde, bcde (last in tuple order) opens
// the H3 class of the five tetrahedra, killed by the 4-simplex. chi = 5 - 10 + 10 - 5 + 1 = 1.
TEST_CASE("The flip of docs/MATH.md §B gives one essential class and only zero-length pairs") {
  const double ts = 96.7774;
  const auto t0 = vt(0, 0, 0), tstar = vt(1, 1, ts), tend = vt(2, 0, 100);
  std::vector<CellSpec> s;
  for (std::vector<kinetic::VertexId> tri :
       {std::vector<kinetic::VertexId>{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {0, 2, 4}})
    add_closure(s, tri, t0, tend);
  s.push_back({{0, 1, 2}, t0, tstar});
  s.push_back({{0, 1, 2, 3}, t0, tstar});
  s.push_back({{0, 1, 2, 4}, t0, tstar});
  s.push_back({{3, 4}, tstar, tend});
  for (kinetic::VertexId v : {0, 1, 2})
    s.push_back({{v, 3, 4}, tstar, tend});
  s.push_back({{0, 1, 3, 4}, tstar, tend});
  s.push_back({{1, 2, 3, 4}, tstar, tend});
  s.push_back({{0, 2, 3, 4}, tstar, tend});
  s.push_back({{0, 1, 2, 3, 4}, tstar, tstar, medusa::CellKind::flip});
  const auto cells = make_cells(s);
  REQUIRE(cells.size() == 31);
  const Diagram f = forward_diagram(cells);
  CHECK(points_of(f) == std::vector<std::tuple<int, double, double>>{{0, 0, inf}});
  CHECK(f.pairs.size() == 16);
  const auto h3 = pairs_in_dimension(f, 3, true);
  REQUIRE(h3.size() == 1);
  CHECK(birth_vertices(h3[0], cells) == std::vector<kinetic::VertexId>{1, 2, 3, 4});
  CHECK(death_vertices(h3[0], cells) == std::vector<kinetic::VertexId>{0, 1, 2, 3, 4});
  CHECK(h3[0].birth == ts);
  const auto h2 = pairs_in_dimension(f, 2, true);
  // At t0 seven triangles meet five independent loops: two open the zero-length H2 classes filled by
  // abcd and abce; at t* bde and cde open the two filled by abde and acde.
  CHECK(h2.size() == 4);
  CHECK_NOTHROW(check_homology_degrees(f));
  const Diagram r = reverse_diagram(cells);
  CHECK(points_of(r) == std::vector<std::tuple<int, double, double>>{{0, 100, -inf}});
  CHECK_NOTHROW(check_homology_degrees(r));
}

// The boundary of a 5-simplex whose last 4-face comes later: that face closes a 4-sphere, an
// essential H4 class no medusa can have (docs/MATH.md §7.6).
TEST_CASE("A class of degree above 3 that is essential or of positive length fails the degree audit") {
  std::vector<CellSpec> s;
  for (int skip : {1, 2, 3, 4, 5, 0}) {
    std::vector<kinetic::VertexId> face;
    for (int v = 0; v < 6; ++v)
      if (v != skip)
        face.push_back(v);
    add_closure(s, face, skip == 0 ? vt(1, 0, 1) : vt(0, 0, 0), vt(2, 0, 2));
  }
  const auto cells = make_cells(s);
  const Diagram f = forward_diagram(cells);
  REQUIRE(pairs_in_dimension(f, 4).size() == 1);
  CHECK(pairs_in_dimension(f, 4)[0].essential);
  CHECK_THROWS_AS(check_homology_degrees(f), InternalError);
}

TEST_CASE("The Euler check compares the essential classes with chi and rejects a mismatch") {
  const auto cells = filled_triangle();
  const Filtration f = make_filtration(cells, Direction::forward);
  Diagram d = compute_diagram(cells, f);
  CHECK(euler_characteristic(f) == 1);
  CHECK(essential_euler_characteristic(d) == 1);
  CHECK_NOTHROW(check_euler(d, f));
  d.pairs.back().essential = false;
  for (auto& p : d.pairs)
    p.essential = false;
  CHECK_THROWS_AS(check_euler(d, f), InternalError);
}

TEST_CASE("Every PHAT representation and reduction algorithm gives the same diagram") {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1, 2, 3}, vt(0, 0, 0), vt(3, 0, 3));
  add_closure(s, {2, 3, 4}, vt(1, 0, 1), vt(2, 0, 2));
  const auto cells = make_cells(s);
  for (Direction dir : {Direction::forward, Direction::reverse}) {
    const Filtration f = make_filtration(cells, dir);
    std::ostringstream a, b, c, d;
    write_diagram_text(a, compute_diagram(cells, f), cells);
    write_diagram_text(b, compute_diagram<phat::vector_vector, phat::standard_reduction>(cells, f), cells);
    write_diagram_text(c, compute_diagram<phat::heap_pivot_column, phat::chunk_reduction>(cells, f), cells);
    write_diagram_text(d, compute_diagram<phat::sparse_pivot_column, phat::row_reduction>(cells, f), cells);
    CHECK(a.str() == b.str());
    CHECK(a.str() == c.str());
    CHECK(a.str() == d.str());
  }
}

TEST_CASE("The same cells in any input order give a byte-identical serialized diagram") {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1, 2, 3}, vt(0, 0, 0), vt(4, 0, 4));
  add_closure(s, {3, 4, 5}, vt(1, 0, 0.25), vt(3, 2, 3.5));
  add_closure(s, {0, 5}, vt(2, 0, 1.0 / 3), vt(3, 1, 3.5));
  auto cells = make_cells(s);
  std::ostringstream reference;
  write_diagram_text(reference, forward_diagram(cells), cells);
  const unsigned seed = 20240611;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  for (int round = 0; round < 5; ++round) {
    std::shuffle(cells.begin(), cells.end(), rng);
    std::ostringstream again;
    write_diagram_text(again, forward_diagram(cells), cells);
    CHECK(again.str() == reference.str());
  }
  CHECK(reference.str().find("0.33333333333333331") != std::string::npos);
}

// The time-symmetric example with vertex 2 of type 2 and vertices 0, 1 of type 1: M_1 is the edge 01
// (one essential H0 class each way), M_2 the vertex 2.
TEST_CASE("All diagrams of a run come whole and per type, forward and reverse, in a fixed order") {
  const auto cells = symmetric_cells();
  const auto diagrams = compute_medusa_diagrams(cells, {1, 1, 2}, {1, 2});
  REQUIRE(diagrams.size() == 6);
  const std::vector<std::pair<Direction, int>> expected{
      {Direction::forward, all_types}, {Direction::reverse, all_types}, {Direction::forward, 1},
      {Direction::reverse, 1},         {Direction::forward, 2},         {Direction::reverse, 2}};
  for (std::size_t k = 0; k < 6; ++k) {
    CAPTURE(k);
    CHECK(diagrams[k].direction == expected[k].first);
    CHECK(diagrams[k].cell_type == expected[k].second);
  }
  CHECK(points_of(diagrams[0]) == std::vector<std::tuple<int, double, double>>{{0, 0, inf}, {1, 2, 4}});
  CHECK(points_of(diagrams[1]) == std::vector<std::tuple<int, double, double>>{{0, 10, -inf}, {1, 8, 6}});
  CHECK(points_of(diagrams[2]) == std::vector<std::tuple<int, double, double>>{{0, 0, inf}});
  CHECK(points_of(diagrams[5]) == std::vector<std::tuple<int, double, double>>{{0, 10, -inf}});
  CHECK(diagrams[4].pairs.size() == 1);
}

namespace {

// A triangle whole at the start (zero-length pairs), and a fourth cell that joins it later (a pair of
// positive length); cells 0, 1 of type 1, cells 2, 3 of type 2.
std::vector<Cell> triangle_and_late_edge() {
  std::vector<CellSpec> s;
  add_closure(s, {0, 1, 2}, vt(0, 0, 0), vt(5, 0, 10));
  s.push_back({{3}, vt(0, 0, 0), vt(5, 0, 10)});
  s.push_back({{2, 3}, vt(2, 0, 4), vt(5, 0, 10)});
  return make_cells(s);
}

} // namespace

TEST_CASE("Diagrams made without their zero-length pairs equal the full ones with those pairs dropped") {
  const auto cells = triangle_and_late_edge();
  const std::vector<int> vertex_type{1, 1, 2, 2};
  const auto full = compute_medusa_diagrams(cells, vertex_type, {1, 2});
  DiagramRunOptions options;
  options.zero_length = false;
  const auto lean = compute_medusa_diagrams(cells, vertex_type, {1, 2}, options);
  REQUIRE(lean.size() == full.size());
  std::size_t dropped = 0;
  for (std::size_t k = 0; k < full.size(); ++k) {
    CAPTURE(k);
    Diagram expected = full[k];
    drop_zero_length(expected);
    dropped += full[k].pairs.size() - expected.pairs.size();
    CHECK(points_of(lean[k]) == points_of(expected));
    for (const PersistencePair& p : lean[k].pairs)
      CHECK_FALSE(p.zero_length);
  }
  CHECK(dropped > 0);
  std::vector<ClassRepresentatives> classes;
  options.forward_classes = &classes;
  CHECK_THROWS_AS(compute_medusa_diagrams(cells, vertex_type, {1, 2}, options), medusa::InternalError);
}

TEST_CASE("A run's diagrams come whole medusa first, then each cell type, forward before reverse") {
  const auto cells = triangle_and_late_edge();
  const std::vector<int> sub_medusas = sub_medusa_types({1, 2});
  REQUIRE(sub_medusas == std::vector<int>{all_types, 1, 2});
  const auto diagrams = compute_medusa_diagrams(cells, {1, 1, 2, 2}, {1, 2});
  REQUIRE(diagrams.size() == 2 * sub_medusas.size());
  for (std::size_t i = 0; i < diagrams.size(); ++i) {
    CAPTURE(i);
    CHECK(diagrams[i].cell_type == sub_medusas[i / 2]);
    CHECK(diagrams[i].direction == (i % 2 == 0 ? Direction::forward : Direction::reverse));
  }
}

TEST_CASE("Each diagram is handed over once, whole and with its representatives, before its zero-length "
          "pairs go") {
  const auto cells = triangle_and_late_edge();
  const std::vector<int> vertex_type{1, 1, 2, 2};
  std::vector<ClassRepresentatives> full_classes;
  DiagramRunOptions keep;
  keep.forward_classes = &full_classes;
  const auto full = compute_medusa_diagrams(cells, vertex_type, {1, 2}, keep);
  const std::vector<std::string> names = medusa_diagram_names({1, 2});
  REQUIRE(names.size() == full.size());
  for (unsigned threads : {1u, 2u}) {
    CAPTURE(threads);
    std::vector<ClassRepresentatives> classes;
    std::vector<int> calls(full.size(), 0);
    DiagramRunOptions options;
    options.threads = threads;
    options.forward_classes = &classes;
    options.zero_length = false;
    options.on_diagram = [&](std::size_t i, Diagram& d, ClassRepresentatives* c) {
      REQUIRE(i < full.size());
      ++calls[i];
      CHECK(diagram_group_name(d) == names[i]);
      CHECK(points_of(d) == points_of(full[i])); // zero-length pairs still there
      REQUIRE((c != nullptr) == (d.direction == Direction::forward));
      if (c != nullptr) {
        CHECK(c->rows == full_classes[i].rows);
        CHECK(c->cycles == full_classes[i].cycles);
      }
    };
    const auto lean = compute_medusa_diagrams(cells, vertex_type, {1, 2}, options);
    CHECK(calls == std::vector<int>(full.size(), 1));
    REQUIRE(lean.size() == full.size());
    for (std::size_t k = 0; k < full.size(); ++k) {
      CAPTURE(k);
      Diagram expected = full[k];
      drop_zero_length(expected);
      CHECK(points_of(lean[k]) == points_of(expected));
      CHECK(classes[k].size() == 0); // their rows named pairs that are gone
    }
  }
}
