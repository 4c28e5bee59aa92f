// The kinetic engine with the audit on: hand-built cases derived on paper, then randomised runs
// whose every batch is audited against CGAL's static Delaunay_triangulation_3 + Fixed_alpha_shape_3.
#include "kinetic_test_support.h"
#include "medusa/core/error.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace medusa::kinetic;
using medusa::kinetic::testing::built_by_formula;
using medusa::kinetic::testing::FormulaCounts;
using medusa::kinetic::testing::ReplayObserver;
using medusa::kinetic::testing::reported_time_error;

namespace {

// Cells standing still or moving, over the given frames (grid scale 1).
Trajectories spatial(std::vector<std::int64_t> frame_times) {
  Trajectories t;
  t.scale = 1;
  t.frame_times = std::move(frame_times);
  return t;
}

void still(Trajectories& t, std::int64_t id, GridPoint p) {
  t.cells.push_back({id, 1, 0, std::vector<GridPoint>(t.frames(), p)});
}

Trajectories appendix_b() {
  // docs/MATH.md §B: a, b, c on x^2 + y^2 = 25, d above, e moving through the sphere.
  Trajectories t = spatial({0, 100});
  still(t, 1, {5, 0, 0});
  still(t, 2, {-3, 4, 0});
  still(t, 3, {-3, -4, 0});
  still(t, 4, {0, 0, 10});
  t.cells.push_back({5, 2, 0, {{-2, 1, -6}, {2, 1, -2}}});
  return t;
}

// A 4x4x4 lattice of the given spacing (every lattice cube cospherical at t0) over four frames 100
// apart, each cell stepping uniformly in [-step, step] per coordinate and frame.
Trajectories jittered_lattice(std::uint64_t seed, std::int64_t spacing, std::int64_t step) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> d(-step, step);
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100, 200, 300};
  int id = 1;
  for (std::int64_t x = 0; x < 4; ++x)
    for (std::int64_t y = 0; y < 4; ++y)
      for (std::int64_t z = 0; z < 4; ++z) {
        Trajectory c;
        c.cell_id = id++;
        c.type = 1;
        GridPoint p{spacing * x, spacing * y, spacing * z};
        for (int k = 0; k < 4; ++k) {
          c.positions.push_back(p);
          for (auto& v : p)
            v += d(rng);
        }
        t.cells.push_back(c);
      }
  return t;
}

KineticOptions with_radius(long rho2, bool audit = true) {
  KineticOptions o;
  o.rho2.num = rho2;
  o.audit = audit;
  return o;
}

} // namespace

TEST_CASE("the worked example flips abc into de at u* = (47 - sqrt 257)/32 with a 4-simplex",
          "[kinetic][engine]") {
  Trajectories t = appendix_b();
  KineticAlphaComplex engine(t, with_radius(49));
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  REQUIRE(s.flips23 == 1);
  REQUIRE(s.flips32 == 0);
  REQUIRE(obs.flips_in_alpha == 1);
  REQUIRE(obs.times.size() == 1);
  REQUIRE(obs.times[0] == Approx(100 * (47 - std::sqrt(257.0)) / 32).epsilon(0).margin(reported_time_error));
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  // After the flip: edge de (vertex ids 3, 4) is in K and triangle abc (0, 1, 2) is not.
  REQUIRE(obs.complex().count(Simplex{3, 4}) == 1);
  REQUIRE(obs.complex().count(Simplex{0, 1, 2}) == 0);
  REQUIRE(obs.complex().count(Simplex{0, 3, 4}) == 1);
  REQUIRE(obs.complex().size() == 5 + 10 + 9 + 3); // all but abc, abcd, abce; plus de, 3 triangles, 3 tets
}

TEST_CASE("with rho = 6 the worked example's flip adds no 4-simplex", "[kinetic][engine]") {
  Trajectories t = appendix_b();
  KineticAlphaComplex engine(t, with_radius(36));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().flips23 == 1);
  REQUIRE(obs.flips_in_alpha == 0);
  REQUIRE(obs.mismatches == 0);
}

TEST_CASE("two cells approaching make their edge short exactly at the predicted time", "[kinetic][engine]") {
  // Four fixed cells far apart and one cell moving towards cell 1 at (0,0,0) from (40,0,0) to
  // (10,0,0) over [0, 100]: |pq| = 40 - 30u; with rho = 10 the edge is short when |pq| <= 20, so at
  // u = 2/3, t = 200/3.
  Trajectories t = spatial({0, 100});
  still(t, 1, {0, 0, 0});
  still(t, 2, {0, 100, 3});
  still(t, 3, {-7, -100, 5});
  still(t, 4, {1, 2, 100});
  t.cells.push_back({5, 1, 0, {{40, 0, 0}, {10, 0, 0}}});
  KineticAlphaComplex engine(t, with_radius(100));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().radius_events >= 1);
  REQUIRE(!obs.times.empty());
  REQUIRE(obs.times.front() == Approx(200.0 / 3).epsilon(0).margin(reported_time_error));
  REQUIRE(obs.complex().count(Simplex{0, 4}) == 1);
  REQUIRE(obs.mismatches == 0);
}

