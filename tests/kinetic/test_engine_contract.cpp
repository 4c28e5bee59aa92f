// The kinetic engine's event stream is a contract (docs/ARCHITECTURE.md, "The event stream is a
// contract"): on every bundled run, on seeded random walks with cells born and dying at frames in 3D
// and in the plane, and on degenerate lattice and hull-box walks, the stream's counts and its digest
// (event_stream_digest.h) must equal the ones recorded in tests/data/kinetic/engine_contract.txt. Any change
// of the engine that moves, adds, drops or reorders a single event, or changes one simplex of one step, fails
// here.
//
// MEDUSA_UPDATE_ENGINE_CONTRACT=1 rewrites the recorded file instead (scripts/update-engine-contract);
// a new recording is right only with a proof that the old stream was wrong.
#include "event_stream_digest.h"
#include "kinetic_test_support.h"
#include "medusa/io/run_reader.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "support/spaced_random_walk.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace medusa::kinetic;
using medusa::kinetic::testing::StreamDigest;

namespace {

const std::string recorded_file = MEDUSA_TEST_DATA "/kinetic/engine_contract.txt";
const std::string repo = MEDUSA_TEST_DATA "/../..";

struct Input {
  Trajectories trajectories;
  SquaredRadius rho2;
};

struct Case {
  std::string name;
  std::string
      radius; // as recorded: "radius=R" (decimal text, as `medusa run --radius` takes it) or "rho2=P/Q"
  std::function<Input()> input;
};

Case decimal_radius_case(std::string name, std::function<Trajectories()> trajectories, std::string radius) {
  return {std::move(name), "radius=" + radius, [trajectories, radius] {
            Input in{trajectories(), {}};
            in.rho2 = squared_radius_from_decimal(radius, in.trajectories.scale);
            return in;
          }};
}

// The degenerate walks of kinetic_test_support.h on a coarse lattice (cospherical and coplanar cells,
// many failures at one time, static repairs, degenerate groups), with births and deaths: seeds the
// stress tool found (tests/kinetic/test_kinetic_dense_lattice.cpp), audit off.
Case degenerate_case(const std::string& kind, std::uint64_t seed, int box_dim) {
  testing::DenseLatticeRun run;
  REQUIRE((box_dim == 0 ? testing::dense_lattice_run(seed, run)
                        : testing::hull_box_run(seed, box_dim, run, true)));
  const std::string radius = "rho2=" + run.options.rho2.num.get_str() + "/" + run.options.rho2.den.get_str();
  return {kind + "_seed" + std::to_string(seed), radius, [run] {
            return Input{run.trajectories, run.options.rho2};
          }};
}

// A bundled run read as `medusa run --source csv|vtk` reads it (VTK centroids snapped to the grid; a
// periodic run as an open one).
medusa::io::RunData read_bundled(const std::string& folder, medusa::io::RunSource source) {
  medusa::io::RunOptions options;
  options.source = source;
  options.allow_periodic_as_open = true;
  return medusa::io::read_run(repo + "/" + folder, options);
}

medusa::io::RunData read_csv_run(const std::string& folder) {
  return read_bundled(folder, medusa::io::RunSource::csv);
}

// `medusa run`'s default radius (--radius auto, pipeline/cli/run_input.cpp): the radius of the ball
// (disc) of the median cell volume, printed with six decimals.
std::string auto_radius(const medusa::io::RunData& data) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6f",
                medusa::io::equivalent_radius(medusa::io::median_cell_volume(data.volumes),
                                              data.trajectories.dimension));
  return buffer;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* folder :
       {"examples/sorting_3d", "tests/data/cc3d/sorting_3d_seed2", "tests/data/cc3d/nosorting_3d",
        "tests/data/cc3d/mitosis_3d", "tests/data/cc3d/sorting_2d", "tests/data/cc3d/periodic_3d",
        "bench/data/large_3d"}) {
    const std::string f = folder;
    const std::string radius = auto_radius(read_csv_run(f));
    out.push_back(decimal_radius_case(
        f.substr(f.rfind('/') + 1) + "_csv_auto", [f] { return read_csv_run(f).trajectories; }, radius));
  }
  // The VTK route (snapped voxel centroids) where it gives another stream than the CSV: the runs with
  // three snapshots (on sorting_3d, mitosis_3d and sorting_2d its stream is the CSV's, digest for digest).
  for (const char* folder :
       {"tests/data/cc3d/sorting_3d_seed2", "tests/data/cc3d/nosorting_3d", "tests/data/cc3d/periodic_3d"}) {
    const std::string f = folder;
    const auto read = [f] { return read_bundled(f, medusa::io::RunSource::vtk); };
    out.push_back(decimal_radius_case(
        f.substr(f.rfind('/') + 1) + "_vtk_auto", [read] { return read().trajectories; },
        auto_radius(read())));
  }
  // A fixed radius too on one run: a second membership pattern on the same Delaunay events.
  out.push_back(decimal_radius_case(
      "sorting_3d_csv_r3", [] { return read_csv_run("examples/sorting_3d").trajectories; }, "3"));
  struct Walk {
    int dimension, n, frames;
    std::uint64_t seed;
  };
  for (const Walk& w : {Walk{3, 400, 6, 20261}, Walk{2, 800, 6, 20262}}) {
    const std::string name = "random_walk_" + std::to_string(w.dimension) + "d_n" + std::to_string(w.n) +
                             "_seed" + std::to_string(w.seed) + "_turnover0.2";
    out.push_back(decimal_radius_case(
        name,
        [w] {
          Trajectories t = medusa::test::spaced_random_walk(w.seed, w.dimension, w.n, w.frames);
          medusa::test::add_turnover(t, 0.2, w.seed + 1);
          return t;
        },
        "3"));
  }
  for (std::uint64_t seed : {1019, 1126, 5142, 6265, 20232, 31284})
    out.push_back(degenerate_case("dense_lattice", seed, 0));
  for (std::uint64_t seed : {146, 910, 11018, 18304})
    out.push_back(degenerate_case("hull_box_3d", seed, 3));
  for (std::uint64_t seed : {434, 2026})
    out.push_back(degenerate_case("hull_box_2d", seed, 2));
  return out;
}

