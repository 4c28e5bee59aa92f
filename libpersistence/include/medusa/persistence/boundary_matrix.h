// Boundary matrices of a filtration for PHAT, built in memory, and their reduction (docs/MATH.md §7.5).
#pragma once

#include "medusa/persistence/compact_column.h"
#include "medusa/persistence/filtration.h"

#include <phat/boundary_matrix.h>
#include <phat/compute_persistence_pairs.h>
#include <phat/persistence_pairs.h>
#include <phat/representations/default_representations.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace medusa::persistence {

// A persistence pair of filtration indices: the class created by column `birth` dies at `death`.
using IndexPair = std::pair<std::int64_t, std::int64_t>;

// One column per cell in filtration order, holding its facet indices over Z/2 (docs/MATH.md §7.5).
template <class Representation = compact_pivot_column>
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
template <class Representation = compact_pivot_column, class Algorithm = phat::twist_reduction>
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

// PHAT's twist reduction (phat/algorithms/twist_reduction.h) step for step, with `poll` called every
// few thousand columns: PHAT's algorithms take no callback, and the reduction of a million-cell medusa
// runs for minutes, which Ctrl-C must be able to stop (by throwing from `poll`). The same column
// operations in the same order give the same reduced matrix, hence the same pairs and representatives.
class PolledTwistReduction {
public:
  explicit PolledTwistReduction(std::function<void()> poll) : poll_(std::move(poll)) {}
  template <class Representation> void operator()(phat::boundary_matrix<Representation>& matrix) const {
    constexpr phat::index poll_every = 4096;
    const phat::index columns = matrix.get_num_cols();
    std::vector<phat::index> lowest_one_lookup(static_cast<std::size_t>(columns), -1);
    for (phat::index dim = matrix.get_max_dim(); dim >= 1; --dim)
      for (phat::index col = 0; col < columns; ++col) {
        if (poll_ && col % poll_every == 0)
          poll_();
        if (matrix.get_dim(col) != dim)
          continue;
        phat::index lowest_one = matrix.get_max_index(col);
        while (lowest_one != -1 && lowest_one_lookup[static_cast<std::size_t>(lowest_one)] != -1) {
          matrix.add_to(lowest_one_lookup[static_cast<std::size_t>(lowest_one)], col);
          lowest_one = matrix.get_max_index(col);
        }
        if (lowest_one != -1) {
          lowest_one_lookup[static_cast<std::size_t>(lowest_one)] = col;
          matrix.clear(lowest_one);
        }
        matrix.finalize(col);
      }
  }

private:
  std::function<void()> poll_;
};

// The finite pairs of a reduced matrix, read as phat::compute_persistence_pairs reads them, sorted by
// birth index.
template <class Representation>
std::vector<IndexPair> reduced_pairs(const phat::boundary_matrix<Representation>& matrix) {
  std::vector<IndexPair> result;
  for (phat::index j = 0; j < matrix.get_num_cols(); ++j)
    if (!matrix.is_empty(j))
      result.emplace_back(matrix.get_max_index(j), j);
  std::sort(result.begin(), result.end());
  return result;
}

// The finite pairs by PolledTwistReduction on compact_pivot_column: what reduce() gives, and
// stoppable.
inline std::vector<IndexPair> reduce(const Filtration& filtration, const std::function<void()>& poll) {
  auto matrix = make_boundary_matrix(filtration);
  PolledTwistReduction{poll}(matrix);
  return reduced_pairs(matrix);
}

// Writes the boundary matrix in PHAT's binary format (int64 number of columns, then per column int64
// dimension, size and entries; phat/boundary_matrix.h save_binary), for the `phat` command-line tool.
// Written under a temporary name and renamed when complete; throws StoreError on I/O failure.
void write_phat_binary(const Filtration& filtration, const std::string& path);

// Reads the pairs written by `phat` in its binary format (int64 count, then birth, death per pair),
// sorted by birth index. Throws StoreError on a missing or truncated file.
std::vector<IndexPair> read_phat_binary_pairs(const std::string& path);

} // namespace medusa::persistence