TEST_CASE("random walks keep the audit green between every pair of events", "[kinetic][engine][random]") {
  // Coordinates on a fine grid (spacing 1000 units per cell diameter) so that no four cells stay
  // coplanar through a slab by chance; audit after every batch for the small runs, sampled for the
  // large ones (the CGAL oracle is exact and costly).
  auto [seed, n, frames, stride] = GENERATE(table<std::uint64_t, int, int, int>(
      {{1, 20, 10, 1}, {2, 40, 5, 1}, {3, 60, 4, 4}, {5, 30, 20, 10}, {4, 200, 2, 200}}));
  CAPTURE(seed, n, frames, stride);
  const int box = static_cast<int>(1000 * std::cbrt(double(n)) * 2);
  Trajectories t = testing::random_walk(seed, n, frames, box, 600);
  KineticOptions options = with_radius(1200 * 1200);
  options.audit_stride = static_cast<std::size_t>(stride);
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.flips23, s.flips32, s.hull_flips, s.radius_events, s.audits, s.audits_compared_with_cgal,
          s.sign_evaluations_exact, s.exact_settled);
  REQUIRE(s.flips23 + s.flips32 > 0);
  REQUIRE(s.radius_events > 0);
  REQUIRE(s.audits_compared_with_cgal > 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
}

TEST_CASE("cells on an integer lattice start from the triangulation just after t0",
          "[kinetic][engine][degenerate]") {
  // A 4x4x4 lattice (every cube cospherical) with small random steps: the audit checks Del(t0+).
  // Steps are large against the lattice spacing (10000) so no degeneracy survives past t0.
  const std::uint64_t seed = 11;
  CAPTURE(seed);
  Trajectories t = jittered_lattice(seed, 10000, 2000);
  KineticAlphaComplex engine(t, with_radius(7000 * 7000));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(engine.statistics().audits > 0);
  REQUIRE(engine.statistics().audits_compared_with_cgal > 0);
}

TEST_CASE("a CC3D-sized lattice settles every certificate without the exact polynomial",
          "[kinetic][engine][degenerate][filter]") {
  // CC3D's initial layout on the 10^-6 grid: centres 5 pixels = 5,000,000 units apart, where the
  // interval enclosures of the in-sphere determinants of lattice cubes straddle zero at t0. Those
  // vanish exactly there; one exact static determinant shows it and the rest is settled in doubles
  // (docs/MATH.md §5.5). The flips install certificates on the flipped points at the flip time, which the
  // failed certificate's isolated root settles in doubles too.
  const std::uint64_t seed = 12;
  CAPTURE(seed);
  Trajectories t = jittered_lattice(seed, 5000000, 2000000);
  KineticOptions options = with_radius(3500000L * 3500000L);
  options.audit_stride = 25;
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.certificates_built, s.start_zero_settled, s.start_zero_tests, s.exact_settled, s.flips23,
          s.flips32, s.hull_flips, s.sign_evaluations, s.sign_evaluations_exact);
  REQUIRE(s.start_zero_settled > 0);
  REQUIRE(s.flips23 + s.flips32 > 0);
  // Left to the exact polynomial: those vanishing to second order at t0 (three collinear hull points
  // in an orientation), at most 1% (docs/MATH.md §3.8).
  REQUIRE(s.exact_settled * 100 <= s.certificates_built);
  REQUIRE(s.audits_compared_with_cgal > 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
}

TEST_CASE("stationary cells on a lattice produce no events", "[kinetic][engine][degenerate]") {
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100, 200};
  int id = 1;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) {
        GridPoint p{5 * x, 5 * y, 5 * z};
        t.cells.push_back({id++, 1, 0, {p, p, p}});
      }
  KineticAlphaComplex engine(t, with_radius(9));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().batches == 0);
  // rho = 3: axis edges (length 5, R = 2.5) are short and Gabriel; face diagonals (R = 3.54) and
  // everything larger are long. K = 27 vertices + 3 * 2 * 3 * 3 = 54 axis edges.
  REQUIRE(obs.complex().size() == 27 + 54);
}

TEST_CASE("cells in one plane are reported clearly, never a crash", "[kinetic][engine]") {
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100};
  for (int i = 0; i < 6; ++i)
    t.cells.push_back({i + 1, 1, 0, {{i * 3, (i * i) % 7, 0}, {i * 3 + 1, (i * i) % 7, 0}}});
  Observer none;
  KineticAlphaComplex first(t, with_radius(16));
  REQUIRE_THROWS_AS(first.run(none), medusa::GeometryError);
  KineticAlphaComplex second(t, with_radius(16));
  REQUIRE_THROWS_WITH(second.run(none), Catch::Contains("all cells lie in one plane at frame 0 (MCS 0)"));
}

TEST_CASE("colliding cells are an error naming both cells and the time", "[kinetic][engine]") {
  Trajectories t = appendix_b();
  t.cells.push_back({6, 1, 0, {{20, 20, 20}, {-20, -20, -20}}});
  t.cells.push_back({7, 1, 0, {{-20, -20, -20}, {20, 20, 20}}});
  Observer none;
  KineticAlphaComplex first(t, with_radius(49));
  REQUIRE_THROWS_AS(first.run(none), medusa::GeometryError);
  KineticAlphaComplex second(t, with_radius(49));
  REQUIRE_THROWS_WITH(second.run(none),
                      Catch::Contains("6") && Catch::Contains("7") && Catch::Contains("50"));
}

