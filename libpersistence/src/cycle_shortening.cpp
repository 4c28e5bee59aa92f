#include "cycle_shortening.h"

#include <algorithm>
#include <unordered_set>

namespace medusa::persistence::detail {

Cofaces::Cofaces(const Filtration& f, int max_dim) : offsets_(f.size() + 1, 0) {
  const auto wanted = [&](std::size_t j) { return f.dims[j] >= 2 && f.dims[j] <= max_dim + 1; };
  for (std::size_t j = 0; j < f.size(); ++j)
    if (wanted(j))
      for (std::int64_t face : f.columns[j])
        ++offsets_[static_cast<std::size_t>(face) + 1];
  for (std::size_t j = 0; j < f.size(); ++j)
    offsets_[j + 1] += offsets_[j];
  entries_.resize(offsets_.back());
  std::vector<std::size_t> next(offsets_.begin(), offsets_.end() - 1);
  // Cofaces are appended in increasing filtration index, so each row comes out ascending.
  for (std::size_t j = 0; j < f.size(); ++j)
    if (wanted(j))
      for (std::int64_t face : f.columns[j])
        entries_[next[static_cast<std::size_t>(face)]++] = static_cast<std::int64_t>(j);
}

void shorten_cycle(const Filtration& f, const Cofaces& cofaces, std::int64_t limit,
                   std::vector<std::int64_t>& z) {
  if (z.size() < 2)
    return;
  const std::int64_t birth = z.back();
  std::unordered_set<std::int64_t> in(z.begin(), z.end());
  // Each step removes at least one cell, so there are at most |z| of them; a pass visits the cofaces
  // of the cells present, in filtration order, so the result does not depend on hashing.
  for (bool shortened = true; shortened;) {
    shortened = false;
    std::vector<std::int64_t> current(in.begin(), in.end());
    std::sort(current.begin(), current.end());
    for (std::int64_t cell : current) {
      for (const std::int64_t* s = cofaces.begin(cell); s != cofaces.end(cell) && in.count(cell) != 0; ++s) {
        if (*s >= limit)
          break;
        const BoundaryColumns::Column faces = f.columns[static_cast<std::size_t>(*s)];
        // Facets all before the birth cell: the sum stays in K_b and keeps b (docs/MATH.md §7.13).
        if (faces.back() >= birth)
          continue;
        const auto shared = static_cast<std::size_t>(
            std::count_if(faces.begin(), faces.end(), [&](std::int64_t x) { return in.count(x) != 0; }));
        if (2 * shared <= faces.size())
          continue;
        for (std::int64_t x : faces)
          if (in.erase(x) == 0)
            in.insert(x);
        shortened = true;
      }
    }
  }
  z.assign(in.begin(), in.end());
  std::sort(z.begin(), z.end());
}

} // namespace medusa::persistence::detail
