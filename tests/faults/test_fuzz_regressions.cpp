// Every input in tests/data/fuzz/<target>/ given to the normal reader, in a child process with a 10 s
// alarm so that a crash or a hang fails the case instead of the executable. The hand-made malformed
// inputs must throw a medusa::Error. The inputs a fuzzer of fuzz/ reported (libFuzzer names them
// crash-, timeout-, oom-, leak-<sha1>) must end in a medusa::Error or a normal return: some are valid
// files on which a sanitizer caught undefined behaviour (scripts/fuzz replays them all under ASan and
// UBSan as seeds), but none may crash, hang or throw anything else.
#include "child_process.h"
#include "medusa/core/error.h"
#include "medusa/io/csv_reader.h"
#include "medusa/io/vtk_reader.h"
#include "medusa/medusa/store_reader.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <vector>

using namespace medusa::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> inputs_of(const std::string& target) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(MEDUSA_TEST_DATA) / "fuzz" / target))
    if (entry.is_regular_file() && entry.path().filename() != "README.txt")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool fuzzer_artifact(const std::string& file) {
  const std::string name = fs::path(file).filename().string();
  for (const char* prefix : {"crash-", "timeout-", "oom-", "leak-", "slow-unit-"})
    if (name.rfind(prefix, 0) == 0)
      return true;
  return false;
}

// Runs `read` on every input of `target`: a medusa::Error for every hand-made input, a medusa::Error
// or a normal return for the fuzzers' findings, never a crash, a hang or another exception.
void check_all_rejected(const std::string& target, const std::function<void(const std::string&)>& read) {
  const std::vector<std::string> files = inputs_of(target);
  REQUIRE_FALSE(files.empty());
  for (const std::string& file : files) {
    CAPTURE(file);
    const ChildResult r = run_in_child([&](std::string& report) {
      try {
        read(file);
        report = "read without error";
        return fuzzer_artifact(file) ? child_threw_expected : child_returned;
      } catch (const medusa::Error& e) {
        report = e.what();
        return child_threw_expected;
      }
    });
    INFO(r.describe());
    CHECK(r.end == ChildResult::End::exited);
    CHECK(r.code == child_threw_expected);
  }
}

} // namespace

TEST_CASE("the CSV reader survives every fuzz regression input and rejects the malformed ones", "[faults]") {
  check_all_rejected("fuzz_csv_reader", [](const std::string& f) { medusa::io::read_csv(f); });
}

TEST_CASE("the VTK reader survives every fuzz regression input and rejects the malformed ones", "[faults]") {
  check_all_rejected("fuzz_vtk_reader", [](const std::string& f) { medusa::io::read_vtk_snapshot(f, 1000); });
}

TEST_CASE("the store reader survives every fuzz regression input and rejects the malformed ones",
          "[faults]") {
  check_all_rejected("fuzz_store_reader", [](const std::string& f) { medusa::read_store(f); });
}
