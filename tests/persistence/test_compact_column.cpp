// The compact boundary matrix (compact_column.h) against PHAT's own representations: the same reduced
// matrix and pairs under each of PHAT's reductions, as PHAT's self-test cross-checks its
// representations.
#include "random_filtration.h"

#include "medusa/core/error.h"
#include "medusa/persistence/boundary_matrix.h"

#include <catch2/catch.hpp>

#include <phat/algorithms/chunk_reduction.h>
#include <phat/algorithms/row_reduction.h>
#include <phat/algorithms/standard_reduction.h>
#include <phat/algorithms/twist_reduction.h>

#include <iostream>
#include <random>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

template <class Representation, class Algorithm>
phat::boundary_matrix<Representation> reduced(const Filtration& f) {
  auto matrix = make_boundary_matrix<Representation>(f);
  Algorithm{}(matrix);
  return matrix;
}

template <class Algorithm> void check_algorithm(const Filtration& f) {
  const auto phats = reduced<phat::bit_tree_pivot_column, Algorithm>(f);
  require_same_columns(reduced<compact_pivot_column, Algorithm>(f), phats);
  // Without a pivot column, additions go through CompactColumn::_add_to.
  require_same_columns(reduced<compact_vector, Algorithm>(f), reduced<phat::vector_vector, Algorithm>(f));
  CHECK(reduce<compact_pivot_column, Algorithm>(f) == reduce<phat::bit_tree_pivot_column, Algorithm>(f));
}

} // namespace

TEST_CASE("The compact boundary matrix reduces to PHAT's reduced matrix and pairs under each of PHAT's "
          "reductions") {
  const unsigned seed = std::random_device{}();
  std::cout << "compact column seed " << seed << '\n';
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 3; ++trial) {
    CAPTURE(seed, trial);
    const Filtration f = random_filtration(rng, 40 + 20 * trial, 600 + 300 * trial);
    require_same_columns(make_boundary_matrix<compact_pivot_column>(f),
                         make_boundary_matrix<phat::bit_tree_pivot_column>(f));
    check_algorithm<phat::twist_reduction>(f);
    check_algorithm<phat::standard_reduction>(f);
    check_algorithm<phat::row_reduction>(f);
    check_algorithm<phat::chunk_reduction>(f);
  }
}

TEST_CASE("A compact column keeps more than four entries on the heap through copies, moves and removals") {
  const phat::column seven{1, 4, 9, 16, 25, 36, 49}, five{1, 4, 9, 16, 25};
  CompactColumn c;
  c._set_col(seven);
  phat::column out;
  c._get_col(out);
  CHECK(out == seven);
  CHECK(c._get_max_index() == 49);
  CompactColumn copy = c;
  c._remove_max();
  c._remove_max();
  c._get_col(out);
  CHECK(out == five);
  copy._get_col(out);
  CHECK(out == seven);
  CompactColumn moved = std::move(copy);
  moved._get_col(out);
  CHECK(out == seven);
  copy = moved; // a moved-from column takes a copy
  copy._get_col(out);
  CHECK(out == seven);
  CompactColumn other;
  other._set_col({4, 9, 100});
  moved._add_to(other);
  moved._get_col(out);
  CHECK(out == phat::column{1, 16, 25, 36, 49, 100});
  moved = c;
  moved._get_col(out);
  CHECK(out == five);
  moved._clear();
  CHECK(moved._is_empty());
  CHECK(moved._get_max_index() == -1);
}

TEST_CASE("A compact column refuses a row that is no 32-bit filtration index") {
  CompactColumn c;
  c._set_col({2, 3});
  CHECK_THROWS_AS(c._set_col({2, phat::index{UINT32_MAX}}), InternalError);
  CHECK_THROWS_AS(c._set_col({-1}), InternalError);
  phat::column out;
  c._get_col(out);
  CHECK(out == phat::column{2, 3});
}
