// `medusa run` on the large bundled run (bench/data/large_3d: 4,945 cells, 3.6 s of work on a quiet
// 2-core machine in November 2026) interrupted by SIGINT or SIGTERM at 10 random moments: each time
// exit code 130 (README) and no file at the output name that `medusa info` accepts as a complete store.
#include "child_process.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
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

// Waits until the child runs medusa (its command line says so) and catches SIGINT and SIGTERM
// (/proc/<pid>/status, SigCgt): a signal sent earlier would find the forked test process, whose
// handlers are Catch's, or medusa before main installed its own. False if the child exits first.
bool wait_for_handlers(pid_t child) {
  const fs::path proc = fs::path("/proc") / std::to_string(child);
  const unsigned long long wanted = (1ULL << (SIGINT - 1)) | (1ULL << (SIGTERM - 1));
  for (int poll = 0; poll < 20000; ++poll) {
    std::ifstream cmdline(proc / "cmdline");
    std::string argv0;
    std::getline(cmdline, argv0, '\0');
    if (argv0 == MEDUSA_BINARY) {
      std::ifstream status(proc / "status");
      for (std::string line; std::getline(status, line);)
        if (line.rfind("SigCgt:", 0) == 0 && (std::stoull(line.substr(7), nullptr, 16) & wanted) == wanted)
          return true;
    }
    int exit_status = 0;
    if (::waitpid(child, &exit_status, WNOHANG) == child)
      return false;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  return false;
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
  // From the moment the handlers are installed (first thing in main) to well inside the run: reading
  // the CSV, the initial triangulation and the first slabs take longer than 2 s, and a slower machine
  // only moves the end further.
  std::uniform_int_distribution<int> delay_ms(0, 2000);
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
    REQUIRE(wait_for_handlers(child));
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
