// kinetic_stress: runs testing::dense_lattice_run for a range of seeds, with the audit and the
// stream replay on, and reports every seed whose run fails in a way a correct engine never does
// (an InternalError, an audit failure, a replay mismatch). Colliding or flat inputs end with a
// GeometryError, which is the right answer for them and is only counted. Not a test: a tool for
// hunting degenerate cases (the regression tests take the seeds it finds,
// test_kinetic_dense_lattice.cpp).
//
// Usage: kinetic_stress [first-seed] [count] [seconds] [input]     (defaults 1, 1000, 600, lattice)
// input: lattice (testing::dense_lattice_run), box3 or box2 (testing::hull_box_run in 3D or 2D),
// box3life or box2life (the same with births and deaths), box3mid or box2mid (the same motion with
// frames at the middle of about half of the slabs).
// MEDUSA_STRESS_VERBOSE=1 also prints why each rejected input was rejected.
// Exit code 1 when some seed failed.
#include "kinetic_test_support.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace medusa::kinetic;

int main(int argc, char** argv) {
  const std::uint64_t first = argc > 1 ? std::stoull(argv[1]) : 1;
  const std::uint64_t count = argc > 2 ? std::stoull(argv[2]) : 1000;
  const int seconds = argc > 3 ? std::stoi(argv[3]) : 600;
  const std::string input = argc > 4 ? argv[4] : "lattice";
  const std::vector<std::string> inputs = {"lattice",  "box3",    "box2",   "box3life",
                                           "box2life", "box3mid", "box2mid"};
  if (std::find(inputs.begin(), inputs.end(), input) == inputs.end()) {
    std::fprintf(stderr,
                 "kinetic_stress: unknown input '%s' (lattice, box3, box2, box3life, box2life, box3mid or "
                 "box2mid)\n",
                 input.c_str());
    return 2;
  }
  const bool verbose = std::getenv("MEDUSA_STRESS_VERBOSE") != nullptr;
  const auto start = std::chrono::steady_clock::now();
  int ok = 0, input_errors = 0, failures = 0, skipped = 0;
  for (std::uint64_t seed = first; seed < first + count; ++seed) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(seconds))
      break;
    testing::DenseLatticeRun run;
    const bool made = input == "lattice"
                          ? testing::dense_lattice_run(seed, run)
                          : testing::hull_box_run(seed, input[3] == '3' ? 3 : 2, run,
                                                  input.substr(4) == "life", input.substr(4) == "mid");
    if (!made) {
      ++skipped;
      continue;
    }
    char what[128];
    std::snprintf(what, sizeof what, "seed %llu (%s, %d cells, %d frames, box %d, step %d)",
                  static_cast<unsigned long long>(seed), run.two_d ? "2D" : "3D", run.n, run.frames, run.box,
                  run.step);
    try {
      KineticAlphaComplex engine(run.trajectories, run.options);
      testing::ReplayObserver obs(engine);
      engine.run(obs);
      if (obs.mismatches != 0 || obs.inconsistencies != 0 || obs.not_closed != 0) {
        ++failures;
        std::printf("%s: the replayed stream differs from the engine's complex\n", what);
      } else {
        ++ok;
      }
    } catch (const medusa::GeometryError& e) {
      if (verbose)
        std::printf("%s: rejected: %s\n", what, e.what());
      ++input_errors; // colliding cells or a flat configuration: reported to the user, as it should be
    } catch (const std::exception& e) {
      ++failures;
      std::printf("%s: %s\n", what, e.what());
    }
    std::fflush(stdout);
  }
  std::printf("kinetic_stress: %d runs completed, %d inputs rejected (GeometryError), %d seeds skipped, %d "
              "failed\n",
              ok, input_errors, skipped, failures);
  return failures == 0 ? 0 : 1;
}
