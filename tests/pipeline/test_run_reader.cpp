#include "io_test_support.h"
#include "medusa/io/run_reader.h"

#include <fstream>
#include <sys/stat.h>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;
using io::test::cc3d_xml;
using io::test::write;
namespace fs = std::filesystem;

namespace {

constexpr std::int64_t S = 1000000;

bool has_warning(const RunData& r, const std::string& part) {
  for (const std::string& w : r.warnings)
    if (w.find(part) != std::string::npos)
      return true;
  return false;
}

} // namespace

TEST_CASE("A CSV run becomes trajectories and a cell missing from a middle frame is split", "[io][run]") {
  const RunData r = read_run(io::test::data("io/gap.csv"));
  const kinetic::Trajectories& t = r.trajectories;
  CHECK(r.used == RunSource::csv);
  CHECK(r.position_convention == "csv-centres");
  CHECK(r.sources == std::vector<std::string>{io::test::data("io/gap.csv")});
  CHECK(t.dimension == 3);
  CHECK(t.scale == S);
  CHECK(t.frame_times == std::vector<std::int64_t>{0, 100, 200});
  REQUIRE(t.cells.size() == 5);
  const std::vector<std::int64_t> ids = {t.cells[0].cell_id, t.cells[1].cell_id, t.cells[2].cell_id,
                                         t.cells[3].cell_id, t.cells[4].cell_id};
  CHECK(ids == std::vector<std::int64_t>{1, 2, 3, 3, 4});
  CHECK(t.cells[0].positions == std::vector<kinetic::GridPoint>{{1000000, 2000000, 3000000},
                                                                {1500000, 2000000, 3000000},
                                                                {2000000, 2500000, 3000000}});
  CHECK(t.cells[1].type == 2);
  CHECK(t.cells[2].first_frame == 0);
  CHECK(t.cells[2].positions == std::vector<kinetic::GridPoint>{{7000000, 8000000, 9000000}});
  CHECK(t.cells[3].first_frame == 2);
  CHECK(t.cells[3].positions == std::vector<kinetic::GridPoint>{{7000000, 8500000, 9000000}});
  CHECK(t.cells[4].first_frame == 2);
  CHECK(t.cells[4].positions == std::vector<kinetic::GridPoint>{{-1000001, 1, 10000000}});
  CHECK(r.volumes == CellVolumes{{125, 126, 124}, {120, 119, 121}, {130}, {131}, {20}});
  CHECK(t.type_names == std::vector<std::string>{"", "Condensing", "NonCondensing"});
  CHECK(has_warning(r, "cell 3 is missing from MCS 100 to 100"));
  CHECK(has_warning(
      r, "1 trajectory is present on a single frame (cells 3): each joins and leaves the complex"));
  CHECK(has_warning(r, "2 trajectories are present at the last frame only (cells 3, 4)"));
}

TEST_CASE("A cell changing type between VTK frames is refused naming the file and cell", "[io][run]") {
  const std::string m = io::test::input_error([] { read_run(io::test::data("io/run_type_change")); });
  CHECK_THAT(m,
             Contains("Step_10.vtk") && Contains("cell 1") && Contains("type 2") && Contains("Step_0.vtk"));
}

TEST_CASE("VTK centroids off the grid are snapped by default and refused when exact positions are asked for",
          "[io][run]") {
  io::test::TempDir dir;
  fs::create_directories(dir.path() / "LatticeData");
  fs::copy_file(io::test::data("io/vtk_split_cell.vtk"), dir.path() / "LatticeData" / "Step_0.vtk");
  fs::copy_file(io::test::data("io/vtk_split_cell.vtk"), dir.path() / "LatticeData" / "Step_3.vtk");
  RunOptions exact;
  exact.snap = false;
  const std::string m = io::test::input_error([&] { read_run(dir.path().string(), exact); });
  CHECK_THAT(m,
             Contains("Step_0.vtk") && Contains("cell 2") && Contains("3 voxels") && Contains("--exact-vtk"));

  const RunData r = read_run(dir.path().string());
  CHECK(r.used == RunSource::vtk);
  CHECK(r.position_convention == "vtk-centroids-voxel-corner");
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 3});
  REQUIRE(r.trajectories.cells.size() == 2);
  CHECK(r.trajectories.cells[0].positions ==
        std::vector<kinetic::GridPoint>(2, kinetic::GridPoint{1000000, 800000, 200000}));
  CHECK(r.trajectories.cells[1].positions ==
        std::vector<kinetic::GridPoint>(2, kinetic::GridPoint{2666667, 333333, 333333}));
  CHECK(r.volumes == CellVolumes{{5, 5}, {3, 3}});
  CHECK(r.snap.snapped);
  CHECK(r.snap.positions == 4);
  CHECK(r.snap.moved == 2);
  CHECK(r.snap.max_displacement_num == 1);
  CHECK(r.snap.max_displacement_den == 3);
  REQUIRE(r.notes.size() == 1);
  CHECK_THAT(r.notes[0], Contains("VTK centroids snapped to the 10^-6 grid: 2 of 4 positions moved, the "
                                  "largest by 0.33 grid units (3.3e-07 lattice units)"));
}

