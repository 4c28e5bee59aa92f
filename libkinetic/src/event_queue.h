// The event queue: certificate failure times in exact order, earliest first (MATH.md 3.7, 5.2).
// Entries of retired or reinstalled certificates stay in the queue and are skipped by version.
#pragma once

#include "medusa/kinetic/algebraic_time.h"

#include <cstdint>
#include <queue>
#include <vector>

namespace medusa::kinetic::detail {

struct QueueEntry {
  SlabTime u;
  std::uint32_t cert;
  std::uint32_t version;
};
struct LaterFirst {
  bool operator()(const QueueEntry& a, const QueueEntry& b) const { return compare(b.u, a.u) < 0; }
};

using EventQueue = std::priority_queue<QueueEntry, std::vector<QueueEntry>, LaterFirst>;

} // namespace medusa::kinetic::detail
