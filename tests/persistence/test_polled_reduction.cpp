// The reduction that Ctrl-C can stop (PolledTwistReduction) against PHAT's own twist reduction, and the
// poll threaded through the whole-run diagrams and the open classes of the summary.
#include "cell_list.h"
#include "medusa/persistence/boundary_matrix.h"
#include "medusa/persistence/medusa_diagrams.h"
#include "medusa/persistence/open_classes.h"

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

// A filtration of the closure of random tetrahedra on `vertices` points, each simplex entering at a
// random step after its last facet: thousands of columns with real fill-in.
Filtration random_filtration(std::mt19937& rng, int vertices, int tets) {
  std::map<std::vector<int>, int> step;
  for (int t = 0; t < tets; ++t) {
    std::set<int> s;
    while (s.size() < 4)
      s.insert(static_cast<int>(rng() % static_cast<unsigned>(vertices)));
    const std::vector<int> tet(s.begin(), s.end());
    for (unsigned mask = 1; mask < 16; ++mask) {
      std::vector<int> f;
      for (int i = 0; i < 4; ++i)
        if (mask & (1u << i))
          f.push_back(tet[static_cast<std::size_t>(i)]);
      step.emplace(f, 0);
    }
  }
  // Births by dimension: a simplex after the latest of its facets.
  std::vector<std::vector<int>> by_size;
  for (const auto& entry : step)
    by_size.push_back(entry.first);
  std::stable_sort(by_size.begin(), by_size.end(),
                   [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::vector<std::pair<int, std::vector<int>>> order;
  for (const std::vector<int>& f : by_size) {
    int& b = step.at(f);
    int latest = 0;
    if (f.size() > 1)
      for (std::size_t drop = 0; drop < f.size(); ++drop) {
        std::vector<int> g = f;
        g.erase(g.begin() + static_cast<std::ptrdiff_t>(drop));
        latest = std::max(latest, step.at(g));
      }
    b = latest + 1 + static_cast<int>(rng() % 50);
    order.emplace_back(b, f);
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return std::make_tuple(a.first, a.second.size(), a.second) <
           std::make_tuple(b.first, b.second.size(), b.second);
  });
  std::map<std::vector<int>, std::int64_t> index;
  Filtration f;
  for (const auto& [birth, s] : order) {
    std::vector<std::int64_t> column;
    if (s.size() > 1)
      for (std::size_t drop = 0; drop < s.size(); ++drop) {
        std::vector<int> g = s;
        g.erase(g.begin() + static_cast<std::ptrdiff_t>(drop));
        column.push_back(index.at(g));
      }
    std::sort(column.begin(), column.end());
    index.emplace(s, static_cast<std::int64_t>(f.size()));
    f.cells.push_back(f.size());
    f.dims.push_back(static_cast<int>(s.size()) - 1);
    f.columns.push_back(column);
  }
  return f;
}

} // namespace

TEST_CASE("The polled twist reduction leaves the reduced matrix and the pairs of PHAT's twist reduction") {
  const unsigned seed = std::random_device{}();
  std::cout << "polled reduction seed " << seed << '\n';
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 5; ++trial) {
    CAPTURE(seed, trial);
    const Filtration f = random_filtration(rng, 60 + 20 * trial, 1200 + 400 * trial);
    auto ours = make_boundary_matrix(f);
    auto phats = make_boundary_matrix(f);
    std::size_t polls = 0;
    PolledTwistReduction{[&] { ++polls; }}(ours);
    phat::twist_reduction{}(phats);
    std::vector<phat::index> a, b;
    for (phat::index j = 0; j < static_cast<phat::index>(f.size()); ++j) {
      // Emptied first: PHAT's pivot column appends to a non-empty vector and then adds the old entries
      // back into itself, which changes the matrix (the other representations clear it).
      a.clear();
      b.clear();
      ours.get_col(j, a);
      phats.get_col(j, b);
      REQUIRE(a == b);
    }
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
