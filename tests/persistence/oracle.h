// Helpers for tests that call external oracles (/usr/bin/python3 with GUDHI, the phat CLI): a
// private temporary directory, command execution, and diagrams as GUDHI lists them.
#pragma once

#include "medusa/persistence/diagram.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace medusa::persistence::test {

using medusa::test::TempDir; // support/temp_files.h

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
