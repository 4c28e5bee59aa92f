// Dense walks on a coarse integer lattice with births and deaths (testing::dense_lattice_run): many
// certificates fail at once in degenerate configurations, which MATH.md 5.2 settles by flipping the
// flippable failures in canonical order and repairing statically when none is flippable or the flips
// cycle. Each seed below is one that a stress run of this generator found failing before that rule
// was implemented in 3D (a flip applied without its flippability test, or "no progress" thrown
// where a static repair was due); each must now run to the end with the audit green.
#include "kinetic_test_support.h"

#include <cstdint>

using namespace medusa::kinetic;

namespace {

void run_to_the_end(std::uint64_t seed) {
  CAPTURE(seed);
  testing::DenseLatticeRun run;
  REQUIRE(testing::dense_lattice_run(seed, run));
  CAPTURE(run.two_d, run.n, run.frames, run.box, run.step);
  KineticAlphaComplex engine(run.trajectories, run.options);
  testing::ReplayObserver obs(engine);
  engine.run(obs);
  const KineticStatistics& s = engine.statistics();
  CAPTURE(s.flips23, s.flips32, s.hull_flips, s.static_rebuilds, s.repairs_at_algebraic_times);
  REQUIRE(s.audits > 0);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
}

} // namespace

TEST_CASE("simultaneous degenerate failures that cycle through flips are settled by a static repair",
          "[kinetic][degenerate][lattice]") {
  // Before: "no progress resolving degenerate Delaunay events" (InternalError) in each.
  for (std::uint64_t seed : {1045u, 1084u, 1130u})
    run_to_the_end(seed);
}

TEST_CASE("a hull flip that would create an edge the triangulation already has is not applied",
          "[kinetic][degenerate][lattice]") {
  // Before: "facet [0 9 14] would get a third top simplex [0 8 9 14]" (InternalError): on the flat
  // hull of the lattice the 2-3 flip of a failed hull facet recreated an existing edge.
  run_to_the_end(1019);
}
