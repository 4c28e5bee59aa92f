#include "medusa/medusa/homology.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>

namespace medusa {

namespace {

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// Symmetric difference of two sorted index lists (addition over Z/2).
void add_column(std::vector<std::size_t>& target, const std::vector<std::size_t>& source) {
  std::vector<std::size_t> sum;
  sum.reserve(target.size() + source.size());
  std::set_symmetric_difference(target.begin(), target.end(), source.begin(), source.end(),
                                std::back_inserter(sum));
  target.swap(sum);
}

} // namespace

std::vector<std::size_t> betti_numbers(const ChainComplex& complex) {
  const std::size_t n = complex.dims.size();
  if (complex.facets.size() != n)
    throw InternalError("betti numbers: " + std::to_string(n) + " dimensions but " +
                        std::to_string(complex.facets.size()) + " facet lists");
  if (n == 0)
    return {};
  const int top = *std::max_element(complex.dims.begin(), complex.dims.end());
  std::vector<std::size_t> f(static_cast<std::size_t>(top) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int d = complex.dims[i];
    if (d < 0 || complex.facets[i].size() != (d == 0 ? 0u : static_cast<std::size_t>(d) + 1))
      throw InternalError("betti numbers: element " + std::to_string(i) + " of dimension " +
                          std::to_string(d) + " has " + std::to_string(complex.facets[i].size()) + " facets");
    for (std::size_t j : complex.facets[i])
      if (j >= n || complex.dims[j] != d - 1)
        throw InternalError("betti numbers: element " + std::to_string(i) + " has an invalid facet " +
                            std::to_string(j));
    ++f[static_cast<std::size_t>(d)];
  }

  // rank[k] = rank of d_k : C_k -> C_{k-1}. Reduce from the top dimension down, clearing the columns
  // of pivots (twist, docs/MATH.md §7.5): a column whose index is a pivot of d_{k+1} reduces to zero.
  std::vector<std::size_t> rank(static_cast<std::size_t>(top) + 2, 0);
  std::vector<char> cleared(n, 0);
  for (int k = top; k >= 1; --k) {
    std::unordered_map<std::size_t, std::vector<std::size_t>> pivot; // low -> reduced column
    for (std::size_t i = 0; i < n; ++i) {
      if (complex.dims[i] != k || cleared[i])
        continue;
      std::vector<std::size_t> col = complex.facets[i];
      std::sort(col.begin(), col.end());
      while (!col.empty()) {
        auto it = pivot.find(col.back());
        if (it == pivot.end())
          break;
        add_column(col, it->second);
      }
      if (!col.empty()) {
        cleared[col.back()] = 1;
        pivot.emplace(col.back(), std::move(col));
      }
    }
    rank[static_cast<std::size_t>(k)] = pivot.size();
  }

  std::vector<std::size_t> betti(static_cast<std::size_t>(top) + 1, 0);
  // beta_0 by union-find, which is also a check of rank d_1.
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::size_t components = f[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (complex.dims[i] != 1)
      continue;
    const std::size_t a = find_root(parent, complex.facets[i][0]);
    const std::size_t b = find_root(parent, complex.facets[i][1]);
    if (a != b) {
      parent[a] = b;
      --components;
    }
  }
  if (top >= 1 && components != f[0] - rank[1])
    throw InternalError("betti numbers: union-find and the rank of d_1 disagree");
  betti[0] = components;
  for (std::size_t k = 1; k <= static_cast<std::size_t>(top); ++k)
    betti[k] = f[k] - rank[k] - rank[k + 1];
  return betti;
}

} // namespace medusa
