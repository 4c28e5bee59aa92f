// Real CompuCell3D runs through the kinetic engine with the audit on: the alpha complex is checked
// against CGAL's static Fixed_alpha_shape_3 at a rational time after every audited batch and at
// every frame; the event stream replays to the engine's complex after every batch.
#include "batch_filter_check.h"
#include "kinetic_test_support.h"
#include "medusa/io/run_reader.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace medusa::kinetic;
using medusa::kinetic::testing::ReplayObserver;

namespace {

// The frames [first, last) of a run, cells clipped to them.
Trajectories frame_window(Trajectories t, std::size_t first, std::size_t last) {
  t.frame_times = std::vector<std::int64_t>(t.frame_times.begin() + first, t.frame_times.begin() + last);
  std::vector<Trajectory> kept;
  for (Trajectory& c : t.cells) {
    if (c.first_frame >= last || c.last_frame() < first)
      continue;
    std::size_t from = std::max(c.first_frame, first), to = std::min(c.last_frame() + 1, last);
    std::vector<GridPoint> p(c.positions.begin() + (from - c.first_frame),
                             c.positions.begin() + (to - c.first_frame));
    c.positions = std::move(p);
    c.first_frame = from - first;
    kept.push_back(std::move(c));
  }
  t.cells = std::move(kept);
  return t;
}

Trajectories read_csv(const std::string& path) {
  medusa::io::RunOptions options;
  options.source = medusa::io::RunSource::csv;
  return medusa::io::read_run(path, options).trajectories;
}

} // namespace

TEST_CASE("a real sorting run keeps the audit green from the lattice start", "[kinetic][real]") {
  // MCS 0 is CC3D's BlobInitializer lattice (every cube cospherical): the engine must start from
  // Del(t0+) and the audit compares with CGAL in every slab.
  Trajectories t = frame_window(read_csv(MEDUSA_TEST_DATA "/../../examples/sorting_3d/cells.csv.gz"), 0, 4);
  REQUIRE(t.cells.size() == 251);
  KineticOptions options;
  options.rho2 = squared_radius_from_decimal("3", t.scale);
  options.audit = true;
  options.audit_stride = 400;
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.flips23, s.flips32, s.hull_flips, s.radius_events, s.audits, s.audits_compared_with_cgal);
  REQUIRE(s.flips23 + s.flips32 > 100);
  REQUIRE(s.audits_compared_with_cgal >= 3);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
}

TEST_CASE("a real run where cells divide and die inserts and deletes them with the audit green",
          "[kinetic][real]") {
  // MCS 300..550: the aggregate loses cells, then divisions start (93 -> 80 -> 119 cells).
  Trajectories t = frame_window(read_csv(MEDUSA_TEST_DATA "/cc3d/mitosis_3d/cells.csv.gz"), 6, 12);
  KineticOptions options;
  options.rho2 = squared_radius_from_decimal("3", t.scale);
  options.audit = true;
  options.audit_stride = 400;
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.insertions, s.deletions, s.local_insertions, s.local_deletions, s.audits,
          s.audits_compared_with_cgal);
  REQUIRE(s.insertions > 0);
  REQUIRE(s.deletions > 0);
  // Each as a local change (engine/local_updates.h): the real run's cells are in general position
  // at these frames.
  REQUIRE(s.local_insertions == s.insertions);
  REQUIRE(s.local_deletions == s.deletions);
  REQUIRE(s.audits_compared_with_cgal >= 5);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
}

TEST_CASE("a real run holds no momentary contact inside a batch", "[kinetic][real][batch]") {
  // docs/MATH.md §6.2: every intermediate complex of a batch must already be filtered by K(t*-) u K(t*+)
  // u U_batch (see batch_filter_check.h). The division window of the mitosis run: insertions and
  // deletions make batches of several ranks. The audit is off (the tests above audit this window).
  // No bundled real run repairs statically at rho = 3, so the repairs' degenerate groups (6.3) are
  // tested on hand-built cases (test_kinetic_degenerate_groups.cpp).
  Trajectories t = frame_window(read_csv(MEDUSA_TEST_DATA "/cc3d/mitosis_3d/cells.csv.gz"), 6, 12);
  KineticOptions options;
  options.rho2 = squared_radius_from_decimal("3", t.scale);
  options.audit = false;
  KineticAlphaComplex engine(t, options);
  testing::BatchFilterCheck filter;
  engine.run(filter);
  CAPTURE(filter.batches, filter.intermediate_ranks);
  REQUIRE(filter.batches > 0);
  REQUIRE(filter.intermediate_ranks > 0);
  REQUIRE(filter.momentary == 0);
}

TEST_CASE("the real 2D sorting run keeps the audit green from its square-lattice start",
          "[kinetic][real][2d]") {
  // CC3D's cellsort_2D demo (100x100x1 lattice, 193 cells, 20 frames): read from the run folder, whose
  // Simulation XML gives the z extent 1, so the run is planar. MCS 0 is a square lattice (every
  // square cocircular): the engine starts from Del(t0+) and the audit compares with CGAL's
  // Delaunay_triangulation_2 + Alpha_shape_2 in every audited slab.
  medusa::io::RunOptions read;
  read.source = medusa::io::RunSource::csv;
  Trajectories t = medusa::io::read_run(MEDUSA_TEST_DATA "/cc3d/sorting_2d", read).trajectories;
  REQUIRE(t.dimension == 2);
  REQUIRE(t.cells.size() == 193);
  REQUIRE(t.frames() == 20);
  KineticOptions options;
  options.rho2 = squared_radius_from_decimal("3", t.scale);
  options.audit = true;
  options.audit_stride = 100;
  KineticAlphaComplex engine(t, options);
  ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.flips22, s.hull_flips, s.radius_events, s.static_rebuilds, s.audits, s.audits_compared_with_cgal);
  REQUIRE(s.flips22 > 100);
  REQUIRE(s.radius_events > 0);
  REQUIRE(s.audits_compared_with_cgal >= 10);
  REQUIRE(obs.step_counts[static_cast<int>(StepKind::flip22)] == static_cast<int>(s.flips22));
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
}
