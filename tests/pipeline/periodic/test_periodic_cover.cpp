// The covering space of a periodic run and the canonical image of its simplices (docs/MATH.md §8.3-§8.5),
// on hand-built runs whose copies are counted on paper.
#include "medusa/core/error.h"
#include "medusa/periodic/canonical_filter.h"
#include "medusa/periodic/periodic_cover.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

using namespace medusa;
using namespace medusa::periodic;

namespace {

constexpr std::int64_t S = 1000000;

// Periodic along x only, period 10 lattice units.
io::PeriodicDomain x_period_10() {
  io::PeriodicDomain d;
  d.periodic = {true, false, false};
  d.period = {10 * S, 0, 0};
  d.lattice = {10, 0, 0};
  return d;
}

kinetic::Trajectory cell(std::int64_t id, std::vector<kinetic::GridPoint> positions, std::size_t first = 0) {
  kinetic::Trajectory t;
  t.cell_id = id;
  t.type = 1;
  t.first_frame = first;
  t.positions = std::move(positions);
  return t;
}

kinetic::Trajectories run(std::vector<kinetic::Trajectory> cells, std::size_t frames) {
  kinetic::Trajectories t;
  t.dimension = 2;
  t.scale = S;
  for (std::size_t k = 0; k < frames; ++k)
    t.frame_times.push_back(static_cast<std::int64_t>(100 * k));
  t.cells = std::move(cells);
  return t;
}

kinetic::SquaredRadius radius_one() { return kinetic::squared_radius_from_decimal("1", S); }

} // namespace

TEST_CASE("Static cells get the copies within 2 rho of the originals' box", "[periodic]") {
  // rho = 1, no motion: a copy is kept when it lies within 2 of the originals' box along x. Cells at
  // 1, 4.5 and 8 (window [-1, 10]): their copies 11, 14.5, 18, -9, -5.5, -2 are all outside. Cells at
  // 0.5 and 9 (window [-1.5, 11]): the copies 10.5 of the first and -1 of the second are kept.
  const auto none =
      cover_trajectories(run({cell(1, {{S, 0, 0}, {S, 0, 0}}), cell(2, {{4500000, S, 0}, {4500000, S, 0}}),
                              cell(3, {{8 * S, 0, 0}, {8 * S, 0, 0}})},
                             2),
                         x_period_10(), radius_one());
  CHECK(none.originals == 3);
  CHECK(none.ghosts() == 0);

  const auto two = cover_trajectories(
      run({cell(1, {{500000, 0, 0}, {500000, 0, 0}}), cell(2, {{9 * S, 3 * S, 0}, {9 * S, 3 * S, 0}})}, 2),
      x_period_10(), radius_one());
  REQUIRE(two.ghosts() == 2);
  CHECK(two.trajectories.cells[2].positions ==
        std::vector<kinetic::GridPoint>{{10500000, 0, 0}, {10500000, 0, 0}});
  CHECK(two.vertices[2].original == 0);
  CHECK(two.vertices[2].offset == std::array<std::int64_t, 3>{1, 0, 0});
  CHECK(two.trajectories.cells[3].positions ==
        std::vector<kinetic::GridPoint>{{-S, 3 * S, 0}, {-S, 3 * S, 0}});
  CHECK(two.vertices[3].offset == std::array<std::int64_t, 3>{-1, 0, 0});
  CHECK(two.trajectories.cells[3].cell_id == 2);
}

TEST_CASE("A copy that comes near only in a later slab enters at that slab's first frame", "[periodic]") {
  // Frames 0..3. Cell 1 stays at 1, cell 2 at 5; cell 3 moves 2 -> 2 -> 2 -> 4 (largest displacement
  // 2 in slab 2 only). Box [1, 5] in slabs 0, 1 and [1, 5] then. Margins: slab 0, 1: 2; slab 2: 2 + 4 = 6.
  // The copy of cell 2 at 15 - 10 = -5 is within 6 of the box only for slab 2: present at frames 2, 3.
  // The copy of cell 1 at 11 likewise (11 <= 5 + 6). Copies of cell 3: 12 (no: 12 > 11) and -8 (no).
  const auto c = cover_trajectories(
      run({cell(1, {{S, 0, 0}, {S, 0, 0}, {S, 0, 0}, {S, 0, 0}}),
           cell(2, {{5 * S, S, 0}, {5 * S, S, 0}, {5 * S, S, 0}, {5 * S, S, 0}}),
           cell(3, {{2 * S, 3 * S, 0}, {2 * S, 3 * S, 0}, {2 * S, 3 * S, 0}, {4 * S, 3 * S, 0}})},
          4),
      x_period_10(), radius_one());
  REQUIRE(c.ghosts() == 2);
  CHECK(c.trajectories.cells[3].cell_id == 1);
  CHECK(c.trajectories.cells[3].first_frame == 2);
  CHECK(c.trajectories.cells[3].positions == std::vector<kinetic::GridPoint>{{11 * S, 0, 0}, {11 * S, 0, 0}});
  CHECK(c.trajectories.cells[4].cell_id == 2);
  CHECK(c.trajectories.cells[4].first_frame == 2);
  CHECK(c.trajectories.cells[4].positions == std::vector<kinetic::GridPoint>{{-5 * S, S, 0}, {-5 * S, S, 0}});
}

