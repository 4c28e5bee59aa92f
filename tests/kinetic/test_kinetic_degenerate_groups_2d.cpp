// Degenerate groups of planar static repairs (docs/MATH.md §6.3, second bullet, in dimension 2), on a
// hand-built run derived on paper, with the audit on.
//
// Why the run looks the way it does. In 2D a cocircular moment reached by generic motion never ends
// in a repair: the edge xy of a failing in-circle certificate has x, y, p, q on one circle at t*, so
// the quadrilateral xpyq is strictly convex at t* and just after, pq is not an edge, and the 2-2 flip
// applies (docs/MATH.md §5.2 step 2; Lawson's flips reach Del(t*+)). Repairs come from momentarily
// collinear points (an edge whose two triangles are flat at t* and whose quadrilateral is not convex
// just after). What a repair then meets is a set of points that are cocircular at t* and stay so
// through the new slab (identically-zero in-circles, docs/MATH.md §5.3, never flipped), whose triangulation
// the global rebuild re-chooses by CGAL's symbolic perturbation (5.4, 5.5): that set is a 2-cell of
// D(t*) cut through by the repair, a degenerate group.
#include "group_observer.h"
#include "kinetic_test_support.h"
#include "support/planar_repair_run.h"

#include <catch2/catch.hpp>

#include <set>
#include <vector>

using namespace medusa::kinetic;
using medusa::kinetic::testing::GroupObserver;
using medusa::kinetic::testing::ReplayObserver;
using medusa::kinetic::testing::with_radius;
using medusa::test::planar_repair_with_pentagon;

namespace {

using Group = std::vector<VertexId>;

} // namespace

TEST_CASE("a planar repair through five cocircular cells reports them as a group iff R^2 <= rho^2",
          "[kinetic][engine][2d][degenerate][groups]") {
  // From the derivation above: one repair, at the frame t = 100; it removes p1 p2 p3 and p1 p3 e and
  // creates e p2 p3 and p1 e p2 (besides the flat triangles on x = 29); the only group is the
  // pentagon {0, 1, 2, 3, 4} with g = 25, reported for rho^2 >= 25 (R = rho included, docs/MATH.md §6.3
  // "<="), none below.
  const long rho2 = GENERATE(26L, 25L, 24L);
  CAPTURE(rho2);
  const Trajectories t = planar_repair_with_pentagon(); // the engine keeps a reference
  KineticAlphaComplex engine(t, with_radius(rho2));
  GroupObserver obs(engine);
  engine.run(obs);

  REQUIRE(obs.repairs == 1);
  REQUIRE(obs.repair_at_frame);
  REQUIRE(obs.repair_time == 100.0);
  REQUIRE(obs.removed.count(Simplex{0, 1, 2}) == 1);
  REQUIRE(obs.removed.count(Simplex{0, 2, 4}) == 1);
  REQUIRE(obs.created.count(Simplex{1, 2, 4}) == 1);
  REQUIRE(obs.created.count(Simplex{0, 1, 4}) == 1);
  REQUIRE(obs.created.count(Simplex{6, 7, 8}) == 1);
  std::set<Group> expected;
  if (rho2 >= 25)
    expected.insert({0, 1, 2, 3, 4});
  REQUIRE(obs.groups == expected);
  REQUIRE(obs.only_in_repairs);
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(obs.not_closed == 0);
  REQUIRE(engine.statistics().audits_compared_with_cgal > 0);
}

TEST_CASE("a planar repair of momentarily collinear cells alone reports no group",
          "[kinetic][engine][2d][degenerate][groups]") {
  // The same run without the pentagon (its five cells dropped): the repair at t = 100 still happens,
  // but every triangle it changes is flat at t = 100 and spans no circle (three collinear points are
  // never concyclic), so no group for any rho.
  Trajectories t = planar_repair_with_pentagon();
  t.cells.erase(t.cells.begin(), t.cells.begin() + 5);
  KineticAlphaComplex engine(t, with_radius(10000));
  GroupObserver obs(engine);
  engine.run(obs);
  REQUIRE(obs.repairs == 1);
  REQUIRE(obs.repair_time == 100.0);
  REQUIRE(obs.groups.empty());
  REQUIRE(obs.mismatches == 0);
  REQUIRE(obs.inconsistencies == 0);
  REQUIRE(engine.statistics().audits_compared_with_cgal > 0);
}
