// Boundary matrices of a filtration for PHAT, built in memory, and their reduction (docs/MATH.md §7.5).
#pragma once

#include "medusa/persistence/filtration.h"

#include <phat/boundary_matrix.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/persistence_pairs.h>
#include <phat/representations/default_representations.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace medusa::persistence {

// A persistence pair of filtration indices: the class created by column `birth` dies at `death`.
using IndexPair = std::pair<std::int64_t, std::int64_t>;

// One column per cell in filtration order, holding its facet indices over Z/2 (docs/MATH.md §7.5).
template <class Representation = phat::bit_tree_pivot_column>
phat::boundary_matrix<Representation> make_boundary_matrix(const Filtration& filtration) {
  phat::boundary_matrix<Representation> matrix;
  matrix.set_num_cols(static_cast<phat::index>(filtration.size()));
  std::vector<phat::index> column;
  for (std::size_t j = 0; j < filtration.size(); ++j) {
    matrix.set_dim(static_cast<phat::index>(j), static_cast<phat::dimension>(filtration.dims[j]));
    column.assign(filtration.columns[j].begin(), filtration.columns[j].end());
    matrix.set_col(static_cast<phat::index>(j), column);
  }
  return matrix;
}

// The finite persistence pairs of the filtration, sorted by birth index. Essential classes are not
// among them (PHAT reports only pairs; see diagram.h).
template <class Representation = phat::bit_tree_pivot_column, class Algorithm = phat::twist_reduction>
std::vector<IndexPair> reduce(const Filtration& filtration) {
  auto matrix = make_boundary_matrix<Representation>(filtration);
  phat::persistence_pairs pairs;
  phat::compute_persistence_pairs<Algorithm>(pairs, matrix);
  pairs.sort();
  std::vector<IndexPair> result;
  result.reserve(static_cast<std::size_t>(pairs.get_num_pairs()));
  for (phat::index i = 0; i < pairs.get_num_pairs(); ++i)
    result.emplace_back(pairs.get_pair(i).first, pairs.get_pair(i).second);
  return result;
}

// Writes the boundary matrix in PHAT's binary format (int64 number of columns, then per column int64
// dimension, size and entries; phat/boundary_matrix.h save_binary), for the `phat` command-line tool.
// Written under a temporary name and renamed when complete; throws StoreError on I/O failure.
void write_phat_binary(const Filtration& filtration, const std::string& path);

// Reads the pairs written by `phat` in its binary format (int64 count, then birth, death per pair),
// sorted by birth index. Throws StoreError on a missing or truncated file.
std::vector<IndexPair> read_phat_binary_pairs(const std::string& path);

} // namespace medusa::persistence
