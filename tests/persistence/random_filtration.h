// For the reduction tests: a random filtration (the closure of random tetrahedra, each simplex entering
// after its facets), and the column-by-column comparison of two reduced matrices.
#pragma once

#include "medusa/persistence/filtration.h"

#include <catch2/catch.hpp>
#include <phat/helpers/misc.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace medusa::persistence::test {

// A filtration of the closure of random tetrahedra on `vertices` points, each simplex entering at a
// random step after its last facet: thousands of columns with real fill-in.
inline Filtration random_filtration(std::mt19937& rng, int vertices, int tets) {
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
    f.cells.push_back(static_cast<FiltrationIndex>(f.size()));
    f.dims.push_back(static_cast<std::int8_t>(s.size() - 1));
    f.columns.push_back(column);
  }
  return f;
}

// Two boundary matrices (any PHAT representations) hold the same columns and dimensions.
template <class A, class B> void require_same_columns(const A& a, const B& b) {
  REQUIRE(a.get_num_cols() == b.get_num_cols());
  std::vector<phat::index> x, y;
  for (phat::index j = 0; j < a.get_num_cols(); ++j) {
    // Emptied first: PHAT's pivot column appends to a non-empty vector and then adds the old entries
    // back into itself, which changes the matrix (the other representations clear it).
    x.clear();
    y.clear();
    a.get_col(j, x);
    b.get_col(j, y);
    REQUIRE(x == y);
    REQUIRE(a.get_dim(j) == b.get_dim(j));
  }
}

} // namespace medusa::persistence::test
