// Exact bottleneck distance (docs/MATH.md §7.7).
#pragma once

#include "medusa/persistence/distance.h"
#include "medusa/persistence/points.h"

#include <cstddef>
#include <vector>

namespace medusa::persistence {

// Exact d_B of the finite parts: the smallest candidate value (a ground distance between two
// points or a half persistence) at which the threshold graph admits a matching leaving only
// near-diagonal points unmatched, found by binary search and Hopcroft-Karp. The n*m ground distances
// are never all stored: random pivots narrow the range until at most sort_limit candidates remain.
double bottleneck_finite(const std::vector<Point>& a, const std::vector<Point>& b,
                         std::size_t sort_limit = std::size_t{1} << 20);

// d_B of two diagrams: finite part, essential part (sorted births, max |b - b'|; +inf when the counts
// differ) and their maximum, or the finite part only when ignore_essential.
DistanceResult bottleneck_distance(const PointDiagram& a, const PointDiagram& b,
                                   bool ignore_essential = false);

} // namespace medusa::persistence