TEST_CASE("A VTK run whose centroids lie on the grid needs no snapping", "[io][run]") {
  io::test::TempDir dir;
  fs::create_directories(dir.path() / "LatticeData");
  fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), dir.path() / "LatticeData" / "Step_5.vtk");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"4\" y=\"3\" z=\"2\""));
  const RunData r = read_run(dir.path().string());
  REQUIRE(r.trajectories.cells.size() == 1);
  CHECK(r.trajectories.cells[0].positions == std::vector<kinetic::GridPoint>{{1000000, 800000, 200000}});
  CHECK(r.trajectories.type_names == std::vector<std::string>{"Medium", "A", "B"});
  CHECK(r.snap.moved == 0);
  CHECK(r.simulation.has_value());
}

TEST_CASE("A VTK run whose lattice differs from the CC3DML is refused", "[io][run]") {
  io::test::TempDir dir;
  fs::create_directories(dir.path() / "LatticeData");
  fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), dir.path() / "LatticeData" / "Step_5.vtk");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"4\" y=\"3\" z=\"3\""));
  CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }),
             Contains("Step_5.vtk") && Contains("differ") && Contains("run.xml"));
}

TEST_CASE("A periodic run is refused unless periodic-as-open is allowed", "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,1,2,3\n0,2,1,4,5,6\n0,3,1,7,8,9\n"
                               "0,4,1,10,11,12\n0,5,1,13,14,15\n");
  write(dir.file("Simulation/run.xml"),
        cc3d_xml("x=\"20\" y=\"20\" z=\"20\"",
                 "    <Boundary_x>Periodic</Boundary_x>\n    <Boundary_z>Periodic</Boundary_z>\n"));
  CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }),
             Contains("run.xml") && Contains("periodic along x,z"));
  RunOptions open;
  open.allow_periodic_as_open = true;
  const RunData r = read_run(dir.path().string(), open);
  CHECK(r.trajectories.cells.size() == 5);
  CHECK(has_warning(r, "periodic boundaries along x,z"));
}

TEST_CASE("A run of one frame is read with a warning that nothing moves in it", "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("one.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n40,1,1,1,2,3\n40,2,1,4,5,6\n");
  const RunData one = read_run(dir.file("one.csv"));
  CHECK(has_warning(one, "one.csv has one frame (MCS 40): no cell moves"));
  write(dir.file("two.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n40,1,1,1,2,3\n50,1,1,4,5,6\n");
  CHECK_FALSE(has_warning(read_run(dir.file("two.csv")), "one frame"));
}

TEST_CASE("A run with lattice z extent 1 is planar", "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"),
        "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,1.5,2,0\n0,2,2,3,4,0\n10,1,1,1,2,0\n"
        "10,2,2,3,4.25,0\n");
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"1\""));
  const RunData r = read_run(dir.path().string());
  CHECK(r.trajectories.dimension == 2);
  CHECK(r.trajectories.cells.size() == 2);
  CHECK(r.volumes.empty());
  // With another or no lattice extent the same data is still planar, with a warning.
  RunOptions o;
  o.z_extent = 60;
  const RunData r60 = read_run(dir.file("cells.csv"), o);
  CHECK(r60.trajectories.dimension == 2);
  CHECK(has_warning(r60, "every z is equal but the lattice z extent is 60; read as a planar (2D) run"));
  io::test::TempDir alone; // no Simulation XML next to the CSV: the z extent is unknown
  write(alone.file("cells.csv"),
        "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,1.5,2,0\n0,2,2,3,4,0\n10,1,1,1,2,0\n10,2,2,3,4.25,0\n");
  const RunData lone = read_run(alone.file("cells.csv"));
  CHECK(lone.trajectories.dimension == 2);
  CHECK(has_warning(lone, "the lattice z extent is unknown; read as a planar (2D) run"));
}

