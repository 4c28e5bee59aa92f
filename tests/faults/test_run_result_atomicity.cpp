// `medusa run` with a previous result at its output names (README, docs/FORMAT.md "One result per
// run"): interrupted (SIGINT/SIGTERM) at each stage of a run on the large bundled run, it exits 130
// and leaves the previous store, diagrams CSV and barcode SVG byte for byte as they were, with no
// temporary or lock file; killed (SIGKILL) at each stage, it leaves the old set whole (the next run
// then goes through); a second run onto the same store while one is running is refused (exit 5) and
// the first one's result is whole. Stages are recognised by the lines of --progress.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Starts medusa with `args` in `dir`, stdout and stderr to `<tag>.stdout` / `<tag>.stderr` there.
pid_t start_medusa(const fs::path& dir, const std::vector<std::string>& args, const std::string& tag) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir(dir.c_str()) != 0 || !std::freopen((tag + ".stdout").c_str(), "w", stdout) ||
        !std::freopen((tag + ".stderr").c_str(), "w", stderr))
      ::_exit(127);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(MEDUSA_BINARY));
    for (const std::string& a : args)
      argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(MEDUSA_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

int wait_exit(pid_t child, bool& signalled) {
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  signalled = WIFSIGNALED(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status);
}

// Polls the progress lines until one starts with "medusa: <stage>"; false if the child exits first.
bool wait_for_stage(pid_t child, const fs::path& stderr_file, const std::string& stage) {
  const std::string marker = "medusa: " + stage;
  for (int poll = 0; poll < 120000; ++poll) {
    std::istringstream lines(read_file(stderr_file));
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(marker, 0) == 0)
        return true;
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child)
      return false;
    std::this_thread::sleep_for(std::chrono::microseconds(250));
  }
  return false;
}

// The files of `dir` other than the children's stdout and stderr, with their contents.
std::map<std::string, std::string> outputs_in(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 7 &&
        (name.substr(name.size() - 7) == ".stdout" || name.substr(name.size() - 7) == ".stderr"))
      continue;
    files[name] = read_file(entry.path());
  }
  return files;
}

std::vector<std::string> names_of(const std::map<std::string, std::string>& files) {
  std::vector<std::string> names;
  for (const auto& [name, content] : files)
    names.push_back(name);
  return names;
}

// A fresh folder holding the result of a small run written as prev.h5, prev.diagrams.csv and
// prev.barcode.svg, prev.diagram.svg (the first 3 frames of examples/sorting_3d at radius 2.5).
fs::path folder_with_previous_result(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() /
                       ("medusa-atomic-" + tag + "-" + std::to_string(static_cast<long long>(::getpid())));
  fs::remove_all(dir);
  fs::create_directories(dir);
  bool signalled = false;
  const pid_t previous =
      start_medusa(dir, {"run", MEDUSA_SMALL_RUN, "-o", "prev.h5", "--radius", "2.5", "-q"}, "previous");
  REQUIRE(wait_exit(previous, signalled) == 0);
  fs::remove(dir / "previous.stdout");
  fs::remove(dir / "previous.stderr");
  return dir;
}

const std::vector<std::string> large_run = {
    "run", MEDUSA_LONG_RUN, "-o", "prev.h5", "--force", "--radius", "3", "--progress", "--threads", "1"};

// The run id a side output names (first line of the CSV), or "".
std::string csv_run_id(const std::string& csv) {
  std::smatch m;
  return std::regex_search(csv, m, std::regex("^# medusa run ([0-9a-f]{32})\n")) ? m[1].str() : "";
}

int info_status(const fs::path& dir, const std::string& store) {
  const std::string command =
      "cd '" + dir.string() + "' && " + std::string(MEDUSA_BINARY) + " info '" + store + "' >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The stages of --progress, in order, as they start their lines.
const std::vector<std::string> stages = {"reading", "kinetic", "medusa store", "filtrations", "exports"};

} // namespace

TEST_CASE("medusa run interrupted at each stage exits 130 and leaves the previous result exactly as it was",
          "[faults]") {
  const fs::path dir = folder_with_previous_result("interrupt");
  const std::map<std::string, std::string> before = outputs_in(dir);
  REQUIRE(names_of(before) ==
          std::vector<std::string>{"prev.barcode.svg", "prev.diagram.svg", "prev.diagrams.csv", "prev.h5"});
  int reached = 0;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const int signal = k % 2 == 0 ? SIGINT : SIGTERM;
    CAPTURE(stages[k], signal);
    // One log per attempt: an earlier attempt's progress lines must not be taken for this one's.
    const std::string tag = "interrupted_" + std::to_string(k);
    const pid_t child = start_medusa(dir, large_run, tag);
    const bool in_stage = wait_for_stage(child, dir / (tag + ".stderr"), stages[k]);
    if (in_stage)
      REQUIRE(::kill(child, signal) == 0);
    bool signalled = false;
    const int code = wait_exit(child, signalled);
    INFO("medusa run stderr: " << read_file(dir / (tag + ".stderr")));
    REQUIRE(in_stage);
    REQUIRE_FALSE(signalled);
    CHECK(code == 130);
    const std::map<std::string, std::string> after = outputs_in(dir);
    CHECK(names_of(after) == names_of(before)); // no temporary file, no lock file
    CHECK((after == before));
    reached += after == before && code == 130 ? 1 : 0;
  }
  CHECK(reached == static_cast<int>(stages.size()));
  fs::remove_all(dir);
}