TEST_CASE("cells meeting along one axis at a third of the slab are an error at that time",
          "[kinetic][engine]") {
  // d = p8 - p9 = (30, 0, 0) - u (90, 0, 0) vanishes at u = 1/3, time 100/3; y and z agree throughout.
  Trajectories t = appendix_b();
  t.cells.push_back({8, 1, 0, {{100, 7, 9}, {40, 7, 9}}});
  t.cells.push_back({9, 2, 0, {{70, 7, 9}, {100, 7, 9}}});
  Observer none;
  KineticAlphaComplex engine(t, with_radius(49));
  REQUIRE_THROWS_WITH(engine.run(none), Catch::Contains("cells 8 and 9 collide at time 33.3"));
}

TEST_CASE("of two collisions foretold at a frame, the earlier one is reported", "[kinetic][engine]") {
  // Two pairs, each alone on a line far from the rest, each joined by a Delaunay edge: 8 and 9 meet
  // at u = 1/3 of the slab; 10 and 11 at u = 1/2 (d = -40 + 80u) or at u = 1/4 (d = -40 + 160u).
  // In the first slab (edges made by the first triangulation) or in the second (edges already there
  // at the frame), starting at 0 or 100.
  for (const bool later_slab : {false, true})
    for (const bool second_first : {false, true}) {
      CAPTURE(later_slab, second_first);
      Trajectories t = appendix_b();
      const auto path = [&](GridPoint from, GridPoint to) {
        return later_slab ? std::vector<GridPoint>{from, from, to} : std::vector<GridPoint>{from, to};
      };
      if (later_slab) {
        t.frame_times.push_back(200);
        for (Trajectory& c : t.cells)
          c.positions.push_back(c.positions.back());
      }
      t.cells.push_back({8, 1, 0, path({100, 7, 9}, {40, 7, 9})});
      t.cells.push_back({9, 2, 0, path({70, 7, 9}, {100, 7, 9})});
      t.cells.push_back({10, 1, 0, path({-100, -7, -9}, {second_first ? -60 : -40, -7, -9})});
      t.cells.push_back({11, 2, 0, path({-60, -7, -9}, {second_first ? -180 : -80, -7, -9})});
      Observer none;
      KineticAlphaComplex engine(t, with_radius(49));
      const std::string start = later_slab ? "1" : "";
      REQUIRE_THROWS_WITH(engine.run(none),
                          Catch::Contains(second_first ? "cells 10 and 11 collide at time " + start + "25"
                                                       : "cells 8 and 9 collide at time " + start + "33.3"));
    }
}

TEST_CASE("cells crossing each coordinate at different times do not collide", "[kinetic][engine]") {
  // d = (30, -20, 0) + u (-90, 80, 0): x vanishes at u = 1/3 and y at u = 1/4, never both, and the
  // reverse motion is the same near miss seen from the other cell.
  Trajectories t = appendix_b();
  t.cells.push_back({8, 1, 0, {{100, 7, 9}, {40, 67, 9}}});
  t.cells.push_back({9, 2, 0, {{70, 27, 9}, {100, 7, 9}}});
  Observer none;
  KineticAlphaComplex engine(t, with_radius(49));
  REQUIRE_NOTHROW(engine.run(none));
  REQUIRE(engine.statistics().audits > 0);
}

TEST_CASE("an event closer to a frame than the static build's first delta happens at its own time",
          "[kinetic][engine][degenerate]") {
  // a, b, c, d on the sphere |x| = 5; e waits at (0, -5, 3) through slab 0, then runs up x = 0, z = 3
  // at 2^26 per slab and crosses that sphere at y = -4 and y = 4: u = 2^-26 and 9 * 2^-26 of slab 1.
  // Cell f, born far away at frame 1, makes the engine rebuild Del statically there. CGAL's first
  // triangulation is built at delta = 2^-24 after the frame (docs/MATH.md §5.5, method A), where e is
  // inside the sphere: not Del(t1+), so it is built again with a smaller delta. The frame batch is
  // then the insertion alone (no flip of a, b, c, d, e and back, no instant 4-simplex), and the
  // five points flip at u = 2^-26 and back at 9 * 2^-26, exactly.
  Trajectories t = spatial({0, 100, 200});
  still(t, 1, {-5, 0, 0});
  still(t, 2, {5, 0, 0});
  still(t, 3, {0, 5, 0});
  still(t, 4, {0, 0, 5});
  const std::int64_t v = std::int64_t(1) << 26;
  t.cells.push_back({5, 2, 0, {{0, -5, 3}, {0, -5, 3}, {0, -5 + v, 3}}});
  t.cells.push_back({6, 2, 1, {{-50, 60, 6}, {-50, 60, 6}}});
  KineticAlphaComplex engine(t, with_radius(100));
  ReplayObserver obs(engine);
  testing::BatchRecorder log;
  testing::TeeObserver both(obs, log);
  engine.run(both);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(engine.statistics().audits_compared_with_cgal > 0);
  REQUIRE(log.batches.size() >= 3);
  const auto& [frame, at_frame] = log.batches[0];
  REQUIRE(frame.at_frame);
  REQUIRE(frame.slab == 1);
  REQUIRE(at_frame.size() == 1);
  REQUIRE(at_frame.front().kind == StepKind::insertion);
  REQUIRE(at_frame.front().vertex == 5);
  const auto& [time, steps] = log.batches[1];
  REQUIRE(time.slab == 1);
  REQUIRE(time.u == std::ldexp(1.0, -26));
  REQUIRE(steps.size() == 1);
  REQUIRE(steps.front().flip);
  REQUIRE(steps.front().flip->vertices == std::vector<VertexId>{0, 1, 2, 3, 4});
  // e leaves the sphere at y = 4: the same five points flip back to a, b, c, d's tetrahedron.
  const auto back = std::find_if(log.batches.begin(), log.batches.end(),
                                 [](const auto& b) { return b.first.u == 9 * std::ldexp(1.0, -26); });
  REQUIRE(back != log.batches.end());
  REQUIRE(back->second.front().flip);
  REQUIRE(back->second.front().flip->vertices == std::vector<VertexId>{0, 1, 2, 3, 4});
  REQUIRE(std::count(back->second.front().delaunay_created.begin(),
                     back->second.front().delaunay_created.end(), Simplex{0, 1, 2, 3}) == 1);
}

