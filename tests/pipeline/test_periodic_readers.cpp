// Periodic CompuCell3D lattices: periodic voxel means, CSV centres wrapped into the lattice, and
// trajectories unwrapped by the minimum image (docs/MATH.md §8.1, §8.2). Expected values are worked out
// by hand in the comments.
#include "io_test_support.h"
#include "medusa/io/periodic_domain.h"
#include "medusa/io/periodic_unwrap.h"
#include "medusa/io/run_reader.h"
#include "medusa/io/vtk_reader.h"

#include <fstream>
#include <map>
#include <sstream>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;
using io::test::cc3d_xml;
using io::test::write;
namespace fs = std::filesystem;

namespace {

constexpr std::int64_t S = 1000000;

const std::string periodic_x = "    <Boundary_x>Periodic</Boundary_x>\n";

// A CC3D-like ASCII snapshot of an nx x ny x nz lattice; `cells` maps voxel (x,y,z) to a cell id (type 1).
std::string snapshot(std::int64_t nx, std::int64_t ny, std::int64_t nz,
                     const std::map<std::array<std::int64_t, 3>, std::int64_t>& cells) {
  const std::int64_t n = nx * ny * nz;
  std::ostringstream types, ids;
  for (std::int64_t p = 0; p < n; ++p) {
    const auto it = cells.find({p % nx, (p / nx) % ny, p / (nx * ny)});
    ids << (it == cells.end() ? 0 : it->second) << ' ';
    types << (it == cells.end() ? 0 : 1) << ' ';
  }
  std::ostringstream out;
  out << "# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS " << nx << ' '
      << ny << ' ' << nz << "\nSPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA " << n
      << "\nFIELD FieldData 2\nCellType 1 " << n << " unsigned_char\n"
      << types.str() << "\nCellId 1 " << n << " long\n"
      << ids.str() << "\n";
  return out.str();
}

} // namespace

TEST_CASE("The minimum image and the wrap reduce differences and coordinates exactly", "[io][periodic]") {
  CHECK(minimum_image(7, 10) == -3);
  CHECK(minimum_image(4, 10) == 4);
  CHECK(minimum_image(-6, 10) == 4);
  CHECK(minimum_image(5, 10) == -5); // half a period: the representative in [-5, 5) is -5
  CHECK(minimum_image(-5, 10) == -5);
  CHECK(minimum_image(25, 10) == -5);
  CHECK(minimum_image(-49999999, 50000000) == 1);
  CHECK(wrap_coordinate(-1, 0, 10) == 9);
  CHECK(wrap_coordinate(10, 0, 10) == 0);
  CHECK(wrap_coordinate(23, 5, 10) == 13);
  CHECK(wrap_coordinate(4, 5, 10) == 14);
  PeriodicDomain d;
  d.periodic = {true, false, true};
  d.period = {10, 0, 4};
  CHECK(wrap_into_domain(d, {-1, -1, 9}) == kinetic::GridPoint{9, -1, 1});
  CHECK(d.axes() == "x,z");
}

TEST_CASE("A VTK cell split by a periodic seam has the periodic mean of its voxels as centre",
          "[io][periodic]") {
  io::test::TempDir dir;
  // 10 x 4 x 2, periodic along x. Cell 1: x = 9, 0, 1 (unwrapped -1, 0, 1: mean 0). Cell 2: x = 8, 9 at
  // y = 2 and x = 0 at y = 3 (unwrapped 8, 9, 10: mean 9; y mean 7/3 is not periodic, so plain).
  // Cell 3 does not straddle: x = 4, 5 (mean 4.5).
  write(dir.file("Step_0.vtk"), snapshot(10, 4, 2,
                                         {{{9, 0, 0}, 1},
                                          {{0, 0, 0}, 1},
                                          {{1, 0, 0}, 1},
                                          {{8, 2, 1}, 2},
                                          {{9, 2, 1}, 2},
                                          {{0, 3, 1}, 2},
                                          {{4, 1, 0}, 3},
                                          {{5, 1, 0}, 3}}));
  const VtkSnapshot v = read_vtk_snapshot(dir.file("Step_0.vtk"), S, {true, false, false});
  REQUIRE(v.cells.size() == 3);
  CHECK(v.cells[0].scaled_sum == std::array<std::int64_t, 3>{0, 0, 0});
  CHECK(v.cells[1].scaled_sum == std::array<std::int64_t, 3>{27 * S, 7 * S, 3 * S});
  CHECK(v.cells[2].scaled_sum == std::array<std::int64_t, 3>{9 * S, 2 * S, 0});
  // Read as open, cell 1 is the plain mean (9 + 0 + 1) / 3, far from its voxels.
  const VtkSnapshot open = read_vtk_snapshot(dir.file("Step_0.vtk"), S);
  CHECK(open.cells[0].scaled_sum == std::array<std::int64_t, 3>{10 * S, 0, 0});
}

