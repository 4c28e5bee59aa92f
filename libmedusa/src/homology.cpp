#include "medusa/medusa/homology.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

namespace medusa {

namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
constexpr std::size_t poll_every = 4096;

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// The reduced columns of the boundary matrices, each stored once when it becomes a pivot and never
// changed after: one arena of row indices, and for every row the column whose lowest entry it is.
class ReducedColumns {
public:
  explicit ReducedColumns(std::size_t rows) : owner_(rows, none) {}
  // The reduced column with lowest entry `row`, or an empty range.
  std::pair<const std::uint32_t*, const std::uint32_t*> with_low(std::uint32_t row) const {
    const std::uint32_t k = owner_[row];
    if (k == none)
      return {nullptr, nullptr};
    return {rows_.data() + starts_[k], rows_.data() + starts_[k + 1]};
  }
  void add(const std::vector<std::uint32_t>& column) {
    owner_[column.back()] = static_cast<std::uint32_t>(starts_.size() - 1);
    rows_.insert(rows_.end(), column.begin(), column.end());
    starts_.push_back(rows_.size());
  }

private:
  std::vector<std::uint32_t> owner_;
  std::vector<std::size_t> starts_{0};
  std::vector<std::uint32_t> rows_;
};

void check(const ChainComplex& complex, std::vector<std::size_t>& f) {
  const std::size_t n = complex.size();
  for (std::size_t i = 0; i < n; ++i) {
    const int d = complex.dim(i);
    if (d < 0 || complex.facet_count(i) != (d == 0 ? 0u : static_cast<std::size_t>(d) + 1))
      throw InternalError("betti numbers: element " + std::to_string(i) + " of dimension " +
                          std::to_string(d) + " has " + std::to_string(complex.facet_count(i)) + " facets");
    for (const std::uint32_t* j = complex.facets_begin(i); j != complex.facets_end(i); ++j)
      if (*j >= n || complex.dim(*j) != d - 1)
        throw InternalError("betti numbers: element " + std::to_string(i) + " has an invalid facet " +
                            std::to_string(*j));
    if (static_cast<std::size_t>(d) >= f.size())
      f.resize(static_cast<std::size_t>(d) + 1, 0);
    ++f[static_cast<std::size_t>(d)];
  }
}

} // namespace

std::vector<std::size_t> betti_numbers(const ChainComplex& complex, const std::function<void()>& poll) {
  const std::size_t n = complex.size();
  if (n >= none)
    throw InternalError("betti numbers: " + std::to_string(n) + " elements, more than 2^32 - 1");
  if (n == 0)
    return {};
  std::vector<std::size_t> f;
  check(complex, f);
  const std::size_t top = f.size() - 1;
  const auto call_poll = [&](std::size_t step) {
    if (poll && step % poll_every == 0)
      poll();
  };

  std::vector<std::vector<std::uint32_t>> of_dim(top + 1);
  for (std::size_t d = 0; d <= top; ++d)
    of_dim[d].reserve(f[d]);
  for (std::uint32_t i = 0; i < n; ++i)
    of_dim[static_cast<std::size_t>(complex.dim(i))].push_back(i);

  // rank[k] = rank of d_k : C_k -> C_{k-1}. From the top dimension down to 2, clearing the columns of
  // pivots (twist, docs/MATH.md §7.5): a column whose index is a pivot of d_{k+1} reduces to zero. The
  // rank of d_1 is f_0 minus the components, which a union-find gives without a reduction.
  std::vector<std::size_t> rank(top + 2, 0);
  std::vector<char> cleared(n, 0);
  ReducedColumns reduced(n);
  std::vector<std::uint32_t> column, sum;
  std::size_t step = 0;
  for (std::size_t k = top; k >= 2; --k) {
    for (std::uint32_t i : of_dim[k]) {
      call_poll(++step);
      if (cleared[i])
        continue;
      column.assign(complex.facets_begin(i), complex.facets_end(i));
      std::sort(column.begin(), column.end());
      while (!column.empty()) {
        const auto [begin, end] = reduced.with_low(column.back());
        if (begin == end)
          break;
        sum.clear();
        std::set_symmetric_difference(column.begin(), column.end(), begin, end, std::back_inserter(sum));
        column.swap(sum);
      }
      if (!column.empty()) {
        cleared[column.back()] = 1;
        reduced.add(column);
        ++rank[k];
      }
    }
  }

  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::uint32_t{0});
  std::size_t components = f[0];
  if (top >= 1)
    for (std::uint32_t e : of_dim[1]) {
      call_poll(++step);
      const std::uint32_t a = find_root(parent, complex.facets_begin(e)[0]);
      const std::uint32_t b = find_root(parent, complex.facets_begin(e)[1]);
      if (a != b) {
        parent[a] = b;
        --components;
      }
    }
  rank[1] = f[0] - components;

  std::vector<std::size_t> betti(top + 1, 0);
  for (std::size_t k = 0; k <= top; ++k) {
    if (rank[k] + rank[k + 1] > f[k])
      throw InternalError("betti numbers: the ranks of the boundary maps around dimension " +
                          std::to_string(k) + " exceed the " + std::to_string(f[k]) + " elements");
    betti[k] = f[k] - rank[k] - rank[k + 1];
  }
  return betti;
}

} // namespace medusa