TEST_CASE("cells inserted and deleted in the middle of a run keep the audit green", "[kinetic][engine]") {
  Trajectories t = testing::random_walk(21, 40, 8, 50, 5);
  // Cell 41 appears at frame 3; cell 1 disappears after frame 4.
  Trajectory born;
  born.cell_id = 41;
  born.type = 2;
  born.first_frame = 3;
  for (int k = 3; k < 8; ++k)
    born.positions.push_back({25 + k, 26, 27 - k});
  t.cells.push_back(born);
  t.cells[0].positions.resize(5);
  KineticAlphaComplex engine(t, with_radius(100));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().insertions == 1);
  REQUIRE(engine.statistics().deletions == 1);
  REQUIRE(engine.statistics().local_insertions == 1);
  REQUIRE(engine.statistics().local_deletions == 1);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::insertion)] == 1);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::deletion)] == 1);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.complex().count(Simplex{0}) == 0);
  REQUIRE(obs.complex().count(Simplex{40}) == 1);
}

TEST_CASE("a cell present at the last frame only adds nothing to the stream", "[kinetic][engine]") {
  // K is reported up to K(t_end-) and t_end gets no instant cells (docs/MATH.md §6.2): the run with the
  // extra cell must give exactly the stream of the run without it.
  const Trajectories without = testing::random_walk(22, 30, 5, 50, 5);
  Trajectories with = without;
  Trajectory late;
  late.cell_id = 31;
  late.type = 1;
  late.first_frame = 4;
  late.positions.push_back({25, 25, 25});
  with.cells.push_back(late);
  KineticAlphaComplex a(without, with_radius(100)), b(with, with_radius(100));
  ReplayObserver oa(a), ob(b);
  a.run(oa);
  b.run(ob);
  REQUIRE(ob.mismatches == 0);
  REQUIRE(ob.inconsistencies == 0);
  CHECK(b.statistics().insertions == 0);
  CHECK(b.statistics().batches == a.statistics().batches);
  CHECK(ob.complex() == oa.complex());
  CHECK(ob.complex().count(Simplex{30}) == 0);
}

namespace {

// Records each batch's time and step kinds.
struct BatchLog : Observer {
  struct Entry {
    EventTime time;
    std::vector<StepKind> kinds;
    int flips_in_alpha = 0;
  };
  std::vector<Entry> batches;
  void batch(const EventTime& t, const std::vector<Step>& steps) override {
    Entry e{t, {}, 0};
    for (const Step& s : steps) {
      e.kinds.push_back(s.kind);
      e.flips_in_alpha += s.flip && s.flip->in_alpha;
    }
    batches.push_back(e);
  }
  int count(StepKind k) const {
    int n = 0;
    for (const Entry& e : batches)
      n += static_cast<int>(std::count(e.kinds.begin(), e.kinds.end(), k));
    return n;
  }
};

} // namespace

