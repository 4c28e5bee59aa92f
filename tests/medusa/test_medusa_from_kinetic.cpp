// Differential tests of libmedusa against libkinetic: the audited kinetic engine feeds a medusa
// builder writing an HDF5 store, and K_t read back from the store must equal the engine's own
// complex at every frame (docs/MATH.md §6.6). Random walks and real CompuCell3D runs (with mitosis).
#include "../kinetic/kinetic_test_support.h"
#include "cc3d_runs.h"
#include "kinetic_run.h"
#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"
#include "medusa_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <optional>

using namespace medusa;
using namespace medusa::test;

namespace {

std::size_t symmetric_difference(const SimplexSet& a, const SimplexSet& b) {
  std::size_t n = 0;
  for (const auto& s : a)
    n += b.count(s) == 0;
  for (const auto& s : b)
    n += a.count(s) == 0;
  return n;
}

// K_t from the store at every frame equals the engine's complex: K(t_k+) at frame k < last, K(t_end-)
// at the last frame (ComplexIndex::at_frame, docs/MATH.md §6.6); the store equals the collected medusa.
void check_store_against_engine(const KineticRun& run, const std::string& store_path) {
  const medusa::Medusa m = medusa::read_store(store_path);
  REQUIRE(same_medusa(m, run.collected));
  REQUIRE(run.engine.finished);
  const std::size_t frames = m.input.frames();
  REQUIRE(frames >= 2);
  const medusa::ComplexIndex index(m);
  CHECK(run.engine.initial_argument == run.engine.initial_state);
  CHECK(tuples(m, index.after(0)) == run.engine.initial_state);
  // The engine reports frame 0 through initial() and the last frame through finish(); frame() is
  // called for the frames in between, after their frame batch.
  REQUIRE(run.engine.at_frame.size() == frames - 2);
  for (std::size_t k = 0; k < frames; ++k) {
    CAPTURE(k, frames);
    const SimplexSet stored = tuples(m, index.at_frame(k));
    const SimplexSet& engine = k == 0            ? run.engine.after_t0
                               : k + 1 == frames ? run.engine.at_end
                                                 : run.engine.at_frame.at(k);
    CAPTURE(stored.size(), engine.size(), symmetric_difference(stored, engine));
    CHECK(stored == engine);
    CHECK(!engine.empty());
    // The same without an index, for the whole medusa and each cell type.
    CHECK(tuples(m, cells_at_frame(m, k)) == engine);
    for (int type : {1, 2})
      CHECK(cells_at_frame(m, k, type) == medusa::ComplexIndex(m, type).at_frame(k));
    // Independent of both: the vertices of K are the cells alive then (docs/MATH.md §5.6): K(t_k+) holds the
    // cells present at t_k that do not end there, K(t_end-) those present through the last slab.
    SimplexSet alive;
    for (std::size_t v = 0; v < m.input.cells.size(); ++v) {
      const kinetic::Trajectory& c = m.input.cells[v];
      const bool present = k + 1 == frames ? c.first_frame + 1 < frames && c.last_frame() + 1 == frames
                                           : c.first_frame <= k && k < c.last_frame();
      if (present)
        alive.insert({static_cast<VertexId>(v)});
    }
    SimplexSet vertices;
    for (const auto& s : engine)
      if (s.size() == 1)
        vertices.insert(s);
    CHECK(vertices == alive);
  }
}

} // namespace

TEST_CASE("K_t read back from the store equals the kinetic engine's complex on random walks",
          "[medusa][kinetic][differential]") {
  auto [seed, n, frames] =
      GENERATE(table<std::uint64_t, int, int>({{11, 30, 5}, {12, 45, 4}, {13, 60, 3}, {14, 80, 3}}));
  CAPTURE(seed, n, frames);
  const int box = static_cast<int>(2000 * std::cbrt(static_cast<double>(n)));
  const kinetic::Trajectories t = kinetic::testing::random_walk(seed, n, frames, box, 600);
  kinetic::SquaredRadius rho2;
  rho2.num = 1200 * 1200;
  const std::string store = temp_path("walk-" + std::to_string(seed) + "-" + std::to_string(n) + ".h5");
  const KineticRun run = run_into_store(t, "1200", rho2, store, 5);
  const kinetic::KineticStatistics& s = run.statistics;
  CAPTURE(s.batches, s.flips23, s.flips32, s.radius_events, s.audits_compared_with_cgal);
  CHECK(s.audits_compared_with_cgal > 0);
  CHECK(s.radius_events > 0);
  check_store_against_engine(run, store);
  std::remove(store.c_str());
}

