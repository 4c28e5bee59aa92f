// Temporary files of the tests: unique paths in the temporary directory and their removal.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace medusa::test {

// A fresh path in the temporary directory, unique per process and name.
inline std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("medusa-test-" + std::to_string(static_cast<long long>(::getpid())) + "-" + name))
      .string();
}

// Removes the listed files when the test case ends, whatever happens.
struct RemoveFiles {
  std::vector<std::string> paths;
  ~RemoveFiles() {
    for (const std::string& p : paths)
      std::remove(p.c_str());
  }
};

} // namespace medusa::test
