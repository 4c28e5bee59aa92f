// Betti numbers over Z/2 of a finite complex given by facet lists (docs/MATH.md §6.6, §7.5). Written here
// because libmedusa must not depend on PHAT (docs/CONVENTIONS.md).
#pragma once

#include <cstddef>
#include <vector>

namespace medusa {

// A complex as columns: dims[i] is the dimension of element i, facets[i] the indices of its facets
// (each of dimension dims[i] - 1; empty for vertices). Every facet index must be a valid element.
struct ChainComplex {
  std::vector<int> dims;
  std::vector<std::vector<std::size_t>> facets;
};

// beta_k for k = 0 .. max dimension (empty for an empty complex). beta_0 by union-find on the edges;
// higher degrees by ranks of the boundary matrices over Z/2 (column reduction with clearing, 7.5):
// beta_k = f_k - rank d_k - rank d_{k+1}.
std::vector<std::size_t> betti_numbers(const ChainComplex& complex);

} // namespace medusa
