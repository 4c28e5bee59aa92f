// Helpers for tests that call external oracles (/usr/bin/python3 with GUDHI, the phat CLI): a
// private temporary directory, command execution, and diagrams as GUDHI lists them.
#pragma once

#include "medusa/persistence/diagram.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace medusa::persistence::test {

// A fresh directory removed at scope exit.
class TempDir {
public:
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("medusa-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

// Runs a shell command; the test fails (with the command shown) if it exits non-zero.
inline void run(const std::string& command) {
  INFO("command: " << command);
  REQUIRE(std::system(command.c_str()) == 0);
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string python() { return MEDUSA_PYTHON; }
inline std::string data_path(const std::string& relative) {
  return std::string(MEDUSA_TEST_DATA) + "/" + relative;
}

// (dim, birth, death), the form GUDHI's persistence lists take.
using Triple = std::tuple<int, double, double>;

// The pairs of positive length (GUDHI leaves out zero-length pairs), sorted.
inline std::vector<Triple> positive_points(const Diagram& d) {
  std::vector<Triple> result;
  for (const auto& p : d.pairs)
    if (!p.zero_length)
      result.emplace_back(p.dim, p.birth, p.death);
  std::sort(result.begin(), result.end());
  return result;
}

} // namespace medusa::persistence::test
