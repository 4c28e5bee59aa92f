#include "periodic_centroid.h"

#include "medusa/core/error.h"
#include "medusa/io/periodic_domain.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace medusa::io {

namespace {

struct Unwrapped {
  std::array<std::int64_t, 3> reference{}; // lattice indices of the first voxel
  std::array<std::int64_t, 3> sum{};       // sum of the unwrapped lattice indices
  std::array<std::int64_t, 3> low{}, high{};
  bool seen = false;
};

[[noreturn]] void overflow(const VtkSnapshot& snap, std::int64_t id, std::int64_t scale) {
  throw InputError(snap.path + ": cell " + std::to_string(id) +
                   ": centroid sum overflows 64 bits at grid scale " + std::to_string(scale));
}

} // namespace

void periodic_centroids(VtkSnapshot& snap, const std::vector<std::int64_t>& ids,
                        const std::array<bool, 3>& periodic, std::int64_t scale) {
  const std::array<std::int64_t, 3>& n = snap.dimensions;
  std::unordered_map<std::int64_t, Unwrapped> cells;
  cells.reserve(snap.cells.size());
  for (std::size_t p = 0; p < ids.size(); ++p) {
    const std::int64_t id = ids[p];
    if (id == 0)
      continue;
    const std::int64_t q = static_cast<std::int64_t>(p);
    const std::array<std::int64_t, 3> index = {q % n[0], (q / n[0]) % n[1], q / (n[0] * n[1])};
    Unwrapped& u = cells[id];
    if (!u.seen) {
      u.seen = true;
      u.reference = index;
    }
    for (std::size_t a = 0; a < 3; ++a) {
      if (!periodic[a])
        continue;
      // Exact integer minimum image on the lattice (docs/MATH.md §8.1).
      const std::int64_t d = minimum_image(index[a] - u.reference[a], n[a]);
      u.sum[a] += u.reference[a] + d;
      u.low[a] = std::min(u.low[a], d);
      u.high[a] = std::max(u.high[a], d);
    }
  }
  for (VtkCell& c : snap.cells) {
    const Unwrapped& u = cells.at(c.id);
    for (std::size_t a = 0; a < 3; ++a) {
      if (!periodic[a])
        continue;
      const std::int64_t extent = u.high[a] - u.low[a];
      if (2 * extent >= n[a])
        throw InputError(snap.path + ": cell " + std::to_string(c.id) + ": its voxels span " +
                         std::to_string(extent + 1) + " of the " + std::to_string(n[a]) +
                         " lattice sites along " + char('x' + a) + " (periodic), from " +
                         std::to_string(u.reference[a] + u.low[a]) + " to " +
                         std::to_string(u.reference[a] + u.high[a]) +
                         " unwrapped: a cell must stay narrower than half the period for its centre to be "
                         "defined (docs/MATH.md §8.1)");
      // X = n_voxels * S*g + S*h * sum, then reduced so that X / n_voxels lies in [S*g, S*g + P).
      std::int64_t base = 0, offset = 0, x = 0, period = 0, span = 0;
      if (__builtin_mul_overflow(c.voxels, snap.origin[a], &base) ||
          __builtin_mul_overflow(snap.spacing[a], u.sum[a], &offset) ||
          __builtin_add_overflow(base, offset, &x) ||
          __builtin_mul_overflow(snap.spacing[a], n[a], &period) ||
          __builtin_mul_overflow(period, c.voxels, &span))
        overflow(snap, c.id, scale);
      c.scaled_sum[a] = wrap_coordinate(x, base, span);
    }
  }
}

} // namespace medusa::io
