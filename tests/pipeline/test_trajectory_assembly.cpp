#include "io_test_support.h"
#include "medusa/io/trajectory_assembly.h"

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

namespace {
CellSample sample(std::int64_t mcs, std::int64_t id, int type, std::int64_t x, std::int64_t line) {
  CellSample s;
  s.mcs = mcs;
  s.cell_id = id;
  s.type = type;
  s.position = {x, 0, 0};
  s.volume = 10 + x;
  s.line = line;
  return s;
}
} // namespace

TEST_CASE("Cells appearing late and ending early become shorter trajectories", "[io][assembly]") {
  const std::vector<CellSample> samples = {sample(0, 1, 1, 0, 2), sample(10, 1, 1, 1, 3),
                                           sample(10, 2, 2, 5, 4), sample(20, 2, 2, 6, 5)};
  const AssembledRun r = assemble_trajectories(samples, {"f"}, 1000000, 3);
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 10, 20});
  REQUIRE(r.trajectories.cells.size() == 2);
  CHECK(r.trajectories.cells[0].first_frame == 0);
  CHECK(r.trajectories.cells[0].last_frame() == 1);
  CHECK(r.trajectories.cells[1].first_frame == 1);
  CHECK(r.trajectories.cells[1].last_frame() == 2);
  CHECK(r.volumes == std::vector<std::vector<std::int64_t>>{{10, 11}, {15, 16}});
  CHECK(r.warnings.empty());
}

TEST_CASE("Explicit frame times keep frames that hold no cell", "[io][assembly]") {
  const AssembledRun r =
      assemble_trajectories({sample(0, 1, 1, 0, 0), sample(20, 1, 1, 0, 0)}, {"f"}, 1000000, 3, {0, 10, 20});
  CHECK(r.trajectories.frame_times.size() == 3);
  CHECK(r.trajectories.cells.size() == 2); // split around the empty frame
}

TEST_CASE("A sample at an MCS that is not a frame is refused", "[io][assembly]") {
  CHECK_THAT(io::test::input_error([] {
               assemble_trajectories({sample(5, 7, 1, 0, 3)}, {"f.csv"}, 1000000, 3, {0, 10});
             }),
             Contains("f.csv:3") && Contains("cell 7") && Contains("MCS 5"));
}

TEST_CASE("Volumes are dropped when one sample lacks them", "[io][assembly]") {
  std::vector<CellSample> s = {sample(0, 1, 1, 0, 0), sample(10, 1, 1, 0, 0)};
  s[1].volume = -1;
  CHECK(assemble_trajectories(s, {"f"}, 1000000, 3).volumes.empty());
}

TEST_CASE("Each trajectory holds its positions and volumes without spare capacity", "[io][assembly]") {
  // Five frames: grown one by one, a list of five would have room for eight.
  std::vector<CellSample> samples;
  for (std::int64_t k = 0; k < 5; ++k)
    samples.push_back(sample(10 * k, 1, 1, k, k + 2));
  const AssembledRun r = assemble_trajectories(samples, {"f"}, 1000000, 3);
  REQUIRE(r.trajectories.cells.size() == 1);
  CHECK(r.trajectories.cells[0].positions.size() == 5);
  CHECK(r.trajectories.cells[0].positions.capacity() == 5);
  REQUIRE(r.volumes.size() == 1);
  CHECK(r.volumes[0].capacity() == 5);
}