// name -> "counts digest=..." of the recorded file; '#' lines are comments.
std::map<std::string, std::string> read_recorded() {
  std::ifstream in(recorded_file);
  std::map<std::string, std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    const std::size_t space = line.find(' ');
    out[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return out;
}

std::map<std::string, std::string> fields(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream words(text);
  std::string w;
  while (words >> w) {
    const std::size_t eq = w.find('=');
    out[w.substr(0, eq)] = eq == std::string::npos ? "" : w.substr(eq + 1);
  }
  return out;
}

// The first difference of a case: its counts in order, then its digest; empty if none.
std::string first_difference(const std::string& recorded, const std::string& now) {
  std::istringstream words(now);
  std::string w;
  const auto old = fields(recorded);
  while (words >> w) {
    const std::size_t eq = w.find('=');
    const std::string key = w.substr(0, eq), value = w.substr(eq + 1);
    const auto it = old.find(key);
    if (it == old.end())
      return key + " not recorded (now " + value + ")";
    if (it->second != value)
      return key + " " + it->second + " recorded, " + value + " now";
  }
  return recorded == now ? "" : "recorded line '" + recorded + "' differs from '" + now + "'";
}

} // namespace

TEST_CASE(
    "the kinetic engine's event stream on every bundled run and seeded random walk equals the recorded one",
    "[kinetic][contract]") {
  const bool update = std::getenv("MEDUSA_UPDATE_ENGINE_CONTRACT") != nullptr;
  const std::map<std::string, std::string> recorded = read_recorded();
  if (!update && recorded.empty()) // a missing or empty file would check nothing
    FAIL("engine contract: no case recorded in " + recorded_file +
         " (scripts/update-engine-contract writes it)");
  std::vector<std::string> lines, differences;
  std::size_t ran = 0;
  for (const Case& c : cases()) {
    const Input in = c.input();
    const Trajectories& t = in.trajectories;
    KineticOptions options;
    options.rho2 = in.rho2;
    KineticAlphaComplex engine(t, options);
    StreamDigest digest;
    engine.run(digest);
    ++ran;
    const std::string now = c.radius + " cells=" + std::to_string(t.cells.size()) + " " + digest.counts() +
                            " digest=" + digest.digest();
    std::printf("%s %s\n", c.name.c_str(), now.c_str());
    std::fflush(stdout);
    lines.push_back(c.name + " " + now);
    const auto it = recorded.find(c.name);
    if (it == recorded.end())
      differences.push_back("engine contract: case " + c.name + " is not recorded in " + recorded_file);
    else if (const std::string d = first_difference(it->second, now); !d.empty())
      differences.push_back("engine contract: case " + c.name + " differs: " + d);
  }
  REQUIRE(ran > 0);
  if (update) {
    std::ofstream out(recorded_file);
    out << "# The kinetic engine's event stream on each case of tests/kinetic/test_engine_contract.cpp: the "
           "radius\n"
           "# (or rho^2 in grid units), counts of the stream and its FNV-1a digest (event_stream_digest.h).\n"
           "# Written by scripts/update-engine-contract; regenerate only with a proof that the old stream\n"
           "# was wrong.\n";
    for (const std::string& line : lines)
      out << line << '\n';
    REQUIRE(out.good());
    return;
  }
  for (const auto& [name, line] : recorded) {
    bool known = false;
    for (const std::string& l : lines)
      known = known || l.compare(0, name.size() + 1, name + " ") == 0;
    if (!known)
      differences.push_back("engine contract: recorded case " + name + " is no longer run");
  }
  if (!differences.empty())
    FAIL(differences.front() +
         (differences.size() > 1 ? " (and " + std::to_string(differences.size() - 1) + " more case(s) differ)"
                                 : std::string()));
}
