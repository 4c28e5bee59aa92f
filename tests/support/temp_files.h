// Temporary files of the tests: unique paths and folders in the temporary directory, and their removal.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
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

// A fresh folder in the temporary directory, removed with everything in it when the object dies.
class TempDir {
public:
  explicit TempDir(const std::string& tag = "dir") {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("medusa-" + tag + "-" + std::to_string(static_cast<long long>(::getpid())) + "-" +
             std::to_string(counter++));
    // A folder left by an earlier process with the same id would otherwise leak into this test.
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
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

} // namespace medusa::test
