// The medusa of runs with static repairs at cospherical (3D) or cocircular (2D) moments: the instant
// cells of the repair's degenerate groups (docs/MATH.md §6.3) are present, d d = 0 (6.4), and the homology
// is that of the space-time body (6.1), derived on paper.
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/homology.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/store_reader.h"
#include "support/planar_repair_run.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <vector>

using namespace medusa;

namespace {

// The same box as in tests/kinetic/test_kinetic_degenerate_groups.cpp: side 20, top face sliding in x
// by delta per frame, exactly a cube when delta = 0 (vertex ids 0..7, z-major).
kinetic::Trajectories sheared_cube(const std::vector<std::int64_t>& deltas) {
  kinetic::Trajectories t;
  t.scale = 1;
  for (std::size_t k = 0; k < deltas.size(); ++k)
    t.frame_times.push_back(100 * static_cast<std::int64_t>(k));
  std::int64_t id = 1;
  for (std::int64_t z : {0, 20})
    for (std::int64_t y : {0, 20})
      for (std::int64_t x : {0, 20}) {
        kinetic::Trajectory c;
        c.cell_id = id++;
        c.type = 1;
        for (std::int64_t d : deltas)
          c.positions.push_back(kinetic::GridPoint{x + (z ? d : 0), y, z});
        t.cells.push_back(c);
      }
  return t;
}

// The square pyramid of tests/kinetic/test_kinetic_degenerate_groups.cpp: base (0,0,0), (20,0,0),
// (20,20,0) and (delta,20,0) with delta from -6 to 6, apex (10,10,20); cospherical at u = 1/2.
kinetic::Trajectories pyramid() {
  kinetic::Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100};
  auto still = [&](std::int64_t id, kinetic::GridPoint p) { t.cells.push_back({id, 1, 0, {p, p}}); };
  still(1, {0, 0, 0});
  still(2, {20, 0, 0});
  still(3, {20, 20, 0});
  t.cells.push_back({4, 1, 0, {{-6, 20, 0}, {6, 20, 0}}});
  still(5, {10, 10, 20});
  return t;
}

// The planar run of tests/support/planar_repair_run.h: p1 p2 p3 and p1 p3 e are removed, e p2 p3
// and p1 e p2 created (p2 p3 p4 stays).
using medusa::test::planar_repair_with_pentagon;

// Forwards the stream, optionally without the degenerate groups (to show what they fill).
class Forward : public kinetic::Observer {
public:
  Forward(kinetic::Observer& next, bool drop_groups) : next_(next), drop_(drop_groups) {}
  void initial(const kinetic::EventTime& t0, const std::vector<kinetic::Simplex>& k) override {
    next_.initial(t0, k);
  }
  void batch(const kinetic::EventTime& time, const std::vector<kinetic::Step>& steps) override {
    std::vector<kinetic::Step> copy = steps;
    for (kinetic::Step& s : copy) {
      groups += s.groups.size();
      if (drop_)
        s.groups.clear();
    }
    next_.batch(time, copy);
  }
  void frame(std::size_t k, const kinetic::EventTime& time) override { next_.frame(k, time); }
  void finish(const kinetic::EventTime& t_end) override { next_.finish(t_end); }
  std::size_t groups = 0;

private:
  kinetic::Observer& next_;
  bool drop_;
};

medusa::Medusa build(const kinetic::Trajectories& t, long rho2, bool drop_groups, std::size_t& groups) {
  kinetic::KineticOptions options;
  options.rho2.num = rho2;
  options.audit = true;
  kinetic::KineticAlphaComplex engine(t, options);
  medusa::MedusaCollector collector;
  medusa::MedusaBuilder builder(collector);
  medusa::RunInfo info;
  info.radius_text = std::to_string(rho2) + " (squared)";
  builder.set_run(info, t);
  Forward forward(builder, drop_groups);
  engine.run(forward);
  groups = forward.groups;
  return collector.take();
}

void check_boundary_of_boundary(const medusa::Medusa& m) {
  for (const medusa::Cell& c : m.cells) {
    std::map<medusa::CellId, int> parity;
    for (medusa::CellId f : c.facets)
      for (medusa::CellId g : m.cell(f).facets)
        parity[g] ^= 1;
    for (const auto& [g, p] : parity) {
      CAPTURE(c.id, g);
      REQUIRE(p == 0);
    }
  }
}

std::vector<std::size_t> betti(const medusa::Medusa& m) {
  medusa::ChainComplex cc;
  for (const medusa::Cell& c : m.cells) {
    cc.add(c.dim(), c.facets);
  }
  return medusa::betti_numbers(cc);
}

} // namespace

