// Shared helpers of the medusa::io tests.
#pragma once

#include "medusa/core/error.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>

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

using medusa::test::TempDir; // support/temp_files.h

} // namespace medusa::io::test