TEST_CASE("A periodic mean just below the seam stays inside the lattice", "[io][periodic]") {
  io::test::TempDir dir;
  // Voxels x = 9, 9, 0 along x (L = 10), first voxel in file order x = 0 at y = 0: unwrapped 0, -1, -1
  // (mean -2/3), reduced into [0, 10): 28/3, i.e. X = 3 * 28/3 * S = 28 S.
  write(dir.file("Step_0.vtk"), snapshot(10, 2, 2, {{{0, 0, 0}, 1}, {{9, 1, 0}, 1}, {{9, 0, 1}, 1}}));
  const VtkSnapshot v = read_vtk_snapshot(dir.file("Step_0.vtk"), S, {true, false, false});
  REQUIRE(v.cells.size() == 1);
  CHECK(v.cells[0].scaled_sum[0] == 28 * S);
}

TEST_CASE("A VTK cell spanning half the period along a periodic axis is refused naming file and cell",
          "[io][periodic]") {
  io::test::TempDir dir;
  // L = 10: voxels at x = 0 and 4 span 5 sites (accepted, mean 2); x = 0 and 5 are half a period apart.
  write(dir.file("Step_7.vtk"), snapshot(10, 2, 2, {{{0, 0, 0}, 1}, {{4, 1, 1}, 1}}));
  const VtkSnapshot ok = read_vtk_snapshot(dir.file("Step_7.vtk"), S, {true, false, false});
  CHECK(ok.cells[0].scaled_sum[0] == 4 * S);
  write(dir.file("Step_8.vtk"),
        snapshot(10, 2, 2, {{{0, 0, 0}, 1}, {{5, 1, 1}, 4}, {{5, 0, 1}, 4}, {{0, 1, 0}, 4}}));
  const std::string m = io::test::input_error([&] {
    read_vtk_snapshot(dir.file("Step_8.vtk"), S, {true, false, false});
  });
  CHECK_THAT(m, Contains("Step_8.vtk") && Contains("cell 4") && Contains("along x") &&
                    Contains("half the period"));
}

TEST_CASE("A VTK run followed across a periodic seam has a continuous trajectory", "[io][periodic]") {
  io::test::TempDir dir;
  // The cell's two voxels move one site per frame in +x across x = 9 | 0 (L = 10): means 8.5, 9.5,
  // 0.5 + 10 = 10.5; read as open, the last frame would jump back to 0.5.
  write(dir.file("LatticeData/Step_0.vtk"), snapshot(10, 2, 2, {{{8, 0, 0}, 1}, {{9, 0, 0}, 1}}));
  write(dir.file("LatticeData/Step_1.vtk"), snapshot(10, 2, 2, {{{9, 0, 0}, 1}, {{0, 0, 0}, 1}}));
  write(dir.file("LatticeData/Step_2.vtk"), snapshot(10, 2, 2, {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}}));
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"2\" z=\"2\"", periodic_x));
  RunOptions o;
  o.allow_periodic_as_open = true;
  const RunData r = read_run(dir.path().string(), o);
  REQUIRE(r.trajectories.cells.size() == 1);
  CHECK(r.trajectories.cells[0].positions ==
        std::vector<kinetic::GridPoint>{{8500000, 0, 0}, {9500000, 0, 0}, {10500000, 0, 0}});
  CHECK(r.domain.axes() == "x");
  CHECK(r.domain.period == std::array<std::int64_t, 3>{10 * S, 0, 0});
}