TEST_CASE("the medusa of a box sheared through a cube holds the cube's instant cells and is acyclic",
          "[medusa][kinetic][groups]") {
  // rho^2 = 10^4 (rho = 100) exceeds every circumradius of the eight cells (all within distance 36):
  // K(t) is the whole Delaunay triangulation at every t, a 3-ball, the union of balls is contractible
  // at every t and the space-time body (M is homotopy equivalent to it, docs/MATH.md §6.1) is contractible:
  // beta = (1, 0, 0, ...). At the cube instant the repair replaces one triangulation of the box by
  // another; the group {0..7} (R^2 = 300 <= rho^2) adds the 7-simplex and every subset of the eight
  // cells in neither triangulation as instant repair cells, which fill the 3-cycle formed by the two
  // triangulations alive together at that rank.
  const std::vector<std::int64_t> deltas =
      GENERATE(std::vector<std::int64_t>{-6, 6}, std::vector<std::int64_t>{-6, 0, 6});
  CAPTURE(deltas);
  std::size_t groups = 0;
  const medusa::Medusa m = build(sheared_cube(deltas), 10000, false, groups);
  REQUIRE(groups == 7); // the cube and its six square faces
  medusa::validate_medusa(m, "sheared cube");
  check_boundary_of_boundary(m);
  bool seven_simplex = false;
  std::set<std::vector<kinetic::VertexId>> repaired;
  std::optional<medusa::VirtualTime> at;
  for (const medusa::Cell& c : m.cells)
    if (c.kind == medusa::CellKind::repair) {
      REQUIRE(c.birth == c.death);
      REQUIRE((!at || *at == c.birth)); // one repair, at one rank
      at = c.birth;
      REQUIRE(repaired.insert(c.vertices.to_vector()).second);
      seven_simplex = seven_simplex || c.vertices == std::vector<kinetic::VertexId>{0, 1, 2, 3, 4, 5, 6, 7};
    }
  REQUIRE(seven_simplex);
  // All 2^8 - 1 subsets of the cube are cells at the repair's rank, each once: alive in K (in the old
  // or the new triangulation, whose closed lifetimes both hold that rank) or instant.
  std::set<std::vector<kinetic::VertexId>> alive;
  for (const medusa::Cell& c : m.cells)
    if (c.kind == medusa::CellKind::regular && c.birth <= *at && *at <= c.death) {
      REQUIRE(repaired.count(c.vertices.to_vector()) == 0);
      alive.insert(c.vertices.to_vector());
    }
  CAPTURE(repaired.size(), alive.size());
  REQUIRE(repaired.size() + alive.size() == 255);
  const std::vector<std::size_t> b = betti(m);
  CAPTURE(b);
  REQUIRE(b.at(0) == 1);
  for (std::size_t k = 1; k < b.size(); ++k)
    REQUIRE(b[k] == 0);

  // Without the groups the two triangulations of the box, both alive at the repair's rank, are not
  // filled by any cell of dimension >= 4 (there are no flips): a spurious class.
  std::size_t dropped = 0;
  const medusa::Medusa without = build(sheared_cube(deltas), 10000, true, dropped);
  check_boundary_of_boundary(without);
  const std::vector<std::size_t> bw = betti(without);
  CAPTURE(bw);
  std::size_t higher = 0;
  for (std::size_t k = 1; k < bw.size(); ++k)
    higher += bw[k];
  REQUIRE(higher > 0);
}

TEST_CASE("the medusa of a box sheared through a cube keeps d d = 0 for radii around the groups' g",
          "[medusa][kinetic][groups]") {
  // rho^2 = 301 (cube and faces), 250 (faces only), 150 (no group): the builder's repair cells and
  // the regular cells form a valid complex in every case.
  const long rho2 = GENERATE(301L, 250L, 150L);
  CAPTURE(rho2);
  std::size_t groups = 0;
  const medusa::Medusa m = build(sheared_cube({-6, 6}), rho2, false, groups);
  REQUIRE(groups == (rho2 >= 300 ? 7u : rho2 >= 200 ? 6u : 0u));
  medusa::validate_medusa(m, "sheared cube");
  check_boundary_of_boundary(m);
  const std::vector<std::size_t> b = betti(m);
  CAPTURE(b);
  REQUIRE(b.at(0) == 1);
}