TEST_CASE("a cell leaving the hull through a facet makes a hull flip when the tetrahedron flattens",
          "[kinetic][engine]") {
  // a, b, c, d fixed; e = (2,2,2) + u (6,6,6) crosses the hull facet bcd (x + y + z = 10) at
  // u = 2/9, t = 200/9: the orientation of ebcd (a D-infinity certificate, case A) vanishes there.
  // rho = 1: every edge is longer than 2, so no radius event interferes.
  Trajectories t = spatial({0, 100});
  still(t, 1, {0, 0, 0});
  still(t, 2, {10, 0, 0});
  still(t, 3, {0, 10, 0});
  still(t, 4, {0, 0, 10});
  t.cells.push_back({5, 1, 0, {{2, 2, 2}, {8, 8, 8}}});
  KineticAlphaComplex engine(t, with_radius(1));
  BatchLog log;
  testing::BatchRecorder steps;
  testing::TeeObserver both(log, steps);
  engine.run(both);
  REQUIRE(engine.statistics().radius_events == 0);
  REQUIRE(log.batches.size() >= 1);
  REQUIRE(log.batches[0].time.time == Approx(200.0 / 9).epsilon(0).margin(reported_time_error));
  REQUIRE(log.count(StepKind::hull_flip) >= 1);
  REQUIRE(engine.statistics().audits > 0);
  // e starts inside abcd, so ebcd is a finite tetrahedron; it flattens and leaves Del (case A), and
  // the stream says so (Step::delaunay_removed), with no finite tetrahedron created.
  const Step& flip = steps.batches.front().second.front();
  REQUIRE(flip.kind == StepKind::hull_flip);
  REQUIRE(flip.delaunay_removed == std::vector<Simplex>{Simplex{1, 2, 3, 4}});
  REQUIRE(flip.delaunay_created.empty());
}

namespace {

// Four cells alone in a slab: a, b fixed, c and d moving. Whenever the four are not coplanar their
// Delaunay triangulation is the one tetrahedron and its hull, so when they pass through one plane the
// tetrahedron turns inside out and stays: every hull certificate fails at once, none is flippable,
// and the static repair finds the same tetrahedra. Before: "no progress resolving degenerate
// Delaunay events" (stress seed 4195: the repair kept the stale orientation, so the same
// certificates failed after each repair).
Trajectories four_cells_through_a_plane(GridPoint c1, GridPoint d0, GridPoint d1) {
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100, 200};
  t.cells.push_back({1, 1, 0, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}});
  t.cells.push_back({2, 1, 0, {{4, 0, 0}, {4, 0, 0}, {4, 0, 0}}});
  t.cells.push_back({3, 1, 0, {{0, 4, 0}, c1, c1}});
  t.cells.push_back({4, 1, 0, {d0, d1, d1}});
  return t;
}

void require_turned_inside_out(const Trajectories& t, double time) {
  KineticAlphaComplex engine(t, with_radius(1));
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.hull_flips, s.static_rebuilds, s.audits);
  REQUIRE(s.flips() == 0);
  REQUIRE(s.reoriented == 1);
  REQUIRE(s.audits_compared_with_cgal > 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(std::count_if(obs.times.begin(), obs.times.end(), [&](double x) {
            return x == Approx(time).epsilon(0).margin(reported_time_error);
          }) == 1);
}

} // namespace

TEST_CASE("four cells passing through one plane at a rational time keep their tetrahedron",
          "[kinetic][engine][degenerate]") {
  // d = (1,1,-2) + u (0,0,4) crosses the plane z = 0 of a, b, c at u = 1/2, t = 50.
  require_turned_inside_out(four_cells_through_a_plane({0, 4, 0}, {1, 1, -2}, {1, 1, 2}), 50);
}

TEST_CASE("four cells passing through one plane at an algebraic time keep their tetrahedron",
          "[kinetic][engine][degenerate]") {
  // c = (0, 4, 2u), d = (1, 1 + u, -1 + 3u): orient(a, b, c, d) = 4 (4 (3u - 1) - 2u (1 + u))
  // = -8 (u^2 - 5u + 2), which vanishes at u = (5 - sqrt 17)/2 ~ 0.438, t ~ 43.8 (and at no other u
  // in [0, 1]).
  require_turned_inside_out(four_cells_through_a_plane({0, 4, 2}, {1, 1, -1}, {1, 2, 2}),
                            100 * (5 - std::sqrt(17.0)) / 2);
}

TEST_CASE("two mirror-image flips at exactly the same time form one batch of two ranks",
          "[kinetic][engine]") {
  // The worked example and its mirror image through the plane x = 500: both D5 certificates vanish
  // at u* = (47 - sqrt 257)/32, an irrational time, so the equality is decided exactly.
  Trajectories t = spatial({0, 100});
  const GridPoint pts[4] = {{5, 0, 0}, {-3, 4, 0}, {-3, -4, 0}, {0, 0, 10}};
  for (int i = 0; i < 4; ++i) {
    still(t, i + 1, pts[i]);
    still(t, i + 11, {1000 - pts[i][0], pts[i][1], pts[i][2]});
  }
  t.cells.push_back({5, 2, 0, {{-2, 1, -6}, {2, 1, -2}}});
  t.cells.push_back({15, 2, 0, {{1002, 1, -6}, {998, 1, -2}}});
  KineticAlphaComplex engine(t, with_radius(49));
  BatchLog log;
  engine.run(log);
  const double t_star = 100 * (47 - std::sqrt(257.0)) / 32;
  int found = 0;
  for (const auto& b : log.batches)
    if (b.time.time == Approx(t_star).epsilon(0).margin(reported_time_error)) {
      ++found;
      REQUIRE(std::count(b.kinds.begin(), b.kinds.end(), StepKind::flip23) == 2);
      REQUIRE(b.flips_in_alpha == 2);
    }
  REQUIRE(found == 1);
}

