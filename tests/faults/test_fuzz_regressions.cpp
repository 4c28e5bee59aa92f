// Every input in tests/data/fuzz/<target>/ (hand-made malformed inputs, and each input a fuzzer of
// fuzz/ ever crashed on) given to the normal reader: it must throw a medusa::Error, in a child process
// with a 10 s alarm so that a crash or a hang fails the case instead of the executable.
#include "child_process.h"
#include "medusa/complex/store_reader.h"
#include "medusa/io/csv_reader.h"
#include "medusa/io/vtk_reader.h"
#include "medusa/kinetic/error.h"

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

// Runs `read` on every input of `target` and checks that each one throws a medusa::Error.
void check_all_rejected(const std::string& target, const std::function<void(const std::string&)>& read) {
  const std::vector<std::string> files = inputs_of(target);
  REQUIRE_FALSE(files.empty());
  for (const std::string& file : files) {
    CAPTURE(file);
    const ChildResult r = run_in_child([&](std::string& report) {
      try {
        read(file);
        report = "read without error";
        return child_returned;
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

TEST_CASE("the CSV reader rejects every fuzz regression input with a medusa::Error", "[faults]") {
  check_all_rejected("fuzz_csv_reader", [](const std::string& f) { medusa::io::read_csv(f); });
}

TEST_CASE("the VTK reader rejects every fuzz regression input with a medusa::Error", "[faults]") {
  check_all_rejected("fuzz_vtk_reader", [](const std::string& f) { medusa::io::read_vtk_snapshot(f, 1000); });
}

TEST_CASE("the store reader rejects every fuzz regression input with a medusa::Error", "[faults]") {
  check_all_rejected("fuzz_store_reader", [](const std::string& f) { medusa::complex::read_store(f); });
}
