// Greedy shortening of class representatives by boundaries of the filtration (docs/MATH.md §7.13).
#pragma once

#include "medusa/persistence/filtration.h"

#include <cstdint>
#include <vector>

namespace medusa::persistence::detail {

// The cofaces of the cells of dimension 1..max_dim of a filtration, among the cells one dimension
// higher, ascending in filtration order (compressed rows).
class Cofaces {
public:
  Cofaces(const Filtration& f, int max_dim);
  // Cofaces of filtration index j: [begin, end).
  const std::int64_t* begin(std::int64_t j) const {
    return entries_.data() + offsets_[static_cast<std::size_t>(j)];
  }
  const std::int64_t* end(std::int64_t j) const {
    return entries_.data() + offsets_[static_cast<std::size_t>(j) + 1];
  }

private:
  std::vector<std::size_t> offsets_;
  std::vector<std::int64_t> entries_;
};

// Shortens the cycle z (filtration indices ascending, its last entry b its birth cell) in place: adds
// the boundary of a cell s of one dimension more, entered before `limit`, all of whose facets enter
// before b, whenever that removes more cells of z than it adds; repeats until no such cell is left.
// `limit` is the death index of a finite pair and the filtration's size for an essential class. The
// result is homologous to z in K_{limit-1}, still a cycle ending at b, and never longer; not
// necessarily the shortest such cycle (docs/MATH.md §7.13).
void shorten_cycle(const Filtration& f, const Cofaces& cofaces, std::int64_t limit,
                   std::vector<std::int64_t>& z);

} // namespace medusa::persistence::detail