TEST_CASE("a certificate vanishing exactly at a frame time is decided by the next slab",
          "[kinetic][engine]") {
  // The worked example scaled by 4: sphere through a, b, c, d has centre (0,0,15), radius 25. e runs
  // up the z axis and reaches the sphere at (0,0,-10) exactly at frame 1 (t = 100), then goes
  // inside: the flip belongs to the frame batch at t = 100, not to slab 0.
  Trajectories t = spatial({0, 100, 200});
  still(t, 1, {20, 0, 0});
  still(t, 2, {-12, 16, 0});
  still(t, 3, {-12, -16, 0});
  still(t, 4, {0, 0, 40});
  t.cells.push_back({5, 2, 0, {{0, 0, -30}, {0, 0, -10}, {0, 0, -2}}});
  KineticAlphaComplex engine(t, with_radius(1));
  BatchLog log;
  engine.run(log);
  REQUIRE(engine.statistics().flips23 == 1);
  REQUIRE(log.batches.size() == 1);
  REQUIRE(log.batches[0].time.at_frame);
  REQUIRE(log.batches[0].time.time == 100.0);
  REQUIRE(log.batches[0].kinds.front() == StepKind::flip23);
}

TEST_CASE("a cell that reaches a hull facet at a frame and stays on it leaves its flat tetrahedron there",
          "[kinetic][engine][degenerate]") {
  // d = (3,3,3) - u (0,0,3) reaches the hull facet abc (z = 0, inside it since x + y = 6 < 10) at
  // frame 1 (t = 100) and stays there in slab 1, so the orientation of abcd is identically zero in
  // slab 1 and tetrahedron abcd would be flat all through it. Del(100+) has d on the hull and no abcd:
  // the frame batch is one static repair (a top simplex flat at the frame and not positively oriented
  // just after it, Engine::top_simplex_turns_at_frame) that removes abcd and creates no finite
  // tetrahedron, and then nothing happens. Before: the certificate counted as valid (identically
  // zero, docs/MATH.md §3.9), abcd stayed flat through slab 1, and the audit found Del different from
  // CGAL's triangulation there.
  Trajectories t = spatial({0, 100, 200});
  still(t, 1, {0, 0, 0});
  still(t, 2, {10, 0, 0});
  still(t, 3, {0, 10, 0});
  still(t, 4, {3, 3, 10});
  t.cells.push_back({5, 1, 0, {{3, 3, 3}, {3, 3, 0}, {3, 3, 0}}});
  const testing::RecordedRun<BatchLog> run(t, with_radius(1));
  REQUIRE(run.log.batches.size() == 1);
  REQUIRE(run.log.batches[0].time.at_frame);
  REQUIRE(run.log.batches[0].time.time == 100.0);
  REQUIRE(run.engine.statistics().flips() == 0);
  REQUIRE(run.engine.statistics().frames_repaired_for_flat_simplices == 1);
  REQUIRE(run.steps.batches.front().second.size() == 1);
  const Step& repair = run.steps.batches.front().second.front();
  REQUIRE(repair.kind == StepKind::repair);
  REQUIRE(repair.delaunay_removed == std::vector<Simplex>{Simplex{0, 1, 2, 4}});
  REQUIRE(repair.delaunay_created.empty());
  REQUIRE(run.engine.statistics().audits_compared_with_cgal > 0);
  REQUIRE(run.replay.mismatches == 0);
  REQUIRE(run.replay.inconsistencies == 0);
}

TEST_CASE("a hull cell that enters the hull facet at a frame and goes on inward makes one hull flip there",
          "[kinetic][engine][degenerate]") {
  // a, b, c on z = 0, d = (3,3,9) above; p = (3,3,-3) -> (3,3,0) -> (3,3,2) reaches the plane of abc
  // inside abc (x + y = 6 < 12) exactly at frame 1 and bends there (3 per slab, then 2). The sphere
  // through a, b, c and p = (3,3,-3) has centre (6,6,15/2) and radius^2 513/4; d is at distance^2
  // 81/4 from it, inside, and the spheres through circle abc only grow above z = 0 as p rises: Del is
  // the three tetrahedra round edge pd all through slab 0, and p is a hull vertex. Its three hull
  // ridges carry the orientation of pabc, 0 at the frame and reflex just after it: one hull flip at
  // t = 100 (3-2 round the edge from the infinite vertex to p) adds pabc, flat there. pabc has the
  // opposite orientation just before the frame (p below the plane) and just after (above), so it
  // turns and the flip stands: no refusal, no repair (Engine::flat_without_turning_at_now across a
  // bend). Just after, p is inside abcd, whose only triangulation with p is the star of p.
  Trajectories t = spatial({0, 100, 200});
  still(t, 1, {0, 0, 0});
  still(t, 2, {12, 0, 0});
  still(t, 3, {0, 12, 0});
  still(t, 4, {3, 3, 9});
  t.cells.push_back({5, 1, 0, {{3, 3, -3}, {3, 3, 0}, {3, 3, 2}}});
  const testing::RecordedRun<BatchLog> run(t, with_radius(1));
  REQUIRE(run.log.batches.size() == 1);
  REQUIRE(run.log.batches[0].time.at_frame);
  REQUIRE(run.log.batches[0].time.time == 100.0);
  REQUIRE(run.log.count(StepKind::hull_flip) == 1);
  REQUIRE(run.log.count(StepKind::repair) == 0);
  REQUIRE(run.engine.statistics().hull_flips == 1);
  REQUIRE(run.engine.statistics().hull_flips_refused_touching == 0);
  REQUIRE(run.engine.statistics().frames_repaired_for_flat_simplices == 0);
  const Step& flip = run.steps.batches.front().second.front();
  REQUIRE(flip.delaunay_created == std::vector<Simplex>{Simplex{0, 1, 2, 4}});
  REQUIRE(flip.delaunay_removed.empty());
  REQUIRE(run.engine.statistics().audits_compared_with_cgal > 0);
  REQUIRE(run.replay.mismatches == 0);
  REQUIRE(run.replay.inconsistencies == 0);
}

