// Shared helpers of the medusa::io tests.
#pragma once

#include "medusa/kinetic/error.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>

namespace medusa::io::test {

inline std::string data(const std::string& relative) {
  return std::string(MEDUSA_TEST_DATA) + "/" + relative;
}

// The message of the InputError thrown by f; fails the test if f throws nothing or something else.
template <class F> std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message.find('\n') == std::string::npos); // one-line messages (docs/CONVENTIONS.md)
    return message;
  } catch (const std::exception& e) {
    FAIL("expected InputError, got: " << e.what());
  }
  FAIL("expected InputError, nothing was thrown");
  return {};
}

// A fresh temporary folder, removed when the object dies.
class TempDir {
public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("medusa_io_test_" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

} // namespace medusa::io::test
