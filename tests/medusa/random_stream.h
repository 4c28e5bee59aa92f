// Random consistent event streams: subcomplexes of the full 3-skeleton on a few vertices evolving over
// batches, with radius changes, 2-3 flips, insertions and deletions (with the conditions under which
// docs/MATH.md §6.3 guarantees the join facets) and repair groups. Used for the invariants of docs/MATH.md
// §6.4.
#pragma once

#include "stream.h"

#include <cstdint>

namespace medusa::test {

struct RandomStreamOptions {
  int vertices = 8;         // vertex ids 0..vertices-1
  int initial_present = 6;  // vertices present at t_0
  std::size_t frames = 5;   // frames 0..frames-1 at 0, 10, 20, ... MCS
  int batches_per_slab = 3; // ordinary batches per slab (plus a frame batch at each inner frame)
};

Stream random_stream(std::uint64_t seed, const RandomStreamOptions& options = {});

} // namespace medusa::test
