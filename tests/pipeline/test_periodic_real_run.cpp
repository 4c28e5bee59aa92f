// The real periodic CompuCell3D run (tests/data/cc3d/periodic_3d: 50 x 50 x 40, periodic in x and y)
// read with its periodic axes (docs/MATH.md §8.1, §8.2): CC3D's own CenterOfMass centres are the oracle.
#include "io_test_support.h"
#include "medusa/io/csv_reader.h"
#include "medusa/io/periodic_domain.h"
#include "medusa/io/run_reader.h"
#include "medusa/io/vtk_reader.h"

#include <map>

using namespace medusa;
using namespace medusa::io;

namespace {

std::string run_path() { return io::test::data("cc3d/periodic_3d"); }

RunData read(RunSource source) {
  RunOptions o;
  o.source = source;
  o.snap = true;
  o.allow_periodic_as_open = true;
  return read_run(run_path(), o);
}

} // namespace

TEST_CASE("The real periodic run's VTK periodic means equal CC3D's centres modulo the period",
          "[io][real][periodic]") {
  const RunData vtk = read(RunSource::vtk);
  REQUIRE(vtk.domain.axes() == "x,y");
  CHECK(vtk.domain.period == std::array<std::int64_t, 3>{50000000, 50000000, 0});
  std::map<std::pair<std::int64_t, std::int64_t>, kinetic::GridPoint> csv;
  for (const CellSample& s : read_csv(run_path() + "/cells.csv.gz").samples)
    csv[{s.mcs, s.cell_id}] = s.position;
  std::size_t compared = 0;
  for (const kinetic::Trajectory& c : vtk.trajectories.cells)
    for (std::size_t k = c.first_frame; k <= c.last_frame(); ++k) {
      CAPTURE(c.cell_id, k);
      const auto it = csv.find({vtk.trajectories.frame_times[k], c.cell_id});
      REQUIRE(it != csv.end());
      // CC3D prints its minimum-image mean with %.6f, the VTK mean is snapped to the same 10^-6 grid
      // (ties to even). Along x and y CC3D's double sums go through shifts by the period, so at an
      // exact tie (n = 128 voxels gives 7 decimals) it may round the other way: the two agree to one
      // grid unit modulo L. Along z (NoFlux, a plain mean) they agree exactly.
      for (std::size_t a = 0; a < 2; ++a)
        CHECK(std::abs(minimum_image(c.at(k)[a] - it->second[a], 50000000)) <= 1);
      CHECK(c.at(k)[2] == it->second[2]);
      ++compared;
    }
  CHECK(compared == 600); // 300 cells x the 2 bundled snapshots
  // The seams are exercised: at MCS 100 some cells straddle one, and their plain voxel mean (the
  // snapshot read as open) is far from their periodic mean.
  const std::string file = run_path() + "/LatticeData/Step_0100.vtk.gz";
  const VtkSnapshot periodic = read_vtk_snapshot(file, 1000000, {true, true, false});
  const VtkSnapshot open = read_vtk_snapshot(file, 1000000);
  REQUIRE(periodic.cells.size() == open.cells.size());
  std::size_t straddling = 0;
  for (std::size_t i = 0; i < open.cells.size(); ++i)
    if (periodic.cells[i].scaled_sum != open.cells[i].scaled_sum)
      ++straddling;
  CHECK(straddling > 0);
}

TEST_CASE("The real periodic run's CSV trajectories cross the seams without jumps", "[io][real][periodic]") {
  const RunData csv = read(RunSource::csv);
  REQUIRE(csv.trajectories.frames() == 21);
  std::int64_t largest_step = 0;
  std::size_t crossings = 0;
  for (const kinetic::Trajectory& c : csv.trajectories.cells)
    for (std::size_t j = 1; j < c.positions.size(); ++j)
      for (std::size_t a = 0; a < 3; ++a) {
        const std::int64_t step = std::abs(c.positions[j][a] - c.positions[j - 1][a]);
        largest_step = std::max(largest_step, step);
        if (a < 2 && wrap_coordinate(c.positions[j][a], 0, 50000000) != c.positions[j][a] &&
            wrap_coordinate(c.positions[j - 1][a], 0, 50000000) == c.positions[j - 1][a])
          ++crossings;
      }
  // Cells of 125 voxels move a few sites per 100 MCS; read as open, a seam crossing was a ~50-site jump.
  CHECK(largest_step < 10000000);
  CHECK(crossings > 0);
  // The VTK and CSV readings of the two bundled snapshots give the same unwrapped trajectories.
  const RunData vtk = read(RunSource::vtk);
  REQUIRE(vtk.trajectories.cells.size() == csv.trajectories.cells.size());
  for (std::size_t i = 0; i < vtk.trajectories.cells.size(); ++i) {
    CAPTURE(vtk.trajectories.cells[i].cell_id);
    const kinetic::GridPoint a0 = csv.trajectories.cells[i].at(0), b0 = vtk.trajectories.cells[i].at(0);
    const kinetic::GridPoint a1 = csv.trajectories.cells[i].at(1), b1 = vtk.trajectories.cells[i].at(1);
    for (std::size_t a = 0; a < 3; ++a) // each position within one grid unit (above)
      CHECK(std::abs((a1[a] - a0[a]) - (b1[a] - b0[a])) <= 2);
  }
}