TEST_CASE("CSV centres on a periodic lattice are wrapped into it and unwrapped between frames",
          "[io][periodic]") {
  io::test::TempDir dir;
  // L = 10 along x. Cell 1 crosses the seam forwards: 9.5, 0.5, 1.5 -> 9.5, 10.5, 11.5. Cell 2 starts at
  // x = 10 (the same point as 0, CC3D writes [0, L]) and crosses backwards: 0, 9.75, 9 -> 0, -0.25, -1.
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
                               "0,1,1,9.5,1,1\n0,2,1,10,3,3\n"
                               "100,1,1,0.5,1,1\n100,2,1,9.75,3,3\n"
                               "200,1,1,1.5,1,1\n200,2,1,9,3,3\n");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\"", periodic_x));
  RunOptions o;
  o.allow_periodic_as_open = true;
  const RunData r = read_run(dir.path().string(), o);
  REQUIRE(r.trajectories.cells.size() == 2);
  CHECK(r.trajectories.cells[0].positions ==
        std::vector<kinetic::GridPoint>{{9500000, S, S}, {10500000, S, S}, {11500000, S, S}});
  CHECK(r.trajectories.cells[1].positions ==
        std::vector<kinetic::GridPoint>{{0, 3 * S, 3 * S}, {-250000, 3 * S, 3 * S}, {-S, 3 * S, 3 * S}});
  CHECK(r.domain.axes() == "x");
}

TEST_CASE("A planar run periodic in x and y is unwrapped in both", "[io][periodic]") {
  io::test::TempDir dir;
  // 8 x 8 x 1, periodic x and y: the cell moves (+1, -1) per frame from (7.5, 0.5): (8.5, -0.5), (9.5, -1.5).
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
                               "0,1,1,7.5,0.5,0\n0,2,1,3,3,0\n0,3,1,4,3,0\n"
                               "10,1,1,0.5,7.5,0\n10,2,1,3,3,0\n10,3,1,4,3,0\n"
                               "20,1,1,1.5,6.5,0\n20,2,1,3,3,0\n20,3,1,4,3,0\n");
  write(dir.file("Simulation/run.xml"),
        cc3d_xml("x=\"8\" y=\"8\" z=\"1\"", periodic_x + "    <Boundary_y>Periodic</Boundary_y>\n"));
  RunOptions o;
  o.allow_periodic_as_open = true;
  const RunData r = read_run(dir.path().string(), o);
  CHECK(r.trajectories.dimension == 2);
  REQUIRE(r.trajectories.cells.size() == 3);
  CHECK(r.trajectories.cells[0].positions ==
        std::vector<kinetic::GridPoint>{{7500000, 500000, 0}, {8500000, -500000, 0}, {9500000, -1500000, 0}});
  CHECK(r.domain.axes() == "x,y");
}

TEST_CASE("A step of half the period between frames is refused naming the cell and both MCS",
          "[io][periodic]") {
  io::test::TempDir dir;
  // L = 10: from 1 to 6 is +5 or -5, both minimal.
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
                               "0,1,1,2,1,1\n0,7,1,1,5,5\n"
                               "100,1,1,2.5,1,1\n100,7,1,6,5,5\n");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\"", periodic_x));
  RunOptions o;
  o.allow_periodic_as_open = true;
  const std::string m = io::test::input_error([&] { read_run(dir.path().string(), o); });
  CHECK_THAT(m, Contains("cells.csv") && Contains("cell 7") && Contains("moves 5 along x") &&
                    Contains("MCS 0 and MCS 100") && Contains("ambiguous"));
}

TEST_CASE("A CSV centre outside the periodic lattice is refused naming line and cell", "[io][periodic]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,2,1,1\n0,3,1,10.000001,1,1\n");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\"", periodic_x));
  RunOptions o;
  o.allow_periodic_as_open = true;
  const std::string m = io::test::input_error([&] { read_run(dir.path().string(), o); });
  CHECK_THAT(m, Contains("cells.csv:3") && Contains("cell 3") && Contains("xCOM") && Contains("[0, 10]"));
}
