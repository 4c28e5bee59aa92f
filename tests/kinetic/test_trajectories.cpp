#include "medusa/core/error.h"
#include "medusa/kinetic/trajectories.h"

#include <catch2/catch.hpp>

using namespace medusa::kinetic;

namespace {
Trajectories two_frames() {
  Trajectories t;
  t.frame_times = {0, 100};
  t.cells.push_back({1, 1, 0, {{0, 0, 0}, {1, 1, 1}}});
  t.cells.push_back({2, 2, 1, {{5, 0, 0}}});
  return t;
}
} // namespace

TEST_CASE("a consistent run validates", "[kinetic][trajectories]") {
  REQUIRE_NOTHROW(two_frames().validate());
}

TEST_CASE("frame times that do not increase are rejected with the frame named", "[kinetic][trajectories]") {
  Trajectories t = two_frames();
  t.frame_times = {100, 100};
  REQUIRE_THROWS_WITH(t.validate(), Catch::Contains("frame 1"));
}

TEST_CASE("a cell present beyond the last frame is rejected with its id", "[kinetic][trajectories]") {
  Trajectories t = two_frames();
  t.cells[1].positions.push_back({6, 0, 0});
  REQUIRE_THROWS_AS(t.validate(), medusa::InputError);
  REQUIRE_THROWS_WITH(t.validate(), Catch::Contains("cell 2"));
}

TEST_CASE("a trajectory knows on which frames it is present", "[kinetic][trajectories]") {
  Trajectories t = two_frames();
  REQUIRE(t.cells[1].present(1));
  REQUIRE_FALSE(t.cells[1].present(0));
  REQUIRE(t.cells[0].last_frame() == 1);
  REQUIRE(t.cells[0].at(1) == GridPoint{1, 1, 1});
}
