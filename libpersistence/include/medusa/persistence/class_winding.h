// How a loop class winds around a periodic domain: a cycle along a periodic axis is not a hole in the
// tissue (docs/MATH.md §8.8).
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/representatives.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::persistence {

// The winding over Z/2 of a degree-1 representative cycle (medusa cell ids of edges) around each axis
// of the medusa's periodic domain: 1 when its edges cross the periodic boundary an odd number of
// times along that axis, else 0. Zero on open axes, and for a cycle of another degree or an open run.
std::array<std::int64_t, 3> cycle_winding(const medusa::Medusa& medusa, CellLists::List cycle);

// Per class of `classes` (aligned with classes.classes): the axes its loop wraps around ("x", "x,y";
// empty for a loop that does not wrap and for other degrees). Essential loops are taken in birth order
// and each reduced by the older wrapping ones (a change of representative that keeps the pairing), so
// at most one per independent direction around the domain wraps (docs/MATH.md §8.8).
std::vector<std::string> class_wrapping_axes(const medusa::Medusa& medusa, const DiagramWithClasses& classes);

// "x", "x,y", ...: the axes with a nonzero winding; empty if none.
std::string winding_axes(const std::array<std::int64_t, 3>& winding);

} // namespace medusa::persistence
