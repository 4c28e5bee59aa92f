// Two cells meeting inside a slab (collision.h, docs/MATH.md §2.5).
#include "collision.h"

#include <cstddef>

namespace medusa::kinetic {

namespace {
__extension__ typedef __int128 Int128; // GCC and Clang: products of two grid differences
} // namespace

std::optional<MeetingTime> meeting_in_slab(const MovingPoint& p, const MovingPoint& q) {
  std::optional<std::size_t> pivot;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::int64_t da = p.a[i] - q.a[i], db = p.b[i] - q.b[i];
    if (db == 0) {
      if (da != 0)
        return std::nullopt; // apart in this coordinate for the whole slab
      continue;
    }
    // da + u db = 0 at u = -da / db, inside (0, 1) iff da and db have opposite signs and |da| < |db|.
    if (da == 0 || (da > 0) == (db > 0) || (da > 0 ? da : -da) >= (db > 0 ? db : -db))
      return std::nullopt;
    if (!pivot) {
      pivot = i;
    } else {
      const std::int64_t pa = p.a[*pivot] - q.a[*pivot], pb = p.b[*pivot] - q.b[*pivot];
      if (static_cast<Int128>(da) * pb != static_cast<Int128>(pa) * db)
        return std::nullopt; // another coordinate vanishes at another time
    }
  }
  if (!pivot)
    return std::nullopt;
  const std::int64_t da = p.a[*pivot] - q.a[*pivot], db = p.b[*pivot] - q.b[*pivot];
  return db > 0 ? MeetingTime{-da, db} : MeetingTime{da, -db};
}

} // namespace medusa::kinetic
