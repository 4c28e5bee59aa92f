// Hopcroft-Karp maximum cardinality matching on a bipartite graph given by adjacency lists
// (internal to libpersistence).
#pragma once

#include <cstddef>
#include <vector>

namespace medusa::persistence::detail {

// Size of a maximum matching between left vertices 0..adjacency.size()-1 and right vertices
// 0..right_count-1.
std::size_t max_matching(const std::vector<std::vector<std::size_t>>& adjacency, std::size_t right_count);

} // namespace medusa::persistence::detail