TEST_CASE("A planar run with differing z is refused naming the line, MCS, cell and values", "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,1.5,2,0\n0,2,2,3,4,0.5\n");
  RunOptions o;
  o.z_extent = 1;
  CHECK_THAT(io::test::input_error([&] { read_run(dir.file("cells.csv"), o); }),
             Contains("cells.csv:3: MCS 0, cell 2: zCOM 0.5 differs from 0 at line 2, but the lattice's z "
                      "extent is 1"));
}

TEST_CASE("The source option chooses between VTK snapshots and the CSV", "[io][run]") {
  io::test::TempDir dir;
  fs::create_directories(dir.path() / "LatticeData");
  fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), dir.path() / "LatticeData" / "Step_5.vtk");
  fs::copy_file(io::test::data("io/gap.csv"), dir.path() / "cells.csv");
  CHECK(read_run(dir.path().string()).used == RunSource::vtk);
  RunOptions csv;
  csv.source = RunSource::csv;
  const RunData r = read_run(dir.path().string(), csv);
  CHECK(r.used == RunSource::csv);
  CHECK(r.trajectories.cells.size() == 5);
  CHECK(has_warning(r, "no CC3DML file"));
}

TEST_CASE("A folder with neither snapshots nor CSV, or a missing path, is refused", "[io][run]") {
  io::test::TempDir dir;
  CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }), Contains(dir.path().string()));
  CHECK_THAT(io::test::input_error([] { read_run("/nonexistent/run"); }), Contains("/nonexistent/run"));
  CHECK_THAT(io::test::input_error([] { read_run(io::test::data("io/vtk_split_cell.vtk")); }),
             Contains("vtk_split_cell.vtk") && Contains("folder"));
}

TEST_CASE("A CSV run whose CC3DML is cut off is refused, not read as open", "[io][run]") {
  io::test::TempDir dir;
  const std::string whole = cc3d_xml("x=\"50\" y=\"50\" z=\"40\"", "    <Boundary_x>Periodic</Boundary_x>\n");
  write((dir.path() / "Simulation" / "run.xml").string(), whole.substr(0, whole.find("<Boundary_x>")));
  fs::copy_file(io::test::data("io/gap.csv"), dir.path() / "cells.csv");
  CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }),
             Contains("run.xml") && Contains("boundary conditions cannot be read"));
}

TEST_CASE("A LatticeData snapshot that cannot be read or is cut short is an error naming it unless skipping "
          "is asked for",
          "[io][run]") {
  for (const std::string kind : {"dangling link", "FIFO", "folder", "cut short"}) {
    CAPTURE(kind);
    io::test::TempDir dir;
    const fs::path lattice = dir.path() / "LatticeData";
    fs::create_directories(lattice);
    fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), lattice / "Step_0.vtk");
    fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), lattice / "Step_20.vtk");
    const fs::path bad = lattice / "Step_10.vtk";
    if (kind == "dangling link")
      fs::create_symlink(dir.path() / "nowhere.vtk", bad);
    else if (kind == "FIFO")
      REQUIRE(::mkfifo(bad.c_str(), 0644) == 0);
    else if (kind == "folder")
      fs::create_directories(bad);
    else { // a copy interrupted part of the way: the file ends inside its cell data
      fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), bad);
      fs::resize_file(bad, fs::file_size(bad) * 2 / 3);
    }
    CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }),
               Contains("Step_10.vtk") && Contains("--skip-unreadable-frames"));
    RunOptions skip;
    skip.skip_unreadable_frames = true;
    const RunData r = read_run(dir.path().string(), skip);
    CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 20});
    CHECK(r.sources.size() == 2);
    CHECK(has_warning(r, "Step_10.vtk"));
  }
}

TEST_CASE("A LatticeData folder or one of its snapshots given as the run says to give the folder holding it",
          "[io][run]") {
  io::test::TempDir dir;
  const fs::path lattice = dir.path() / "LatticeData";
  fs::create_directories(lattice);
  fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), lattice / "Step_0.vtk");
  for (const std::string& path : {lattice.string(), lattice.string() + "/"})
    CHECK_THAT(io::test::input_error([&] { read_run(path); }),
               Contains("this is a LatticeData folder: give the CC3D output folder that holds it (" +
                        fs::absolute(dir.path()).lexically_normal().string() + ")"));
  CHECK_THAT(io::test::input_error([&] { read_run((lattice / "Step_0.vtk").string()); }),
             Contains("give the folder that holds LatticeData/ (" + dir.path().string() + ")"));
}