TEST_CASE("medusa run killed at each stage leaves the previous result whole and the next run goes through",
          "[faults]") {
  const fs::path dir = folder_with_previous_result("kill");
  const std::map<std::string, std::string> before = outputs_in(dir);
  const std::string old_id = csv_run_id(before.at("prev.diagrams.csv"));
  REQUIRE(old_id.size() == 32);
  for (const std::string& stage : stages) {
    CAPTURE(stage);
    const std::string tag = "killed_" + stage.substr(0, stage.find(' '));
    const pid_t child = start_medusa(dir, large_run, tag);
    const bool in_stage = wait_for_stage(child, dir / (tag + ".stderr"), stage);
    if (in_stage)
      REQUIRE(::kill(child, SIGKILL) == 0);
    bool signalled = false;
    wait_exit(child, signalled);
    REQUIRE(in_stage);
    REQUIRE(signalled);
    // The previous set at the final names, unchanged (a kill may leave temporaries and the lock file).
    const std::map<std::string, std::string> after = outputs_in(dir);
    for (const auto& [name, content] : before) {
      REQUIRE(after.count(name) == 1);
      CHECK(after.at(name) == content);
    }
    CHECK(info_status(dir, "prev.h5") == 0);
  }
  // A killed run's lock file is no obstacle: the next run completes and its three outputs agree.
  bool signalled = false;
  const pid_t next =
      start_medusa(dir, {"run", MEDUSA_SMALL_RUN, "-o", "prev.h5", "--force", "--radius", "3", "-q"}, "next");
  REQUIRE(wait_exit(next, signalled) == 0);
  const std::map<std::string, std::string> after = outputs_in(dir);
  const std::string new_id = csv_run_id(after.at("prev.diagrams.csv"));
  CHECK(new_id.size() == 32);
  CHECK(new_id != old_id);
  CHECK(after.at("prev.barcode.svg").find("data-medusa-run=\"" + new_id + "\"") != std::string::npos);
  CHECK(info_status(dir, "prev.h5") == 0);
  fs::remove_all(dir);
}

TEST_CASE("A second medusa run onto a store being written is refused and the first run's result is whole",
          "[faults]") {
  const fs::path dir = folder_with_previous_result("concurrent");
  const pid_t first = start_medusa(dir, large_run, "first");
  REQUIRE(wait_for_stage(first, dir / "first.stderr", "kinetic"));
  const pid_t second = start_medusa(
      dir, {"run", MEDUSA_SMALL_RUN, "-o", "prev.h5", "--force", "--radius", "2", "-q"}, "second");
  bool signalled = false;
  const int second_code = wait_exit(second, signalled);
  const int first_code = wait_exit(first, signalled);
  const std::string second_err = read_file(dir / "second.stderr");
  INFO("second run stderr: " << second_err);
  CHECK(second_code == 5);
  CHECK(second_err.find("another medusa run is writing it") != std::string::npos);
  CHECK(first_code == 0);
  const std::map<std::string, std::string> after = outputs_in(dir);
  CHECK(names_of(after) ==
        std::vector<std::string>{"prev.barcode.svg", "prev.diagram.svg", "prev.diagrams.csv", "prev.h5"});
  const std::string id = csv_run_id(after.at("prev.diagrams.csv"));
  CHECK(id.size() == 32);
  CHECK(after.at("prev.barcode.svg").find("data-medusa-run=\"" + id + "\"") != std::string::npos);
  CHECK(after.at("prev.diagram.svg").find("data-medusa-run=\"" + id + "\"") != std::string::npos);
  CHECK(info_status(dir, "prev.h5") == 0);
  // The store is the first run's (radius 3), not the refused one's (radius 2).
  const std::string command = "cd '" + dir.string() + "' && " + MEDUSA_BINARY + " info prev.h5 > info.stdout";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK(read_file(dir / "info.stdout").find("\nradius: 3\n") != std::string::npos);
  CHECK(read_file(dir / "info.stdout").find("run id: " + id) != std::string::npos);
  fs::remove_all(dir);
}
