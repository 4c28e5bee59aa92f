// Betti numbers over Z/2 of a finite complex given by facet lists (docs/MATH.md §6.6, §7.5). Written here
// because libmedusa must not depend on PHAT (docs/CONVENTIONS.md); it is also the oracle that the PHAT
// paths of libpersistence are tested against.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <vector>

namespace medusa {

// A complex as columns, stored flat: element i has dimension dims[i] and the facets
// facets[starts[i] .. starts[i + 1]) (each of dimension dims[i] - 1; none for vertices). Every facet
// index must be a valid element.
class ChainComplex {
public:
  template <class It> void add(int dim, It first, It last) {
    dims_.push_back(dim);
    for (; first != last; ++first)
      facets_.push_back(static_cast<std::uint32_t>(*first));
    starts_.push_back(facets_.size());
  }
  template <class Range> void add(int dim, const Range& facet_indices) {
    add(dim, std::begin(facet_indices), std::end(facet_indices));
  }
  void reserve(std::size_t elements, std::size_t facet_entries) {
    dims_.reserve(elements);
    starts_.reserve(elements + 1);
    facets_.reserve(facet_entries);
  }
  std::size_t size() const { return dims_.size(); }
  int dim(std::size_t i) const { return dims_[i]; }
  const std::uint32_t* facets_begin(std::size_t i) const { return facets_.data() + starts_[i]; }
  const std::uint32_t* facets_end(std::size_t i) const { return facets_.data() + starts_[i + 1]; }
  std::size_t facet_count(std::size_t i) const { return starts_[i + 1] - starts_[i]; }

private:
  std::vector<int> dims_;
  std::vector<std::size_t> starts_{0};
  std::vector<std::uint32_t> facets_;
};

// beta_k for k = 0 .. max dimension (empty for an empty complex): beta_k = f_k - rank d_k -
// rank d_{k+1}, with rank d_1 from a union-find on the edges and the higher ranks by column
// reduction with clearing (docs/MATH.md §7.5). `poll` is called every few thousand columns, so a caller
// can stop a long computation by throwing from it. Throws InternalError for a malformed complex or
// more than 2^32 - 1 elements.
std::vector<std::size_t> betti_numbers(const ChainComplex& complex, const std::function<void()>& poll = {});

} // namespace medusa
