// Two cells meeting inside a slab (docs/MATH.md §2.5): p(u) = q(u) for some u in the open slab (0, 1).
// The engine reports it as an input error; the lower-bound skeleton of bench/ stops on it.
#pragma once

#include "moving_point.h"

#include <cstdint>
#include <optional>

namespace medusa::kinetic {

// u = num / den, den > 0, not reduced.
struct MeetingTime {
  std::int64_t num = 0, den = 1;
};

// When p and q are at one position at some u in (0, 1): p - q = da + u db vanishes there iff every
// coordinate does, at the same u. Decided in integers (grid coordinates and displacements are below
// 2^41, so the cross products fit in 128 bits). nullopt when they never meet inside the slab, and
// also for equal positions and velocities, two cells at one position at the slab start, which the
// frame reports.
std::optional<MeetingTime> meeting_in_slab(const MovingPoint& p, const MovingPoint& q);

} // namespace medusa::kinetic
