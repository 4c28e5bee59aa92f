// The real CompuCell3D runs of tests/data/cc3d: counts from each run's README.txt, and the VTK
// centroids against CC3D's own CSV centres (tests/data/cc3d/README.txt: they agree to 6 decimals).
#include "io_test_support.h"
#include "medusa/io/centroid.h"
#include "medusa/io/csv_reader.h"
#include "medusa/io/gzip_reader.h"
#include "medusa/io/run_reader.h"
#include "medusa/io/vtk_reader.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <random>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

// Along a periodic axis of length L, CC3D's centre is the minimum-image mean: the plain mean after
// some m of the cell's n voxels are moved by one period, (X + m L) / n, taken modulo L (README of
// periodic_3d). So the CSV value x, the exact mean rounded to the grid, satisfies
// |n x - (X + m L)| <= n / 2 modulo n L for some m in [0, n]. Returns that m (0 for a cell that does not
// straddle the seam), or nothing when no wrap of the voxels gives x. Candidates lie L apart and the
// tolerance is n / 2 grid units, so a wrong x passes only by a coincidence of order n / L (~1e-6).
std::optional<std::int64_t> periodic_shift(const VtkSnapshot& v, const VtkCell& c, int axis, std::int64_t x) {
  const auto a = static_cast<std::size_t>(axis);
  const std::int64_t period = v.dimensions[a] * v.spacing[a], n = c.voxels;
  const std::int64_t mod = n * period;
  const std::int64_t r = (((n * x - c.scaled_sum[a]) % mod) + mod) % mod; // in [0, n L)
  const std::int64_t m = (r + period / 2) / period;                       // nearest multiple of L
  if (std::abs(r - m * period) * 2 > n)
    return std::nullopt;
  return m;
}

// From each run's README.txt ("Cells:" and "Saved MCS:").
struct RunFacts {
  std::string name;
  std::size_t cells_first, cells_last, type1_first, type2_first, frames;
  std::int64_t mcs_first, mcs_last;
  int dimension;
  bool periodic;
};

const std::vector<RunFacts>& runs() {
  static const std::vector<RunFacts> r = {
      {"sorting_3d_seed2", 251, 251, 132, 119, 21, 0, 2000, 3, false},
      {"nosorting_3d", 251, 251, 126, 125, 21, 0, 2000, 3, false},
      {"periodic_3d", 300, 300, 157, 143, 21, 0, 2000, 3, true},
      {"sorting_2d", 193, 193, 99, 94, 20, 0, 9500, 2, false},
      {"mitosis_3d", 93, 165, 50, 43, 21, 0, 1000, 3, false},
  };
  return r;
}

std::string run_path(const std::string& name) { return io::test::data("cc3d/" + name); }

std::size_t present_at(const kinetic::Trajectories& t, std::size_t frame, int type = 0) {
  return static_cast<std::size_t>(
      std::count_if(t.cells.begin(), t.cells.end(), [&](const kinetic::Trajectory& c) {
        return c.present(frame) && (type == 0 || c.type == type);
      }));
}

std::vector<std::string> snapshots(const std::string& run) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(run_path(run) + "/LatticeData"))
    if (is_vtk_step_name(e.path().filename().string()))
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

void require_same(const RunData& a, const RunData& b) {
  const kinetic::Trajectories &s = a.trajectories, &t = b.trajectories;
  REQUIRE(s.frame_times == t.frame_times);
  REQUIRE(s.cells.size() == t.cells.size());
  for (std::size_t i = 0; i < s.cells.size(); ++i) {
    CAPTURE(i);
    CHECK(s.cells[i].cell_id == t.cells[i].cell_id);
    CHECK(s.cells[i].type == t.cells[i].type);
    CHECK(s.cells[i].first_frame == t.cells[i].first_frame);
    CHECK(s.cells[i].positions == t.cells[i].positions);
  }
  CHECK(a.volumes == b.volumes);
  CHECK(s.type_names == t.type_names);
  CHECK(s.dimension == t.dimension);
}

} // namespace

