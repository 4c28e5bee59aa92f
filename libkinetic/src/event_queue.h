// The event queue: certificate failure times in exact order, earliest first (MATH.md 3.7, 5.2).
// Entries of retired or reinstalled certificates stay in the queue and are skipped by version.
#pragma once

#include "medusa/kinetic/algebraic_time.h"

#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

struct QueueEntry {
  QueueEntry(SlabTime time, std::uint32_t c, std::uint32_t v) : u(std::move(time)), cert(c), version(v) {
    u.enclosure(lo, hi);
  }
  SlabTime u;
  std::uint32_t cert;
  std::uint32_t version;
  // An enclosure of u when the entry was made. Refinement only narrows u's own enclosure, so this
  // one stays valid: most comparisons in the heap are decided here, without calling compare().
  double lo = 0.0, hi = 0.0;
};
struct LaterFirst {
  bool operator()(const QueueEntry& a, const QueueEntry& b) const {
    if (b.hi < a.lo)
      return true;
    if (a.hi < b.lo)
      return false;
    return compare(b.u, a.u) < 0;
  }
};

using EventQueue = std::priority_queue<QueueEntry, std::vector<QueueEntry>, LaterFirst>;

} // namespace medusa::kinetic::detail
