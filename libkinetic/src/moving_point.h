// A point moving linearly on one slab: p(u) = a + u b, u in [0, 1] (docs/MATH.md §2.2), on the grid.
#pragma once

#include <array>
#include <cstdint>

namespace medusa::kinetic {

struct MovingPoint {
  std::array<std::int64_t, 3> a{}; // position at the slab start (grid units)
  std::array<std::int64_t, 3> b{}; // displacement over the slab (grid units)
};

} // namespace medusa::kinetic
