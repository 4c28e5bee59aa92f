// A small valid store for the fault tests: the worked flip of MATH.md Appendix B (5 vertices, 2 frames,
// 31 cells) streamed through libmedusa's builder into a StoreWriter.
#pragma once

#include "appendix_b.h"
#include "medusa/complex/store_writer.h"
#include "medusa_fixtures.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace medusa::test {

inline void write_small_store(const std::string& path) {
  complex::StoreWriter writer(path);
  play_into(appendix_b_stream(), writer, 5, 2);
}

inline std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

inline void write_file_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
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