TEST_CASE("K_t read back from the store equals the kinetic engine's complex on a real CC3D run",
          "[medusa][kinetic][differential][cc3d]") {
  const kinetic::Trajectories t = read_cc3d("nosorting_3d", 6);
  REQUIRE(t.frames() == 6);
  REQUIRE(t.cells.size() == 251);
  const std::string store = temp_path("nosorting.h5");
  const KineticRun run = run_into_store(t, "3", kinetic::squared_radius_from_decimal("3", t.scale), store, 5);
  CAPTURE(run.statistics.batches, run.statistics.flips23, run.statistics.flips32,
          run.statistics.radius_events);
  CHECK(run.statistics.audits_compared_with_cgal > 0);
  check_store_against_engine(run, store);
  std::remove(store.c_str());
}

TEST_CASE("K_t read back from the store equals the kinetic engine's complex through divisions and deaths",
          "[medusa][kinetic][differential][cc3d]") {
  // Frames 0..9 (MCS 0..450) of mitosis_3d: deaths from MCS 50 on, divisions from MCS 350 on.
  const kinetic::Trajectories t = read_cc3d("mitosis_3d", 10);
  REQUIRE(t.frames() == 10);
  // A trajectory starting at an inner frame is inserted there; one ending at an inner frame is deleted
  // there, after its last position (docs/MATH.md §5.6).
  // (Cells ending at frame 0 are counted apart: libkinetic never deletes them, see below.)
  std::size_t born = 0, died = 0;
  for (const kinetic::Trajectory& c : t.cells) {
    born += c.first_frame > 0 && c.first_frame + 1 < t.frames();
    died += c.last_frame() + 1 < t.frames();
  }
  CAPTURE(born, died);
  REQUIRE(born > 0);
  REQUIRE(died > 0);
  const std::string store = temp_path("mitosis.h5");
  const KineticRun run = run_into_store(t, "3", kinetic::squared_radius_from_decimal("3", t.scale), store, 5);
  CAPTURE(run.statistics.batches, run.statistics.insertions, run.statistics.deletions);
  CHECK(run.statistics.insertions == born);
  CHECK(run.statistics.deletions == died);
  check_store_against_engine(run, store);
  std::remove(store.c_str());
}

// A cell present at frame 0 only (it died between frames 0 and 1, as 3 cells of mitosis_3d do) is
// deleted in a batch at t_0 and is in K at no later frame.
TEST_CASE("a cell present at frame 0 only is no longer in K after frame 1", "[medusa][kinetic]") {
  constexpr std::uint64_t seed = 21;
  CAPTURE(seed);
  kinetic::Trajectories t =
      kinetic::testing::random_walk(seed, 20, 3, static_cast<int>(2000 * std::cbrt(20.0)), 600);
  t.cells[0].positions.resize(1);
  const std::string store = temp_path("frame0-death.h5");
  kinetic::SquaredRadius rho2;
  rho2.num = 1200 * 1200;
  const KineticRun run = run_into_store(t, "1200", rho2, store, 1);
  std::remove(store.c_str());
  CAPTURE(run.statistics.deletions);
  CHECK(run.statistics.deletions == 1);
  CHECK(run.engine.at_frame.at(1).count({0}) == 0);
  CHECK(run.engine.at_end.count({0}) == 0);
}

TEST_CASE("a store read with the frame batches only gives every frame's batch and complex as a whole read",
          "[medusa][kinetic][store]") {
  const std::uint64_t seed = GENERATE(21, 22);
  CAPTURE(seed);
  const int n = 40, frames = 5;
  const int box = static_cast<int>(2000 * std::cbrt(static_cast<double>(n)));
  const kinetic::Trajectories t = kinetic::testing::random_walk(seed, n, frames, box, 600);
  kinetic::SquaredRadius rho2;
  rho2.num = 1200 * 1200;
  medusa::test::TempDir dir("frame-batches");
  const std::string store = dir.file("walk.h5");
  run_into_store(t, "1200", rho2, store, 1000); // audited at the frames: this test is about reading
  const Medusa whole = read_store(store);
  StoreReadOptions frame_batches;
  frame_batches.every_batch = false;
  const Medusa thin = read_store(store, frame_batches);
  CAPTURE(whole.batches.size(), thin.batches.size());
  REQUIRE(thin.batches.size() > 0);
  CHECK(thin.batches.size() < whole.batches.size() / 4);
  // Each kept record is one of the whole read's, in the same order.
  std::size_t at = 0;
  for (const BatchRecord& b : thin.batches) {
    while (at < whole.batches.size() && whole.batches[at].batch != b.batch)
      ++at;
    REQUIRE(at < whole.batches.size());
    const BatchRecord& w = whole.batches[at];
    CHECK((w.slab == b.slab && w.at_frame == b.at_frame && w.ranks == b.ranks && w.time == b.time &&
           w.u == b.u));
  }
  CHECK(thin.frames.size() == whole.frames.size());
  CHECK(thin.cells.size() == whole.cells.size());
  for (std::size_t k = 0; k < t.frames(); ++k) {
    CAPTURE(k);
    CHECK(frame_batch(thin, k) == frame_batch(whole, k));
    for (std::optional<int> type : {std::optional<int>(), std::optional<int>(1)})
      CHECK(cells_at_frame(thin, k, type) == cells_at_frame(whole, k, type));
  }
}
