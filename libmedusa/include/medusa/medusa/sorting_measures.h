// Classical cell-sorting measures of every time slice K_t (docs/MATH.md §6.9): contacts between types,
// same-type neighbour fractions and clusters, from the edges and vertices of the exact complexes.
#pragma once

#include "medusa/medusa/medusa.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace medusa {

// The measures of one slice for the whole complex (type empty) or for the cells of one type X.
struct SortingMeasures {
  std::optional<int> type;
  std::size_t cells = 0;                 // vertices of K_t (of type X)
  std::size_t edges = 0;                 // edges of K_t (with at least one end of type X)
  std::size_t heterotypic_edges = 0;     // of those, edges whose two cells differ in type
  std::size_t cells_with_neighbours = 0; // cells (of type X) with at least one edge in K_t
  // Mean over cells_with_neighbours of (neighbours of the same type / neighbours); NaN when there
  // is no such cell.
  double same_type_fraction = 0.0;
  std::size_t clusters = 0;        // components of K_t (of K_t^X, docs/MATH.md §7.4)
  std::size_t largest_cluster = 0; // cells in the largest of them (0 without cells)

  // heterotypic_edges / edges; NaN without edges.
  double heterotypic_fraction() const;
  // cells / clusters; NaN without clusters.
  double mean_cluster_size() const;
};

// One sample per slice, as signatures_over_time lays them out: after every batch, then K(t_end-).
struct SortingSample {
  std::uint64_t batch = 0;
  bool before = false; // true only for the final sample K(t_end-)
  double time = 0.0;
  std::vector<std::size_t> frames;       // the frames whose reported state this is
  std::vector<SortingMeasures> measures; // whole complex first, then each type in increasing order
};

// The measures of every slice. Needs the input (cell types). Cost O(N log B) for N cells and B
// batches: counts by a sweep over the slices, clusters by offline dynamic connectivity (a segment
// tree over the slices with a union-find that undoes its unions). `poll` is called every few
// thousand steps, so a caller can stop by throwing.
std::vector<SortingSample> sorting_over_time(const Medusa& medusa, const std::function<void()>& poll = {});

} // namespace medusa