TEST_CASE("a cell present only at the first frame is deleted at t0", "[kinetic][engine]") {
  // Its deletion at t0 must take it out of K at once, not leave it there for the whole run.
  Trajectories t = testing::random_walk(21, 20, 3, static_cast<int>(2000 * std::cbrt(20.0)), 600);
  t.cells[0].positions.resize(1);
  KineticAlphaComplex engine(t, with_radius(1200 * 1200));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().deletions == 1);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::deletion)] == 1);
  REQUIRE(obs.times.front() == 0.0);
  REQUIRE(obs.complex().count(Simplex{0}) == 0);
  REQUIRE(obs.mismatches == 0);
}

TEST_CASE("a cell present at one inner frame only is inserted and deleted there", "[kinetic][engine]") {
  // It must also be deleted there, not stay frozen where it was for the rest of the run. Here it is
  // present at frame 1 of 0..3 only.
  Trajectories t = testing::random_walk(21, 20, 4, static_cast<int>(2000 * std::cbrt(20.0)), 600);
  Trajectory& once = t.cells[0];
  once.first_frame = 1;
  once.positions = {once.positions[1]};
  KineticAlphaComplex engine(t, with_radius(1200 * 1200));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(engine.statistics().insertions == 1);
  REQUIRE(engine.statistics().deletions == 1);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::insertion)] == 1);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::deletion)] == 1);
  REQUIRE(obs.complex().count(Simplex{0}) == 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
}

TEST_CASE("a hull cell with three neighbours leaves by closing its star with one hull facet",
          "[kinetic][engine]") {
  // d sits above the face abc of the tetrahedron abce, outside its circumsphere (centre (20, 20,
  // -20), radius^2 1200; d is 2700 away), so it is joined to a, b and c only (its star: abcd and the
  // three infinite tetrahedra over its hull facets). When it leaves at frame 1, abc becomes
  // a hull facet again: the one infinite tetrahedron [-1 a b c] fills the hole
  // (engine/local_updates.h).
  Trajectories t = spatial({0, 100, 200});
  still(t, 1, {0, 0, 0});
  still(t, 2, {40, 0, 0});
  still(t, 3, {0, 40, 0});
  still(t, 4, {0, 0, -40});
  t.cells.push_back({5, 2, 0, {{10, 10, 30}, {10, 10, 31}}});
  KineticAlphaComplex engine(t, with_radius(100));
  testing::ArrivalsObserver obs(engine);
  engine.run(obs);
  REQUIRE(obs.arrivals.size() == 1);
  REQUIRE(obs.arrivals[0].kind == StepKind::deletion);
  CHECK(obs.arrivals[0].delaunay_removed == std::vector<Simplex>{Simplex{0, 1, 2, 4}});
  CHECK(obs.arrivals[0].delaunay_created.empty());
  REQUIRE(engine.statistics().local_deletions == 1);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
}

TEST_CASE("cells moving in shared planes repair degenerate groups mid-slab and stay audited",
          "[kinetic][engine][degenerate]") {
  // Every cell keeps its z through the run, on one of four layers, and walks in x and y: four cells of
  // a layer stay coplanar through every slab (identically-zero orientations), so a flip that would
  // flatten a tetrahedron between them can fall at an irrational time; no elementary flip applies
  // and the engine repairs the triangulation statically (docs/MATH.md §5.2 step 3, 5.4). The audit checks
  // every batch against CGAL.
  auto seed = GENERATE(range<std::uint64_t>(1, 4));
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> start(0, 4000), step(-700, 700), layer(0, 3);
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100, 200};
  for (int i = 0; i < 30; ++i) {
    Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    GridPoint p{start(rng), start(rng), 1000 * layer(rng)};
    for (std::size_t k = 0; k < t.frame_times.size(); ++k) {
      c.positions.push_back(p);
      p[0] += step(rng);
      p[1] += step(rng);
    }
    t.cells.push_back(c);
  }
  KineticAlphaComplex engine(t, with_radius(900 * 900));
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.flips23, s.flips32, s.hull_flips, s.static_rebuilds, s.audits, s.audits_compared_with_cgal);
  REQUIRE(s.repairs_at_algebraic_times > 0);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::repair)] > 0);
  REQUIRE(s.audits_compared_with_cgal > 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
}

