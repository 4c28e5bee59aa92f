#include "medusa/io/centroid.h"

#include "medusa/core/error.h"

namespace medusa::io {

bool centroid_on_grid(const std::array<std::int64_t, 3>& scaled_sum, std::int64_t n) {
  for (std::int64_t x : scaled_sum)
    if (x % n != 0)
      return false;
  return true;
}

kinetic::GridPoint snap_centroid(const std::array<std::int64_t, 3>& scaled_sum, std::int64_t n,
                                 SnapReport& report) {
  if (n <= 0)
    throw InternalError("snap_centroid: voxel count must be positive");
  kinetic::GridPoint out{};
  bool moved = false;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t x = scaled_sum[a];
    std::int64_t q = x / n, r = x % n;
    if (r < 0) { // floor division: 0 <= r < n
      --q;
      r += n;
    }
    const std::int64_t twice = 2 * r;
    if (twice > n || (twice == n && q % 2 != 0))
      ++q;
    out[a] = q;
    // |X/n - q| = |x - q n| / n
    const std::int64_t num = x - q * n < 0 ? q * n - x : x - q * n;
    if (num != 0) {
      moved = true;
      report.widen(num, n);
    }
  }
  if (moved)
    ++report.moved;
  return out;
}

} // namespace medusa::io
