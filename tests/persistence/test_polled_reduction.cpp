// The reduction that Ctrl-C can stop (PolledTwistReduction) against PHAT's own twist reduction, and the
// poll threaded through the whole-run diagrams and the open classes of the summary.
#include "cell_list.h"
#include "medusa/persistence/boundary_matrix.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "medusa/persistence/open_classes.h"
#include "random_filtration.h"

#include <catch2/catch.hpp>

#include <phat/algorithms/twist_reduction.h>

#include <atomic>
#include <iostream>
#include <map>
#include <random>
#include <set>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

struct Stop {};

} // namespace

TEST_CASE("The polled twist reduction leaves the reduced matrix and the pairs of PHAT's twist reduction") {
  const unsigned seed = std::random_device{}();
  std::cout << "polled reduction seed " << seed << '\n';
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 5; ++trial) {
    CAPTURE(seed, trial);
    const Filtration f = random_filtration(rng, 60 + 20 * trial, 1200 + 400 * trial);
    auto ours = make_boundary_matrix(f);
    auto phats = make_boundary_matrix<phat::bit_tree_pivot_column>(f);
    std::size_t polls = 0;
    PolledTwistReduction{[&] { ++polls; }}(ours);
    phat::twist_reduction{}(phats);
    require_same_columns(ours, phats);
    CHECK(reduced_pairs(ours) == reduce(f));
    CHECK(reduce(f, {}) == reduce(f));
    // Every 4096 columns of each dimension's pass (dimensions 3, 2, 1).
    CHECK(polls == 3 * ((f.size() + 4095) / 4096));
    CHECK(f.size() > 4096);
  }
}

TEST_CASE("A poll that throws stops a reduction, the diagrams of a run on any thread count, and the open "
          "classes") {
  std::mt19937 rng(7);
  const Filtration f = random_filtration(rng, 60, 500);
  CHECK_THROWS_AS(reduce(f, [] { throw Stop{}; }), Stop);

  const std::vector<Cell> cells = positional(symmetric_cells());
  const std::vector<int> vertex_type{1, 1, 2};
  const std::vector<Diagram> plain = compute_medusa_diagrams(cells, vertex_type, {1, 2});
  for (unsigned threads : {1u, 2u, 4u}) {
    CAPTURE(threads);
    std::atomic<int> calls{0};
    DiagramRunOptions counting;
    counting.threads = threads;
    counting.poll = [&] { ++calls; };
    const std::vector<Diagram> polled = compute_medusa_diagrams(cells, vertex_type, {1, 2}, counting);
    REQUIRE(polled.size() == plain.size());
    for (std::size_t k = 0; k < plain.size(); ++k)
      CHECK(polled[k].pairs.size() == plain[k].pairs.size());
    CHECK(calls >= static_cast<int>(plain.size())); // each reduction polls at its first column
    DiagramRunOptions stopping;
    stopping.threads = threads;
    stopping.poll = [] { throw Stop{}; };
    CHECK_THROWS_AS(compute_medusa_diagrams(cells, vertex_type, {1, 2}, stopping), Stop);
  }
  CHECK(end_classes_beyond_first(cells, {}, 0, 5, [] {}) == end_classes_beyond_first(cells, {}, 0, 5));
  CHECK_THROWS_AS(end_classes_beyond_first(cells, {}, 0, 5, [] { throw Stop{}; }), Stop);
}