TEST_CASE("A snapshot missing from the middle of an evenly saved series is an error naming its MCS",
          "[io][run]") {
  io::test::TempDir dir;
  const fs::path lattice = dir.path() / "LatticeData";
  fs::create_directories(lattice);
  for (const char* name : {"Step_0.vtk", "Step_10.vtk", "Step_30.vtk", "Step_40.vtk"})
    fs::copy_file(io::test::data("io/vtk_split_cell_exact.vtk"), lattice / name);
  CHECK_THAT(io::test::input_error([&] { read_run(dir.path().string()); }),
             Contains("MCS 20 is missing") && Contains("Step_10.vtk") && Contains("Step_30.vtk"));
  RunOptions skip;
  skip.skip_unreadable_frames = true;
  const RunData r = read_run(dir.path().string(), skip);
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 10, 30, 40});
  CHECK(has_warning(r, "MCS 20 is missing"));
}

TEST_CASE("A series that stops a frame spacing or more before the simulation's last MCS is said to be "
          "missing frames",
          "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"), "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n0,1,1,1,2,3\n0,2,2,3,4,5\n"
                               "100,1,1,1,2,3.5\n100,2,2,3,4,5.5\n");
  // The simulation runs MCS 0 to 300: frames 200 and 300 are missing.
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\"", "    <Steps>301</Steps>\n"));
  const RunData cut = read_run(dir.path().string());
  CHECK(has_warning(cut, "the last frame read is MCS 100, but "));
  CHECK(has_warning(cut,
                    "runs to MCS 300 (<Steps>301</Steps>) with frames every 100 MCS: its later frames are "
                    "missing (a run still going, or files not copied), and the analysis covers MCS 0 to 100 "
                    "only"));
  // MCS 0 to 199: the next frame, MCS 200, would be beyond the run; nothing is said.
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\"", "    <Steps>200</Steps>\n"));
  CHECK_FALSE(has_warning(read_run(dir.path().string()), "the last frame read"));
}

namespace {

const std::string csv_header = "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n";

// The rows of `cells` cells at each MCS of `frames`, cell i at x = i.
std::string csv_rows(const std::vector<std::int64_t>& frames, int cells) {
  std::string text;
  for (const std::int64_t mcs : frames)
    for (int i = 1; i <= cells; ++i)
      text += std::to_string(mcs) + "," + std::to_string(i) + "," + std::to_string(1 + i % 2) + "," +
              std::to_string(i) + "," + std::to_string(i * i % 7) + "," + std::to_string(i * i * i % 5) +
              "\n";
  return text;
}

std::string csv_frames(const std::vector<std::int64_t>& frames, int cells) {
  return csv_header + csv_rows(frames, cells);
}

// The run read with --skip-unreadable-frames.
RunData read_skipping(const std::string& path) {
  RunOptions skip;
  skip.skip_unreadable_frames = true;
  return read_run(path, skip);
}

} // namespace

TEST_CASE("A CSV whose last frame stops part of the way through the one before is refused as still being "
          "written",
          "[io][run]") {
  io::test::TempDir dir;
  // A run still writing its CSV: MCS 200 has the first 3 of the 8 rows of MCS 100 (lines 18 to 20).
  write(dir.file("cells.csv"), csv_frames({0, 100}, 8) + csv_rows({200}, 3));
  CHECK_THAT(
      io::test::input_error([&] { read_run(dir.file("cells.csv")); }),
      Contains("cells.csv: the last frame, MCS 200, stops after 3 rows (lines 18 to 20) where MCS 100 has "
               "8 in the same order: a file still being written") &&
          Contains("--skip-unreadable-frames"));
  const RunData r = read_skipping(dir.file("cells.csv"));
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 100});
  CHECK(has_warning(r, "the last frame, MCS 200, stops after 3 rows"));
  CHECK(has_warning(r, "; left out"));
}

TEST_CASE("A CSV row with a mistyped MCS is refused naming the frame it makes", "[io][run]") {
  io::test::TempDir dir;
  // Cell 3's row of MCS 100 says 150 (line 12): a frame of one row lacking the 7 cells around it.
  std::string text = csv_frames({0}, 8);
  for (int i = 1; i <= 8; ++i)
    text += (i == 3 ? "150," : "100,") + std::to_string(i) + "," + std::to_string(1 + i % 2) + "," +
            std::to_string(i) + ",1,1\n";
  text += csv_rows({200}, 8);
  write(dir.file("cells.csv"), text);
  CHECK_THAT(io::test::input_error([&] { read_run(dir.file("cells.csv")); }),
             Contains("cells.csv: MCS 150 lacks 7 of the 7 cells present at MCS 100 and MCS 200, with 1 row "
                      "(line 12): an incomplete frame"));
  const RunData r = read_skipping(dir.file("cells.csv"));
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 100, 200});
  CHECK(has_warning(r, "MCS 150 lacks 7 of the 7 cells"));
  CHECK(has_warning(r, "cell 3 is missing from MCS 100"));
  CHECK_FALSE(has_warning(r, "no row has MCS"));
}

