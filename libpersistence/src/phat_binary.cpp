#include "medusa/persistence/boundary_matrix.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace medusa::persistence {
namespace {

void put(std::ofstream& out, std::int64_t value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

} // namespace

void write_phat_binary(const Filtration& filtration, const std::string& path) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw StoreError("phat matrix: cannot open " + temporary + " for writing");
    put(out, static_cast<std::int64_t>(filtration.size()));
    for (std::size_t j = 0; j < filtration.size(); ++j) {
      put(out, filtration.dims[j]);
      put(out, static_cast<std::int64_t>(filtration.columns[j].size()));
      for (std::int64_t row : filtration.columns[j])
        put(out, row);
    }
    out.close();
    if (!out)
      throw StoreError("phat matrix: write failed on " + temporary);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw StoreError("phat matrix: cannot rename " + temporary + " to " + path);
}

std::vector<IndexPair> read_phat_binary_pairs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw StoreError("phat pairs: cannot open " + path);
  std::int64_t count = 0;
  if (!in.read(reinterpret_cast<char*>(&count), sizeof count) || count < 0)
    throw StoreError("phat pairs: " + path + " has no valid pair count");
  std::vector<IndexPair> pairs(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    std::int64_t values[2];
    if (!in.read(reinterpret_cast<char*>(values), sizeof values))
      throw StoreError("phat pairs: " + path + " is truncated at pair " + std::to_string(i));
    pairs[i] = {values[0], values[1]};
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

} // namespace medusa::persistence
