// Hierarchical clustering of runs from a distance matrix, as a dendrogram in the layout of scipy's
// linkage matrix.
#pragma once

#include "medusa/persistence/distance_matrix.h"

#include <cstddef>
#include <vector>

namespace medusa::persistence {

// One merge: clusters `first` < `second` (leaves are 0..n-1, the cluster made by merge k is n+k)
// join at `height` into a cluster of `size` leaves.
struct Merge {
  std::size_t first = 0;
  std::size_t second = 0;
  double height = 0;
  std::size_t size = 0;
};

struct Dendrogram {
  std::size_t leaves = 0;
  std::vector<Merge> merges; // n-1 merges, heights non-decreasing
};

// Single linkage: the edges of a minimum spanning tree (Boost.Graph, Kruskal) in increasing weight,
// merged with union-find. Ties are taken in (weight, i, j) order.
Dendrogram single_linkage(const DistanceMatrix& distances);

// Average linkage (UPGMA): repeatedly merge the two clusters of smallest mean pairwise distance
// (Lance-Williams update); ties go to the pair of smallest cluster ids.
Dendrogram average_linkage(const DistanceMatrix& distances);

} // namespace medusa::persistence
