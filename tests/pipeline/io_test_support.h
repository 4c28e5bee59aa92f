// Shared helpers of the medusa::io tests.
#pragma once

#include "medusa/core/error.h"
#include "support/temp_files.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
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

// Writes `text` to `path`, creating its folders.
inline void write(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
}

// A CompuCell3D XML with the lattice `dims` (e.g. `x="10" y="10" z="10"`), `potts` inside <Potts> after
// the dimensions (boundaries, steps), and the cell types Medium (0), A (1) and B (2).
inline std::string cc3d_xml(const std::string& dims, const std::string& potts = "") {
  return "<CompuCell3D>\n  <Potts>\n    <Dimensions " + dims + "/>\n" + potts +
         "  </Potts>\n  <Plugin Name=\"CellType\">\n    <CellType TypeName=\"Medium\" TypeId=\"0\"/>\n"
         "    <CellType TypeName=\"A\" TypeId=\"1\"/>\n    <CellType TypeName=\"B\" TypeId=\"2\"/>\n"
         "  </Plugin>\n</CompuCell3D>\n";
}

using medusa::test::TempDir; // support/temp_files.h

} // namespace medusa::io::test