TEST_CASE("Every real run's CSV gives the cell and frame counts of its README", "[io][real]") {
  std::size_t checked = 0;
  for (const RunFacts& f : runs()) {
    CAPTURE(f.name);
    RunOptions o;
    o.source = RunSource::csv;
    o.allow_periodic_as_open = f.periodic;
    const RunData r = read_run(run_path(f.name), o);
    const kinetic::Trajectories& t = r.trajectories;
    CHECK(r.used == RunSource::csv);
    CHECK(r.sources == std::vector<std::string>{run_path(f.name) + "/cells.csv.gz"});
    REQUIRE(t.frames() == f.frames);
    CHECK(t.frame_times.front() == f.mcs_first);
    CHECK(t.frame_times.back() == f.mcs_last);
    CHECK(t.dimension == f.dimension);
    CHECK(present_at(t, 0) == f.cells_first);
    CHECK(present_at(t, t.frames() - 1) == f.cells_last);
    CHECK(present_at(t, 0, 1) == f.type1_first);
    CHECK(present_at(t, 0, 2) == f.type2_first);
    CHECK(t.type_names == std::vector<std::string>{"Medium", "Condensing", "NonCondensing"});
    if (f.name != "mitosis_3d") {
      CHECK(t.cells.size() == f.cells_first); // every cell lives through the whole run
      for (const auto& c : t.cells)
        CHECK(c.positions.size() == f.frames);
    }
    ++checked;
  }
  CHECK(checked == 5);
}

TEST_CASE("The mitosis run's cells appear and disappear with the README's count per frame", "[io][real]") {
  const std::vector<std::size_t> expected = {93,  90,  84,  81,  79,  78,  76,  80,  93,  104, 114,
                                             119, 119, 122, 129, 132, 136, 153, 160, 168, 165};
  RunOptions csv;
  csv.source = RunSource::csv;
  RunOptions vtk;
  vtk.source = RunSource::vtk;
  vtk.snap = true;
  for (const RunOptions& o : {csv, vtk}) {
    const RunData r = read_run(run_path("mitosis_3d"), o);
    CAPTURE(r.position_convention);
    const kinetic::Trajectories& t = r.trajectories;
    REQUIRE(t.frames() == expected.size());
    for (std::size_t k = 0; k < t.frames(); ++k) {
      CAPTURE(k);
      CHECK(t.frame_times[k] == std::int64_t(50 * k));
      CHECK(present_at(t, k) == expected[k]);
    }
    std::int64_t max_id = 0;
    for (const auto& c : t.cells)
      max_id = std::max(max_id, c.cell_id);
    CHECK(max_id == 223); // README: max id 223
    // No cell vanishes and comes back in this run: one trajectory per id.
    std::vector<std::int64_t> ids;
    for (const auto& c : t.cells)
      ids.push_back(c.cell_id);
    CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    CHECK(std::count_if(t.cells.begin(), t.cells.end(), [](const auto& c) { return c.first_frame > 0; }) > 0);
  }
}

TEST_CASE("VTK voxel centroids equal CC3D's CSV centres to 6 decimals on every real snapshot", "[io][real]") {
  std::size_t files = 0, cells = 0, straddling = 0;
  for (const RunFacts& f : runs()) {
    CAPTURE(f.name);
    std::map<std::pair<std::int64_t, std::int64_t>, CellSample> csv;
    for (const CellSample& s : read_csv(run_path(f.name) + "/cells.csv.gz").samples)
      csv[{s.mcs, s.cell_id}] = s;
    for (const std::string& file : snapshots(f.name)) {
      CAPTURE(file);
      const std::int64_t mcs = vtk_step_mcs(file);
      const VtkSnapshot v = read_vtk_snapshot(file, 1000000);
      const auto in_frame =
          std::count_if(csv.begin(), csv.end(), [&](const auto& e) { return e.first.first == mcs; });
      CHECK(static_cast<std::size_t>(in_frame) == v.cells.size());
      for (const VtkCell& c : v.cells) {
        CAPTURE(c.id);
        const auto it = csv.find({mcs, c.id});
        REQUIRE(it != csv.end());
        CHECK(it->second.type == c.type);
        CHECK(it->second.volume == c.voxels);
        // CC3D prints xCM/volume with %.6f: the exact mean rounded to the grid (ties to even).
        SnapReport report;
        const kinetic::GridPoint rounded = snap_centroid(c.scaled_sum, c.voxels, report);
        if (f.periodic) { // x and y wrap (minimum image, README); z is NoFlux, a plain mean
          CHECK(rounded[2] == it->second.position[2]);
          for (int axis = 0; axis < 2; ++axis) {
            CAPTURE(axis);
            const std::optional<std::int64_t> m = periodic_shift(v, c, axis, it->second.position[axis]);
            REQUIRE(m.has_value());
            if (*m % c.voxels != 0)
              ++straddling;
          }
        } else {
          CHECK(rounded == it->second.position);
        }
        ++cells;
      }
      ++files;
    }
  }
  CHECK(files == 47); // 21 + 20 + 3 x 2 snapshots in tests/data/cc3d
  CHECK(cells > 0);
  // The periodic run's cells drift across the seams by MCS 100, so the wrap is exercised.
  CHECK(straddling > 0);
}

