#include "medusa/io/cell_volumes.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>

namespace medusa::io {

double median_cell_volume(const CellVolumes& volumes) {
  std::vector<std::int64_t> all;
  for (const auto& v : volumes)
    all.insert(all.end(), v.begin(), v.end());
  if (all.empty())
    throw InputError("no cell volumes available for --radius auto (the source has no volume column): give "
                     "--radius in lattice units");
  const std::size_t mid = all.size() / 2;
  std::nth_element(all.begin(), all.begin() + mid, all.end());
  const double upper = double(all[mid]);
  if (all.size() % 2 == 1)
    return upper;
  const double lower = double(*std::max_element(all.begin(), all.begin() + mid));
  return (lower + upper) / 2;
}

double equivalent_radius(double volume, int dimension) {
  const double pi = std::acos(-1.0);
  if (volume < 0)
    throw InputError("cell volume must be non-negative, got " + std::to_string(volume));
  if (dimension == 3)
    return std::cbrt(3 * volume / (4 * pi));
  if (dimension == 2)
    return std::sqrt(volume / pi);
  throw InputError("dimension must be 2 or 3, got " + std::to_string(dimension));
}

} // namespace medusa::io