TEST_CASE("the medusa of a square pyramid through a cospherical moment holds its 4-simplex and is acyclic",
          "[medusa][kinetic][groups]") {
  // rho^2 = 10^4: K(t) is the whole triangulation (two tetrahedra) at every t, the body is
  // contractible, beta(M) = (1, 0, ...). The repair at u = 1/2 swaps the base diagonal; the groups are
  // the five points (R^2 = 225) and the base (R^2 = 200). The two triangulations together hold all
  // 10 edges and 10 triangles of the five points and 4 of the 5 tetrahedra, so the instant cells are
  // exactly the flat base 3-simplex abcd and the 4-simplex abcde. (Here the two triangulations alone
  // would leave no hole: they share the cone over the base boundary, a disc, so their union is
  // contractible; the instant cells must keep it so.)
  std::size_t groups = 0;
  const medusa::Medusa m = build(pyramid(), 10000, false, groups);
  REQUIRE(groups == 2);
  medusa::validate_medusa(m, "pyramid");
  check_boundary_of_boundary(m);
  std::vector<std::vector<kinetic::VertexId>> instants;
  for (const medusa::Cell& c : m.cells)
    if (c.kind == medusa::CellKind::repair)
      instants.push_back(c.vertices.to_vector());
  std::sort(instants.begin(), instants.end());
  REQUIRE(instants == std::vector<std::vector<kinetic::VertexId>>{{0, 1, 2, 3}, {0, 1, 2, 3, 4}});
  const std::vector<std::size_t> b = betti(m);
  CAPTURE(b);
  REQUIRE(b.at(0) == 1);
  for (std::size_t k = 1; k < b.size(); ++k)
    REQUIRE(b[k] == 0);
}

TEST_CASE("the medusa of a planar repair through five cocircular cells holds the pentagon's instant cells",
          "[medusa][kinetic][groups][2d]") {
  // rho^2 = 26 >= g = 25: the pentagon {0..4} is the repair's group. Every simplex of the pentagon that
  // is Delaunay on either side of the repair has R <= 5 < rho and is in K there (the triangles are
  // short top simplices, the edges their faces), so the instant cells are exactly the subsets of
  // {0..4} in neither triangulation (docs/MATH.md §6.3): the two edges p1 p4 = {0,3} and p4 e = {3,4}; of
  // the ten triangles, the five other than p1 p2 p3, p2 p3 p4, p1 p3 e, e p2 p3, p1 e p2; all five
  // 3-simplices and the 4-simplex: 13 cells, all instant.
  const kinetic::Trajectories t = planar_repair_with_pentagon();
  std::size_t groups = 0;
  const medusa::Medusa m = build(t, 26, false, groups);
  REQUIRE(groups == 1);
  medusa::validate_medusa(m, "planar pentagon");
  check_boundary_of_boundary(m);
  std::vector<std::vector<kinetic::VertexId>> instants;
  for (const medusa::Cell& c : m.cells)
    if (c.kind == medusa::CellKind::repair) {
      REQUIRE(c.birth == c.death);
      instants.push_back(c.vertices.to_vector());
    }
  std::sort(instants.begin(), instants.end());
  const std::vector<std::vector<kinetic::VertexId>> expected = {
      {0, 1, 2, 3}, {0, 1, 2, 3, 4}, {0, 1, 2, 4}, {0, 1, 3}, {0, 1, 3, 4}, {0, 2, 3}, {0, 2, 3, 4},
      {0, 3},       {0, 3, 4},       {1, 2, 3, 4}, {1, 3, 4}, {2, 3, 4},    {3, 4}};
  REQUIRE(instants == expected);
  const std::vector<std::size_t> b = betti(m);
  CAPTURE(b);

  // Without the group the two triangulations of the quadrilateral p1 p2 e p3 (p1 p3 versus p2 e as
  // diagonal), both alive at the repair's rank and sharing their boundary, form a 2-sphere that no
  // cell fills: one spurious class more, in degree 2.
  std::size_t dropped = 0;
  const medusa::Medusa without = build(t, 26, true, dropped);
  check_boundary_of_boundary(without);
  const std::vector<std::size_t> bw = betti(without);
  CAPTURE(bw);
  REQUIRE(b.at(0) == bw.at(0));
  std::size_t higher = 0, higher_without = 0;
  for (std::size_t k = 1; k < b.size(); ++k)
    higher += b[k];
  for (std::size_t k = 1; k < bw.size(); ++k)
    higher_without += bw[k];
  REQUIRE(higher_without == higher + 1);
  REQUIRE(bw.at(2) == b.at(2) + 1);
}

TEST_CASE("the medusa of a planar repair with rho below the pentagon's radius has no repair cell",
          "[medusa][kinetic][groups][2d]") {
  // rho^2 = 24 < g = 25: no group, so no instant repair cell, and the medusa is still valid.
  const kinetic::Trajectories t = planar_repair_with_pentagon();
  std::size_t groups = 0;
  const medusa::Medusa m = build(t, 24, false, groups);
  REQUIRE(groups == 0);
  medusa::validate_medusa(m, "planar pentagon");
  check_boundary_of_boundary(m);
  for (const medusa::Cell& c : m.cells)
    REQUIRE(c.kind != medusa::CellKind::repair);
}
