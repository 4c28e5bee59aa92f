// Damaging a store on purpose: its bytes read whole, written back altered (flipped or truncated), for
// the tests that a damaged store gives a StoreError and is never read as other data.
#pragma once

#include "temp_files.h"

#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace medusa::test {

inline std::vector<char> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

inline void write_file_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Writes `bytes` to `path` with the byte at `offset` XORed with `mask`.
inline void write_flipped(const std::string& path, std::vector<char> bytes, std::size_t offset,
                          unsigned char mask) {
  bytes.at(offset) = static_cast<char>(static_cast<unsigned char>(bytes.at(offset)) ^ mask);
  write_file_bytes(path, bytes);
}

// Writes the first `keep` bytes of `bytes` to `path`.
inline void write_truncated(const std::string& path, const std::vector<char>& bytes, std::size_t keep) {
  write_file_bytes(path, std::vector<char>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(keep)));
}

} // namespace medusa::test