TEST_CASE("A CSV frame missing from the middle of an evenly saved series is refused naming its MCS",
          "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"), csv_frames({0, 100, 300, 400}, 6));
  CHECK_THAT(io::test::input_error([&] { read_run(dir.file("cells.csv")); }),
             Contains("cells.csv: no row has MCS 200: the frames go from MCS 100 to MCS 300, every 100 MCS "
                      "elsewhere") &&
                 Contains("--skip-unreadable-frames"));
  const RunData r = read_skipping(dir.file("cells.csv"));
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 100, 300, 400});
  CHECK(has_warning(r, "no row has MCS 200"));
}

TEST_CASE("CSV frames of cells dividing, dying or seeded, or saved unevenly, are read without a word",
          "[io][run]") {
  io::test::TempDir dir;
  const auto read_quietly = [&](const std::string& text, const std::vector<std::int64_t>& frames) {
    write(dir.file("cells.csv"), text);
    const RunData r = read_run(dir.file("cells.csv"));
    CHECK(r.trajectories.frame_times == frames);
    CAPTURE(r.warnings);
    CHECK(r.warnings.empty());
  };
  // 5 cells, then 12 (more than doubled by division between two saved frames).
  read_quietly(csv_frames({0, 100}, 5) + csv_rows({200, 300}, 12), {0, 100, 200, 300});
  // 20 cells, then 8 (12 died between two frames).
  read_quietly(csv_frames({0, 100}, 20) + csv_rows({200, 300}, 8), {0, 100, 200, 300});
  // Seeded over time: 4, 9, 19, 40 cells, then 40 again (cells new at the last frame are warned of).
  read_quietly(csv_frames({0}, 4) + csv_rows({100}, 9) + csv_rows({200}, 19) + csv_rows({300, 400}, 40),
               {0, 100, 200, 300, 400});
  // Saved at MCS 0, 10, 100, 1000; every 100 and then every 50 or every 10.
  read_quietly(csv_frames({0, 10, 100, 1000}, 6), {0, 10, 100, 1000});
  read_quietly(csv_frames({0, 100, 200, 250, 300}, 6), {0, 100, 200, 250, 300});
  read_quietly(csv_frames({0, 100, 200, 300, 310, 320, 330}, 6), {0, 100, 200, 300, 310, 320, 330});
}

TEST_CASE("A CSV centre off the lattice of the run's CC3DML is refused naming file, line, MCS and cell",
          "[io][run]") {
  io::test::TempDir dir;
  // Cells at x = 1..8 on a lattice 10 wide; cell 5's row of MCS 100 (line 14) says x = 27.5.
  std::string text = csv_frames({0}, 8);
  for (int i = 1; i <= 8; ++i)
    text += "100," + std::to_string(i) + "," + std::to_string(1 + i % 2) + "," +
            (i == 5 ? "27.5" : std::to_string(i)) + ",1,1\n";
  write(dir.file("cells.csv"), text);
  write(dir.file("Simulation/run.xml"), cc3d_xml("x=\"10\" y=\"10\" z=\"10\""));
  CHECK_THAT(
      io::test::input_error([&] { read_run(dir.path().string()); }),
      Contains("cells.csv:14: MCS 100, cell 5: xCOM 27.5 lies outside [0, 10], the lattice along x of ") &&
          Contains("run.xml"));
  // Without the CC3DML nothing says how large the lattice is: read as given.
  fs::remove_all(dir.path() / "Simulation");
  CHECK(read_run(dir.file("cells.csv")).trajectories.frames() == 2);
}

TEST_CASE("A CSV centre off a periodic lattice is refused naming line, MCS, cell, value and CC3DML",
          "[io][run]") {
  io::test::TempDir dir;
  write(dir.file("cells.csv"),
        csv_frames({0}, 8) + "100,1,2,50.5,1,1\n" + csv_rows({100}, 8).substr(csv_rows({100}, 1).size()));
  write(dir.file("Simulation/run.xml"),
        cc3d_xml("x=\"50\" y=\"50\" z=\"50\"", "    <Boundary_x>Periodic</Boundary_x>\n"));
  RunOptions periodic;
  periodic.read_periodic = true;
  CHECK_THAT(
      io::test::input_error([&] { read_run(dir.path().string(), periodic); }),
      Contains("cells.csv:10: MCS 100, cell 1: xCOM 50.5 lies outside [0, 50], the periodic lattice along "
               "x of ") &&
          Contains("run.xml"));
}
