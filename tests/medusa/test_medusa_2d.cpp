// The medusa of planar runs (dimension 2) built by the kinetic engine: the store records the
// dimension, read_store's validators (d d = 0, facets, nested and disjoint lifetimes) pass, the Euler
// characteristic of M agrees with its persistence, and a 2-2 flip with R_S <= rho adds its instant
// 3-simplex (docs/MATH.md §6.3 one dimension down).
#include "kinetic/kinetic_test_support.h"
#include "kinetic_run.h"
#include "medusa/io/run_reader.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/euler.h"
#include "medusa/persistence/filtration.h"
#include "medusa_fixtures.h"

#include <catch2/catch.hpp>

#include <cstdio>

using namespace medusa;
using namespace medusa::test;

namespace {

medusa::Medusa stored(const kinetic::Trajectories& t, const std::string& radius,
                      const kinetic::SquaredRadius& rho2, const std::string& tag) {
  const std::string store = temp_path(tag + ".h5");
  run_into_store(t, radius, rho2, store, 20);
  medusa::Medusa m = medusa::read_store(store); // validates the medusa
  std::remove(store.c_str());
  return m;
}

// The real 2D CompuCell3D run (193 cells, 20 frames), from its CSV.
kinetic::Trajectories real_2d_run() {
  io::RunOptions options;
  options.source = io::RunSource::csv;
  return io::read_run(std::string(MEDUSA_TEST_DATA) + "/cc3d/sorting_2d", options).trajectories;
}

void check_euler(const medusa::Medusa& m) {
  long long chi = 0;
  for (const medusa::Cell& c : m.cells)
    chi += c.dim() % 2 == 0 ? 1 : -1;
  for (persistence::Direction d : {persistence::Direction::forward, persistence::Direction::reverse}) {
    const persistence::Filtration f = persistence::make_filtration(m.cells, d);
    const persistence::Diagram diagram = persistence::compute_diagram(m.cells, f);
    CHECK(persistence::euler_characteristic(f) == chi);
    CHECK(persistence::essential_euler_characteristic(diagram) == chi);
  }
}

} // namespace

TEST_CASE("a 2-2 flip of four cocircular cells with R_S <= rho adds an instant 3-simplex",
          "[medusa][kinetic][2d]") {
  // a = (-5,0), b = (5,0), c = (0,-5) on the circle of radius 5; d = (0, 10 - 8u) crosses it at
  // u = 5/8: the edge ab flips to cd with both old triangles in K for rho = 6 (derivation in
  // tests/kinetic/test_kinetic_engine_2d.cpp).
  kinetic::Trajectories t;
  t.dimension = 2;
  t.scale = 1;
  t.frame_times = {0, 100};
  t.cells.push_back({1, 1, 0, {{-5, 0, 0}, {-5, 0, 0}}});
  t.cells.push_back({2, 1, 0, {{5, 0, 0}, {5, 0, 0}}});
  t.cells.push_back({3, 1, 0, {{0, -5, 0}, {0, -5, 0}}});
  t.cells.push_back({4, 2, 0, {{0, 10, 0}, {0, 2, 0}}});
  kinetic::SquaredRadius rho2;
  rho2.num = 36;
  const medusa::Medusa m = stored(t, "6", rho2, "flip22");
  REQUIRE(m.input.dimension == 2);
  std::size_t flips = 0;
  for (const medusa::Cell& c : m.cells)
    if (c.kind == medusa::CellKind::flip) {
      ++flips;
      REQUIRE(c.vertices == std::vector<kinetic::VertexId>{0, 1, 2, 3});
      REQUIRE(c.birth == c.death);
      REQUIRE(c.facets.size() == 4);
      // Its facets: the old triangles abc, abd dying and the new ones acd, bcd born at the flip.
      for (medusa::CellId f : c.facets)
        REQUIRE(m.cell(f).vertices.size() == 3);
    }
  REQUIRE(flips == 1);
  REQUIRE(m.cells_of_dimension(3).size() == 1);
  check_euler(m);
}

TEST_CASE("the medusa of the real 2D sorting run records dimension 2 and passes the validators",
          "[medusa][kinetic][2d][cc3d]") {
  const kinetic::Trajectories t = first_frames(real_2d_run(), 6);
  REQUIRE(t.dimension == 2);
  const medusa::Medusa m = stored(t, "3", kinetic::squared_radius_from_decimal("3", t.scale), "sorting2d");
  REQUIRE(m.input.dimension == 2);
  REQUIRE(m.cells_of_dimension(2).size() > 0);
  REQUIRE(m.cells_of_dimension(4).empty());
  check_euler(m);
}

TEST_CASE("twelve cells becoming cocircular at one instant give a valid planar medusa",
          "[medusa][kinetic][2d]") {
  // The degenerate batch of tests/kinetic (all twelve on the circle of radius 50 at t = 50): with
  // rho = 60 the 2-2 flips inside the batch carry instant 3-simplices whose facets must exist.
  const kinetic::Trajectories t = kinetic::testing::cocircular_burst();
  kinetic::SquaredRadius rho2;
  rho2.num = 3600;
  const medusa::Medusa m = stored(t, "60", rho2, "burst2d");
  REQUIRE(m.input.dimension == 2);
  REQUIRE(m.cells_of_dimension(3).size() > 0);
  check_euler(m);
}

TEST_CASE("in a planar run's forward filtration every finite H2 class has zero length",
          "[medusa][persistence][2d][cc3d]") {
  // docs/MATH.md §7.6's argument for H3 in 3D, one dimension down: the medusa of a planar run lives in
  // space-time R^3, where H2 classes are bounded components of the complement (Alexander duality). A
  // bounded component of the complement of M_{<=s} lies at times < s and stays bounded when later
  // cells are added, so a class of positive length never dies: H2 classes are bubbles of space-time
  // (a hole that opened inside the tissue and closed again, born when it closes), all essential or
  // on the diagonal. The summary of `medusa run` names them so (run_summary.cpp).
  const kinetic::Trajectories t = real_2d_run();
  REQUIRE(t.dimension == 2);
  const medusa::Medusa m = stored(t, "3", kinetic::squared_radius_from_decimal("3", t.scale), "sorting2d_h2");
  const persistence::Filtration f = persistence::make_filtration(m.cells, persistence::Direction::forward);
  const persistence::Diagram d = persistence::compute_diagram(m.cells, f);
  std::size_t essential = 0, finite = 0, positive = 0;
  for (const persistence::PersistencePair& p : d.pairs) {
    if (p.dim != 2)
      continue;
    if (p.essential) {
      ++essential;
      continue;
    }
    ++finite;
    positive += p.zero_length ? 0 : 1;
  }
  CAPTURE(essential, finite);
  REQUIRE(essential > 0); // the run has bubbles, so the statement is not vacuous
  CHECK(positive == 0);
}