TEST_CASE("A radius with 4 rho not below a period is refused with a geometry error", "[periodic]") {
  const io::PeriodicDomain d = x_period_10();
  CHECK_NOTHROW(check_periodic_radius(d, kinetic::squared_radius_from_decimal("2.499999", S), "2.499999"));
  try {
    check_periodic_radius(d, kinetic::squared_radius_from_decimal("2.5", S), "2.5");
    FAIL("radius 2.5 on a period of 10 was accepted");
  } catch (const GeometryError& e) {
    CHECK_THAT(e.what(),
               Catch::Matchers::Contains("radius 2.5") && Catch::Matchers::Contains("period 10 along x"));
  }
}

TEST_CASE("A simplex is canonical when its smallest cell is an original, and named by the originals",
          "[periodic]") {
  PeriodicCover cover;
  cover.originals = 3;
  cover.vertices = {{0, {0, 0, 0}}, {1, {0, 0, 0}},  {2, {0, 0, 0}},
                    {0, {1, 0, 0}}, {1, {-1, 0, 0}}, {2, {1, 0, 0}}};
  // {original 1, copy of 0}: smallest cell 0 is a copy -> not canonical; its translate {copy of 1, 0}
  // (vertices 4 and 0) is.
  CHECK(!canonical_image(cover, {1, 3}));
  CHECK(canonical_image(cover, {4, 0}) == std::vector<kinetic::VertexId>{0, 1});
  CHECK(canonical_image(cover, {5, 1, 0}) == std::vector<kinetic::VertexId>{0, 1, 2});
  CHECK(!canonical_image(cover, {5, 4, 3}));
  CHECK_THROWS_AS(canonical_image(cover, {0, 3}), InternalError);
  // A sentinel (no cell) makes any simplex non-canonical, even one with an original as smallest cell.
  cover.vertices.push_back({-1, {0, 0, 0}});
  cover.sentinels = 1;
  CHECK(cover.ghosts() == 3);
  CHECK(!canonical_image(cover, {0, 6}));
  CHECK(!canonical_image(cover, {6, 1, 2}));
}

TEST_CASE("Static sentinels enclose the cover, more than 2 rho from every point at every time",
          "[periodic]") {
  // Cells moving in the plane on a band periodic along x (period 10, rho = 1: r = 1 lattice unit = S
  // grid units). Every position of originals and copies lies in their box; the sentinels must lie
  // outside the box grown by 2 r (more than 2 rho from every point at every time, positions between
  // frames being convex combinations), and beyond each of its corners there must be one, so that
  // their hull holds every point strictly inside.
  const auto c = cover_trajectories(
      run({cell(1, {{500000, 0, 0}, {S, 2 * S, 0}}), cell(2, {{9 * S, 3 * S, 0}, {8 * S, 4 * S, 0}}),
           cell(3, {{5 * S, 6 * S, 0}, {4 * S, 7 * S, 0}})},
          2),
      x_period_10(), radius_one());
  REQUIRE(c.sentinels > 4);
  REQUIRE(c.originals + c.ghosts() + c.sentinels == c.trajectories.cells.size());
  std::array<std::int64_t, 2> lo{c.trajectories.cells[0].positions[0][0],
                                 c.trajectories.cells[0].positions[0][1]};
  std::array<std::int64_t, 2> hi = lo;
  for (std::size_t v = 0; v < c.originals + c.ghosts(); ++v)
    for (const kinetic::GridPoint& p : c.trajectories.cells[v].positions)
      for (std::size_t a = 0; a < 2; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
  std::array<bool, 4> corner{};
  for (std::size_t v = c.originals + c.ghosts(); v < c.trajectories.cells.size(); ++v) {
    const kinetic::Trajectory& t = c.trajectories.cells[v];
    CHECK(c.vertices[v].is_sentinel());
    CHECK(t.cell_id == -1);
    REQUIRE(t.positions.size() == 2);
    CHECK(t.positions[0] == t.positions[1]);
    const kinetic::GridPoint& p = t.positions[0];
    CHECK(p[2] == 0);
    const bool outside =
        p[0] < lo[0] - 2 * S || p[0] > hi[0] + 2 * S || p[1] < lo[1] - 2 * S || p[1] > hi[1] + 2 * S;
    CHECK(outside);
    for (std::size_t k = 0; k < 4; ++k)
      if ((k & 1 ? p[0] > hi[0] : p[0] < lo[0]) && (k & 2 ? p[1] > hi[1] : p[1] < lo[1]))
        corner[k] = true;
  }
  CHECK(corner == std::array<bool, 4>{true, true, true, true});
}