TEST_CASE("The real periodic run is refused by default and read as open when allowed", "[io][real]") {
  for (const RunSource source : {RunSource::csv, RunSource::vtk}) {
    RunOptions o;
    o.source = source;
    o.snap = true;
    CHECK_THAT(io::test::input_error([&] { read_run(run_path("periodic_3d"), o); }),
               Contains("periodic_3d.xml") && Contains("periodic along x,y"));
    o.allow_periodic_as_open = true;
    const RunData r = read_run(run_path("periodic_3d"), o);
    CHECK(r.trajectories.cells.size() == 300);
    CHECK(r.trajectories.frames() == (source == RunSource::csv ? 21u : 2u));
    CHECK(std::any_of(r.warnings.begin(), r.warnings.end(), [](const std::string& w) {
      return w.find("periodic boundaries along x,y") != std::string::npos;
    }));
  }
}

TEST_CASE("The real 2D run is planar from its snapshots too", "[io][real]") {
  RunOptions o;
  o.snap = true;
  const RunData r = read_run(run_path("sorting_2d"), o);
  CHECK(r.used == RunSource::vtk);
  CHECK(r.trajectories.dimension == 2);
  CHECK(r.trajectories.frames() == 20);
  CHECK(r.trajectories.cells.size() == 193);
  CHECK(r.sources.size() == 20);
  for (const auto& c : r.trajectories.cells)
    for (const auto& p : c.positions)
      REQUIRE(p[2] == 0);
}

TEST_CASE("A real VTK folder reads with snapping and reports the moves", "[io][real]") {
  RunOptions o;
  o.snap = false;
  CHECK_THAT(io::test::input_error([&] { read_run(run_path("sorting_3d_seed2"), o); }),
             Contains("--exact-vtk"));
  o.snap = true;
  const RunData r = read_run(run_path("sorting_3d_seed2"), o);
  CHECK(r.used == RunSource::vtk);
  CHECK(r.trajectories.frame_times == std::vector<std::int64_t>{0, 100});
  CHECK(r.trajectories.cells.size() == 251);
  CHECK(r.snap.moved > 0);
  CHECK(2 * r.snap.max_displacement_num <= r.snap.max_displacement_den);
  // MCS 0 cells are 5x5x5 cubes: 125 voxels, centres exactly on the grid (corner + 2).
  REQUIRE(r.volumes.size() == 251);
  for (const auto& v : r.volumes)
    CHECK(v[0] == 125);
}

TEST_CASE("Row order of a real CSV does not change the trajectories", "[io][real]") {
  const std::string source = run_path("mitosis_3d") + "/cells.csv.gz";
  RunOptions o;
  const RunData original = read_csv_run(source, o); // no CC3DML for either side of the comparison

  // The raw rows of the real file, re-ordered below.
  std::vector<std::string> lines;
  std::string header, line;
  GzipReader in(source);
  REQUIRE(in.next_line(header));
  while (in.next_line(line))
    lines.push_back(line);

  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  io::test::TempDir dir;
  for (int variant = 0; variant < 2; ++variant) {
    CAPTURE(variant);
    std::vector<std::string> rows = lines;
    if (variant == 0) {
      std::shuffle(rows.begin(), rows.end(), rng);
    } else { // sorted by cell id, then MCS
      const auto key = [](const std::string& l) {
        const std::size_t c1 = l.find(','), c2 = l.find(',', c1 + 1);
        return std::make_pair(std::stoll(l.substr(c1 + 1, c2 - c1 - 1)), std::stoll(l.substr(0, c1)));
      };
      std::stable_sort(rows.begin(), rows.end(),
                       [&](const auto& a, const auto& b) { return key(a) < key(b); });
    }
    const std::string path = dir.file("cells_" + std::to_string(variant) + ".csv");
    {
      std::ofstream out(path);
      out << header << "\n";
      for (const auto& r : rows)
        out << r << "\n";
    }
    require_same(original, read_csv_run(path, o));
  }
}
