#include "medusa/io/centroid.h"

#include "medusa/core/error.h"

namespace medusa::io {

namespace {
__extension__ using Wide = __int128; // exact cross-multiplication of two int64 fractions
} // namespace

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
      // num/n > best_num/best_den  <=>  num * best_den > best_num * n (exact in 128 bits)
      if (static_cast<Wide>(num) * report.max_displacement_den >
          static_cast<Wide>(report.max_displacement_num) * n) {
        report.max_displacement_num = num;
        report.max_displacement_den = n;
      }
    }
  }
  if (moved)
    ++report.moved;
  return out;
}

} // namespace medusa::io
