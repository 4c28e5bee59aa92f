// How a loop class winds around a periodic domain: a cycle along a periodic axis is not a hole in the
// tissue (docs/MATH.md §8.8).
#pragma once

#include "medusa/medusa/medusa.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::persistence {

// The winding of a degree-1 representative cycle (medusa cell ids of edges, a Z/2 cycle) around each
// axis of the medusa's periodic domain: the sum, along closed walks that cover the cycle, of the
// periods each edge crosses. Zero on open axes, and for a cycle of another degree or an open run.
std::array<std::int64_t, 3> cycle_winding(const medusa::Medusa& medusa,
                                          const std::vector<medusa::CellId>& cycle);

// "x", "x,y", ...: the axes with a nonzero winding; empty if none.
std::string winding_axes(const std::array<std::int64_t, 3>& winding);

} // namespace medusa::persistence
