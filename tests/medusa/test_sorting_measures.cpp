// The sorting measures of docs/MATH.md §6.9 on a hand-made medusa whose values are worked out below.
#include "medusa/medusa/sorting_measures.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace medusa;

namespace {

// Cells 0, 1 of type 1 and 2, 3 of type 2. From batch 0: edges 01, 12, 23; at batch 1 edges 12 and
// 23 leave and edge 03 enters (and edge 13 lives inside batch 1 only); the run ends at batch 2.
Medusa four_cells() {
  Medusa m;
  for (int type : {1, 1, 2, 2}) {
    kinetic::Trajectory t;
    t.type = type;
    m.input.cells.push_back(t);
  }
  m.batches = {{0, 0, 0.0, 0.0, true, 0}, {1, 0, 0.5, 5.0, false, 2}};
  m.end = {2, 0, 10.0};
  auto add = [&](std::vector<VertexId> v, std::vector<CellId> facets, VirtualTime birth, VirtualTime death) {
    Cell c;
    c.id = m.cells.size();
    c.vertices = std::move(v);
    c.facets.assign(facets.begin(), facets.end());
    c.birth = birth;
    c.death = death;
    m.cells.push_back(c);
  };
  const VirtualTime t0{0, 0, 0.0}, t1{1, 1, 5.0}, t1b{1, 2, 5.0};
  for (VertexId v = 0; v < 4; ++v)
    add({v}, {}, t0, m.end);
  add({0, 1}, {1, 0}, t0, m.end);
  add({1, 2}, {2, 1}, t0, t1);
  add({2, 3}, {3, 2}, t0, t1);
  add({0, 3}, {3, 0}, t1, m.end);
  add({1, 3}, {3, 1}, t1, t1b);
  return m;
}

} // namespace

TEST_CASE("sorting measures count contacts, same-type neighbours and clusters of every slice",
          "[medusa][sorting]") {
  const std::vector<SortingSample> s = sorting_over_time(four_cells());
  REQUIRE(s.size() == 3); // K(0+), K(1+), K(t_end-)
  CHECK(s[0].time == 0.0);
  CHECK(s[2].before);

  // K(0+): edges 01, 12, 23.
  const SortingMeasures& all0 = s[0].measures[0];
  CHECK(!all0.type);
  CHECK(all0.cells == 4);
  CHECK(all0.edges == 3);
  CHECK(all0.heterotypic_edges == 1);
  CHECK(all0.heterotypic_fraction() == 1.0 / 3.0);
  CHECK(all0.same_type_fraction == 0.75); // (1 + 1/2 + 1/2 + 1) / 4
  CHECK(all0.clusters == 1);
  CHECK(all0.largest_cluster == 4);
  const SortingMeasures& one0 = s[0].measures[1];
  CHECK(one0.type == 1);
  CHECK(one0.edges == 2); // 01, 12
  CHECK(one0.heterotypic_fraction() == 0.5);
  CHECK(one0.same_type_fraction == 0.75);
  CHECK(one0.clusters == 1);
  CHECK(one0.largest_cluster == 2);

  // K(1+) and K(t_end-): edges 01, 03; cell 2 alone.
  for (std::size_t k : {1u, 2u}) {
    CAPTURE(k);
    const SortingMeasures &all = s[k].measures[0], &one = s[k].measures[1], &two = s[k].measures[2];
    CHECK(all.edges == 2);
    CHECK(all.heterotypic_fraction() == 0.5);
    CHECK(all.cells_with_neighbours == 3);
    CHECK(all.same_type_fraction == 0.5); // (1/2 + 1 + 0) / 3
    CHECK(all.clusters == 2);
    CHECK(all.largest_cluster == 3);
    CHECK(all.mean_cluster_size() == 2.0);
    CHECK(one.same_type_fraction == 0.75);
    CHECK(one.clusters == 1);
    CHECK(two.type == 2);
    CHECK(two.cells == 2);
    CHECK(two.edges == 1);
    CHECK(two.heterotypic_fraction() == 1.0);
    CHECK(two.cells_with_neighbours == 1);
    CHECK(two.same_type_fraction == 0.0);
    CHECK(two.clusters == 2);
    CHECK(two.largest_cluster == 1);
    CHECK(two.mean_cluster_size() == 1.0);
  }
}

TEST_CASE("sorting measures without contacts have no fractions", "[medusa][sorting]") {
  Medusa m;
  kinetic::Trajectory t;
  t.type = 1;
  m.input.cells = {t};
  m.batches = {{0, 0, 0.0, 0.0, true, 0}};
  m.end = {1, 0, 1.0};
  Cell v;
  v.vertices.push_back(0);
  v.death = m.end;
  m.cells = {v};
  const std::vector<SortingSample> s = sorting_over_time(m);
  REQUIRE(s.size() == 2);
  CHECK(std::isnan(s[0].measures[0].heterotypic_fraction()));
  CHECK(std::isnan(s[0].measures[1].same_type_fraction));
  CHECK(s[0].measures[1].clusters == 1);
  CHECK(s[0].measures[1].largest_cluster == 1);
}

TEST_CASE("the same-type fraction stays accurate with a cell of a hundred neighbours", "[medusa][sorting]") {
  // A star: cell 0 (type 1) touches cells 1..100, of type 1 when even. The exact sum in units of
  // 1/lcm(1..100) would not fit, so the per-type histogram is used.
  Medusa m;
  m.batches = {{0, 0, 0.0, 0.0, true, 0}};
  m.end = {1, 0, 1.0};
  for (VertexId v = 0; v <= 100; ++v) {
    kinetic::Trajectory t;
    t.type = v == 0 || v % 2 == 0 ? 1 : 2;
    m.input.cells.push_back(t);
    Cell c;
    c.id = m.cells.size();
    c.vertices.push_back(v);
    c.death = m.end;
    m.cells.push_back(c);
  }
  for (VertexId v = 1; v <= 100; ++v) {
    Cell c;
    c.id = m.cells.size();
    c.vertices.push_back(0);
    c.vertices.push_back(v);
    c.facets = {static_cast<std::uint32_t>(v), 0};
    c.death = m.end;
    m.cells.push_back(c);
  }
  const std::vector<SortingSample> s = sorting_over_time(m);
  REQUIRE(s.size() == 2);
  const SortingMeasures &all = s[0].measures[0], &one = s[0].measures[1], &two = s[0].measures[2];
  CHECK(all.same_type_fraction == (0.5 + 50.0) / 101.0);
  CHECK(one.cells == 51);
  CHECK(one.same_type_fraction == Approx((0.5 + 50.0) / 51.0).epsilon(1e-15));
  CHECK(two.same_type_fraction == 0.0);
  CHECK(all.heterotypic_fraction() == 0.5);
  CHECK(one.clusters == 1);
  CHECK(one.largest_cluster == 51);
  CHECK(two.clusters == 50);
}
