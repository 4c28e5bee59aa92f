#include "io_test_support.h"
#include "medusa/io/centroid.h"
#include "medusa/io/vtk_reader.h"

#include <fstream>
#include <zlib.h>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

namespace {

constexpr std::int64_t S = 1000000;

// The voxels of tests/data/io/vtk_split_cell.vtk (4 x 3 x 2, x fastest): cell 1 (type 1) is the square
// (0..1, 0..1, 0) plus a stray voxel (3,2,1); cell 2 (type 2) is (3,0,0), (3,1,0), (2,0,1).
std::vector<int> split_types() {
  return {1, 1, 0, 2, 1, 1, 0, 2, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 1};
}

void put_big_endian(std::string& out, std::uint64_t v, int bytes) {
  for (int b = bytes - 1; b >= 0; --b)
    out.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
}

// The same lattice as a BINARY legacy file (big-endian, as vtkDataWriter writes it), with a
// non-trivial origin and spacing.
std::string binary_split_cell() {
  const std::vector<int> types = split_types();
  std::string s = "# vtk DataFile Version 3.0\nbinary test\nBINARY\nDATASET STRUCTURED_POINTS\n"
                  "DIMENSIONS 4 3 2\nSPACING 2 2 2\nORIGIN 0.5 -1 2\nPOINT_DATA 24\nFIELD FieldData 3\n";
  s += "CellType 1 24 unsigned_char\n";
  for (int t : types)
    put_big_endian(s, static_cast<std::uint64_t>(t), 1);
  s += "\nCellId 1 24 long\n";
  for (int t : types)
    put_big_endian(s, static_cast<std::uint64_t>(t), 8); // ids equal types in this lattice
  s += "\nClusterId 1 24 int\n";
  for (int t : types)
    put_big_endian(s, static_cast<std::uint64_t>(t), 4);
  s += "\n";
  return s;
}

void write_file(const std::string& path, const std::string& bytes, bool gzip) {
  if (gzip) {
    gzFile f = gzopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    REQUIRE(gzwrite(f, bytes.data(), static_cast<unsigned>(bytes.size())) == static_cast<int>(bytes.size()));
    REQUIRE(gzclose(f) == Z_OK);
  } else {
    std::ofstream(path, std::ios::binary) << bytes;
  }
}

std::string vtk_error(const std::string& fixture) {
  return io::test::input_error([&] { read_vtk_snapshot(io::test::data("io/" + fixture), S); });
}

} // namespace

TEST_CASE("A cell split into pieces has the centroid of all its voxels", "[io][vtk]") {
  const VtkSnapshot v = read_vtk_snapshot(io::test::data("io/vtk_split_cell.vtk"), S);
  CHECK(v.dimensions == std::array<std::int64_t, 3>{4, 3, 2});
  CHECK(v.origin == std::array<std::int64_t, 3>{0, 0, 0});
  CHECK(v.spacing == std::array<std::int64_t, 3>{S, S, S});
  CHECK_FALSE(v.binary);
  REQUIRE(v.cells.size() == 2);
  // Cell 1: x indices 0+1+0+1+3 = 5, y 0+0+1+1+2 = 4, z 1; n = 5 -> centroid (1, 0.8, 0.2).
  CHECK(v.cells[0].id == 1);
  CHECK(v.cells[0].type == 1);
  CHECK(v.cells[0].voxels == 5);
  CHECK(v.cells[0].scaled_sum == std::array<std::int64_t, 3>{5 * S, 4 * S, 1 * S});
  CHECK(centroid_on_grid(v.cells[0].scaled_sum, 5));
  // Cell 2: x 3+3+2 = 8, y 0+1+0 = 1, z 1; n = 3 -> (8/3, 1/3, 1/3), off the grid.
  CHECK(v.cells[1].id == 2);
  CHECK(v.cells[1].type == 2);
  CHECK(v.cells[1].voxels == 3);
  CHECK(v.cells[1].scaled_sum == std::array<std::int64_t, 3>{8 * S, 1 * S, 1 * S});
  CHECK_FALSE(centroid_on_grid(v.cells[1].scaled_sum, 3));
}

TEST_CASE("Binary big-endian and gzip snapshots read like ASCII ones with origin and spacing", "[io][vtk]") {
  io::test::TempDir dir;
  for (const bool gzip : {false, true}) {
    CAPTURE(gzip);
    const std::string path = dir.file(gzip ? "Step_7.vtk.gz" : "Step_7.vtk");
    write_file(path, binary_split_cell(), gzip);
    const VtkSnapshot v = read_vtk_snapshot(path, S);
    CHECK(v.binary);
    CHECK(v.origin == std::array<std::int64_t, 3>{S / 2, -S, 2 * S});
    CHECK(v.spacing == std::array<std::int64_t, 3>{2 * S, 2 * S, 2 * S});
    REQUIRE(v.cells.size() == 2);
    // X = n*S*origin + S*spacing*sum(index): cell 1 -> centroid (0.5+2*1, -1+2*0.8, 2+2*0.2) = (2.5,
    // 0.6, 2.4).
    CHECK(v.cells[0].voxels == 5);
    CHECK(v.cells[0].scaled_sum == std::array<std::int64_t, 3>{5 * 2500000, 5 * 600000, 5 * 2400000});
    CHECK(v.cells[1].voxels == 3);
    CHECK(v.cells[1].scaled_sum ==
          std::array<std::int64_t, 3>{3 * S / 2 + 16 * S, -3 * S + 2 * S, 6 * S + 2 * S});
    CHECK(vtk_step_mcs(path) == 7);
  }
}