TEST_CASE("certificates settled on the enclosures from doubles keep the audit green and the replay exact",
          "[kinetic][engine]") {
  const std::uint64_t seed = GENERATE(31, 32);
  CAPTURE(seed);
  Trajectories t = testing::random_walk(seed, 30, 4, 24, 3);
  KineticAlphaComplex engine(t, with_radius(25));
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  REQUIRE(obs.mismatches == 0);
  REQUIRE(s.audits > 0);
  // Both paths ran: a filter proof and a root isolated on the enclosure from doubles.
  REQUIRE(s.double_filter_settled > 0);
  REQUIRE(s.double_isolation_settled > 0);
  REQUIRE(s.flips23 + s.flips32 > 0);
}

TEST_CASE("certificates built at the start are counted by formula as CGAL's triangulation has faces",
          "[kinetic][engine][statistics]") {
  // Stationary cells over one slab: every facet of Del(t0+) gets one Delaunay certificate (in-sphere
  // between two finite tetrahedra, orientation otherwise, docs/MATH.md §3.2), and every frontier simplex one
  // radius certificate (docs/MATH.md §4.4). With rho below every half edge length all edges are long and in
  // F and nothing else is; with rho above every circumradius F is the finite tetrahedra. The last
  // frame rebuilds nothing (no slab follows), so each is built once.
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Dt = CGAL::Delaunay_triangulation_3<K>;
  const std::uint64_t seed = 31;
  CAPTURE(seed);
  const Trajectories t = testing::random_walk(seed, 40, 2, 1000, 0); // step 0: still
  std::vector<K::Point_3> pts;
  for (const Trajectory& c : t.cells)
    pts.emplace_back(double(c.at(0)[0]), double(c.at(0)[1]), double(c.at(0)[2]));
  Dt dt(pts.begin(), pts.end());
  REQUIRE(dt.number_of_vertices() == pts.size());
  std::size_t finite_pairs = 0, all_facets = 0;
  for (auto f = dt.all_facets_begin(); f != dt.all_facets_end(); ++f) {
    ++all_facets;
    finite_pairs += !dt.is_infinite(f->first) && !dt.is_infinite(dt.mirror_facet(*f).first);
  }
  REQUIRE(finite_pairs > 0);
  REQUIRE(all_facets > finite_pairs);
  // The two radii are far from every edge and circumradius (integer coordinates: squared lengths are
  // exact in doubles).
  const long tiny = 1, huge = 100000000000000L;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    REQUIRE(CGAL::squared_distance(e->first->vertex(e->second)->point(),
                                   e->first->vertex(e->third)->point()) > 4.0 * tiny);
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    REQUIRE(CGAL::squared_radius(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                                 c->vertex(3)->point()) < 0.5 * double(huge));

  const std::size_t hull = all_facets - finite_pairs;
  CHECK(built_by_formula(t, tiny) == FormulaCounts{finite_pairs, hull, dt.number_of_finite_edges(), 0, 0});
  CHECK(built_by_formula(t, huge) == FormulaCounts{finite_pairs, hull, 0, 0, dt.number_of_finite_cells()});
}

TEST_CASE("five cospherical cells reaching one circle turn two tetrahedra at once and the batch repairs",
          "[kinetic][engine][degenerate]") {
  // a, p, q, r, b stay on one sphere for the whole slab (their in-sphere polynomial is identically
  // zero) and reach one circle at u = 1/2, t = 50: orient(a, p, q, r) = c (2u - 7)(2u - 3)(2u - 1) and
  // orient(b, p, q, r) = -c' (2u - 7)(2u - 3)(2u - 1) (found and checked with sympy). Both
  // tetrahedra on a facet of the five turn inside out at that instant, so the product of their
  // orientations (Substitute::cell_orientations) only touches zero. What sees it is the five's
  // convex hull: the certificate of each of its facets, against an apex x outside their sphere, is
  // the inner tetrahedron's orientation times the power of x with respect to the limit sphere, and
  // changes sign there (engine/certificates.h). Four far static cells enclose the five, outside
  // their sphere for the whole slab.
  Trajectories t;
  t.scale = 1;
  t.frame_times = {0, 100};
  auto cell = [&](std::int64_t id, GridPoint from, GridPoint to) {
    t.cells.push_back({id, 1, 0, {from, to}});
  };
  cell(1, {377, -11687, -1885}, {-377, -9425, 1885}); // a
  cell(2, {3857, 11368, 0}, {4263, 8120, 0});         // p
  cell(3, {-13195, 0, 0}, {-7917, 0, 0});             // q
  cell(4, {-9541, -203, 2639}, {-9947, 8323, -2639}); // r
  cell(5, {-637, 12285, 455}, {637, 8827, -455});     // b
  const std::int64_t f = 1000000;
  cell(6, {f, f, f}, {f, f, f});
  cell(7, {f, -f, -f}, {f, -f, -f});
  cell(8, {-f, f, -f}, {-f, f, -f});
  cell(9, {-f, -f, f}, {-f, -f, f});
  KineticAlphaComplex engine(t, with_radius(100));
  ReplayObserver obs(engine);
  engine.run(obs);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::repair)] == 1);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
}
