// `medusa run` on the large bundled run (bench/data/large_3d: 4,945 cells, about a minute of work)
// interrupted by SIGINT or SIGTERM at 10 random moments: each time
// exit code 130 (README) and no file at the output name that `medusa info` accepts as a complete store.
#include "child_process.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// Starts `medusa run` on the large run with its output in `dir`; stdout and stderr go to
// files in `dir`.
pid_t start_run(const fs::path& dir) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(dir.c_str()) != 0 || !std::freopen("stdout.txt", "w", stdout) ||
        !std::freopen("stderr.txt", "w", stderr))
      ::_exit(127);
    ::execl(MEDUSA_BINARY, MEDUSA_BINARY, "run", MEDUSA_LONG_RUN, "-o", "interrupted.h5", "--radius", "3",
            "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return child;
}

// Exit status of `medusa info <path>` (0 = a complete, valid store).
int info_status(const fs::path& path) {
  const std::string command = std::string(MEDUSA_BINARY) + " info '" + path.string() + "' >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST_CASE("medusa run interrupted at 10 random moments exits 130 and leaves no complete store", "[faults]") {
  const std::uint64_t seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937_64 random(seed);
  // From just after start-up (the handlers are installed first thing in main) to well inside the
  // run: reading the CSV, the initial triangulation and the first slabs all take longer than 3 s.
  std::uniform_int_distribution<int> delay_ms(300, 3000);
  std::bernoulli_distribution use_sigint(0.5);
  const fs::path dir = fs::temp_directory_path() /
                       ("medusa-faults-interrupt-" + std::to_string(static_cast<long long>(::getpid())));
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int delay = delay_ms(random);
    const int signal = use_sigint(random) ? SIGINT : SIGTERM;
    CAPTURE(attempt, delay, signal);
    fs::remove_all(dir);
    fs::create_directories(dir);
    const pid_t child = start_run(dir);
    REQUIRE(child > 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay));
    REQUIRE(::kill(child, signal) == 0);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    INFO("medusa run stderr: " << std::ifstream(dir / "stderr.txt").rdbuf());
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    const fs::path output = dir / "interrupted.h5";
    if (fs::exists(output))
      CHECK(info_status(output) != 0);
  }
  fs::remove_all(dir);
}