TEST_CASE("Snapping a centroid rounds to the nearest grid point with ties to even", "[io][vtk]") {
  SnapReport r;
  // (8e6/3, 1e6/3, 1e6/3) -> (2666667, 333333, 333333), each moved by 1/3.
  CHECK(snap_centroid({8 * S, S, S}, 3, r) == kinetic::GridPoint{2666667, 333333, 333333});
  CHECK(r.moved == 1);
  CHECK(r.max_displacement_num == 1);
  CHECK(r.max_displacement_den == 3);
  // Ties: 5/2 -> 2, 7/2 -> 4, -5/2 -> -2, -7/2 -> -4; exact values do not count as moved.
  CHECK(snap_centroid({5, 7, -5}, 2, r) == kinetic::GridPoint{2, 4, -2});
  CHECK(snap_centroid({-7, 6, 0}, 2, r) == kinetic::GridPoint{-4, 3, 0});
  CHECK(r.moved == 3);
  CHECK(r.max_displacement_num == 1);
  CHECK(r.max_displacement_den == 2);
  CHECK(snap_centroid({10, 20, -30}, 10, r) == kinetic::GridPoint{1, 2, -3});
  CHECK(r.moved == 3);
}

TEST_CASE("A snapshot whose POINT_DATA does not match DIMENSIONS is refused", "[io][vtk]") {
  CHECK_THAT(vtk_error("vtk_wrong_dimensions.vtk"), Contains("vtk_wrong_dimensions.vtk:8") &&
                                                        Contains("POINT_DATA 23") &&
                                                        Contains("DIMENSIONS 4 3 2"));
}

TEST_CASE("A snapshot with too few values is refused naming the array", "[io][vtk]") {
  CHECK_THAT(vtk_error("vtk_too_few_values.vtk"),
             Contains("vtk_too_few_values.vtk") && Contains("CellId has only 20 of 24 values"));
}

TEST_CASE("A snapshot with a bad token is refused naming file and line", "[io][vtk]") {
  CHECK_THAT(vtk_error("vtk_bad_token.vtk"),
             Contains("vtk_bad_token.vtk:15") && Contains("'x7'") && Contains("CellId"));
}

TEST_CASE("A cell whose voxels carry two types is refused naming the cell", "[io][vtk]") {
  CHECK_THAT(vtk_error("vtk_type_conflict.vtk"), Contains("vtk_type_conflict.vtk") && Contains("cell 1") &&
                                                     Contains("type 1") && Contains("type 2") &&
                                                     Contains("(0,1,0)"));
}

TEST_CASE("A truncated gzip snapshot is refused naming the file", "[io][vtk]") {
  CHECK_THAT(vtk_error("vtk_truncated.vtk.gz"), Contains("vtk_truncated.vtk.gz"));
}

TEST_CASE("Snapshot MCS comes from the Step_<MCS> file name", "[io][vtk]") {
  CHECK(vtk_step_mcs("/a/b/LatticeData/Step_0100.vtk.gz") == 100);
  CHECK(vtk_step_mcs("Step_09500.vtk") == 9500);
  CHECK(is_vtk_step_name("Step_0.vtk"));
  CHECK_FALSE(is_vtk_step_name("Step_.vtk"));
  CHECK_FALSE(is_vtk_step_name("StepLDF.dml"));
  CHECK_THAT(io::test::input_error([] { vtk_step_mcs("/x/lattice.vtk"); }), Contains("/x/lattice.vtk"));
}

TEST_CASE("A file that is not a STRUCTURED_POINTS snapshot is refused", "[io][vtk]") {
  io::test::TempDir dir;
  write_file(dir.file("grid.vtk"), "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n",
             false);
  write_file(dir.file("text.vtk"), "hello\n", false);
  CHECK_THAT(io::test::input_error([&] { read_vtk_snapshot(dir.file("grid.vtk"), S); }),
             Contains("grid.vtk") && Contains("STRUCTURED_POINTS"));
  CHECK_THAT(io::test::input_error([&] { read_vtk_snapshot(dir.file("text.vtk"), S); }),
             Contains("text.vtk:1") && Contains("legacy VTK"));
}
