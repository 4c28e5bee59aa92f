#include "medusa/persistence/open_classes.h"

#include "medusa/core/error.h"
#include "medusa/persistence/boundary_matrix.h"

#include <algorithm>
#include <string>
#include <tuple>

namespace medusa::persistence {

std::array<std::size_t, 3> end_classes_beyond_first(const std::vector<medusa::Cell>& cells,
                                                    const std::vector<char>& member,
                                                    std::uint64_t first_batch, std::uint64_t end_batch,
                                                    const std::function<void()>& poll) {
  if (!member.empty() && member.size() != cells.size())
    throw InternalError("open classes: membership of " + std::to_string(member.size()) + " cells for " +
                        std::to_string(cells.size()));
  // Degrees 1 and 2 only need cells up to dimension 3 (homology in degree k depends on the
  // (k+1)-skeleton), so the cone is taken on cells up to dimension 2.
  constexpr int top = 3;
  std::vector<std::size_t> end_part, rest, first_part;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const medusa::Cell& c = cells[i];
    if (c.id != i)
      throw InternalError("open classes: cell at position " + std::to_string(i) + " has id " +
                          std::to_string(c.id));
    if ((!member.empty() && !member[i]) || c.dim() > top)
      continue;
    (c.death.batch >= end_batch ? end_part : rest).push_back(i);
    if (c.birth.batch <= first_batch && c.dim() < top)
      first_part.push_back(i);
  }
  // docs/MATH.md §7.12: L_end first, the rest of M after it, the apex w, then the cone w*c of every
  // cell c of L_first. Within each part by dimension: a facet of an L_end cell dies no earlier, so it
  // is in L_end; a facet of an L_first cell is born no earlier, so its cone is there too.
  const auto by_dim = [&](std::size_t a, std::size_t b) {
    return std::make_tuple(cells[a].dim(), a) < std::make_tuple(cells[b].dim(), b);
  };
  std::sort(end_part.begin(), end_part.end(), by_dim);
  std::sort(rest.begin(), rest.end(), by_dim);
  std::sort(first_part.begin(), first_part.end(), by_dim);

  constexpr std::int64_t absent = -1;
  std::vector<std::int64_t> index(cells.size(), absent), cone(cells.size(), absent);
  Filtration f;
  std::vector<std::int64_t> col;
  // Column `at` is appended when it is complete (`col`), in filtration order.
  check_filtration_size(end_part.size() + rest.size() + 1 + first_part.size(), cells.size());
  const auto add = [&](std::size_t cell, int dim) {
    f.cells.push_back(static_cast<FiltrationIndex>(cell));
    f.dims.push_back(static_cast<std::int8_t>(dim));
    col.clear();
    return static_cast<std::int64_t>(f.cells.size() - 1);
  };
  const auto check = [&](std::int64_t row, std::int64_t at, const medusa::Cell& c) {
    if (row == absent || row >= at)
      throw InternalError("open classes: a facet of cell " + std::to_string(c.id) +
                          " is missing or does not precede it");
    return row;
  };
  for (const std::vector<std::size_t>* part : {&end_part, &rest})
    for (std::size_t i : *part) {
      const medusa::Cell& c = cells[i];
      const std::int64_t at = add(i, c.dim());
      index[i] = at;
      for (medusa::CellId facet : c.facets)
        col.push_back(check(facet < cells.size() ? index[facet] : absent, at, c));
      std::sort(col.begin(), col.end());
      f.columns.push_back(col);
    }
  const std::int64_t apex = add(cells.size(), 0); // no cell of the medusa
  f.columns.push_back(col);
  for (std::size_t i : first_part) {
    const medusa::Cell& c = cells[i];
    const std::int64_t at = add(i, c.dim() + 1);
    cone[i] = at;
    col.push_back(check(index[i], at, c));
    if (c.facets.empty())
      col.push_back(apex);
    for (medusa::CellId facet : c.facets)
      col.push_back(check(facet < cells.size() ? cone[facet] : absent, at, c));
    std::sort(col.begin(), col.end());
    f.columns.push_back(col);
  }

  // An essential class of degree k born at an index inside L_end is a class of L_end whose image in
  // H_k(M ∪ w*L_first) = H_k(M, L_first) is not zero; their number is the rank of the map.
  std::vector<char> paired(f.size(), 0);
  for (const IndexPair& p : reduce(f, poll)) {
    paired[static_cast<std::size_t>(p.first)] = 1;
    paired[static_cast<std::size_t>(p.second)] = 1;
  }
  std::array<std::size_t, 3> rank{};
  for (std::size_t j = 0; j < end_part.size(); ++j)
    if (!paired[j] && f.dims[j] >= 1 && f.dims[j] <= 2)
      ++rank[static_cast<std::size_t>(f.dims[j])];
  return rank;
}

namespace {

void check_pair_of_diagrams(const Diagram& forward, const Diagram& reverse) {
  if (forward.direction != Direction::forward || reverse.direction != Direction::reverse ||
      forward.cell_type != reverse.cell_type)
    throw InternalError("hole fates: needs the forward and reverse diagrams of one sub-medusa");
}

} // namespace

std::array<HoleFates, 3> hole_fates(const std::vector<medusa::Cell>& cells, const std::vector<char>& member,
                                    const Diagram& forward, const Diagram& reverse, std::uint64_t first_batch,
                                    std::uint64_t end_batch, const std::function<void()>& poll) {
  check_pair_of_diagrams(forward, reverse); // before the reduction, which is the long part
  return hole_fates(forward, reverse, first_batch, end_batch,
                    end_classes_beyond_first(cells, member, first_batch, end_batch, poll));
}

std::array<HoleFates, 3> hole_fates(const Diagram& forward, const Diagram& reverse, std::uint64_t first_batch,
                                    std::uint64_t end_batch, const std::array<std::size_t, 3>& beyond) {
  check_pair_of_diagrams(forward, reverse);
  std::array<HoleFates, 3> fates;
  for (const PersistencePair& p : forward.pairs) {
    if (p.zero_length || p.dim < 1 || p.dim > 2)
      continue;
    HoleFates& h = fates[static_cast<std::size_t>(p.dim)];
    const bool initial = p.birth_time.batch <= first_batch;
    if (p.essential)
      (initial ? h.never_filled_initial : h.never_filled_formed) += 1;
    else
      (initial ? h.filled_initial : h.filled_formed) += 1;
  }
  // The reverse filtration starts with L_end, the cells dying at the final batch: its essential
  // classes born there span B, the image of H_k(L_end) in H_k(M) (docs/MATH.md §7.3, §7.12).
  std::array<std::size_t, 3> carried{};
  for (const PersistencePair& p : reverse.pairs)
    if (p.essential && p.dim >= 1 && p.dim <= 2 && p.birth_time.batch >= end_batch)
      ++carried[static_cast<std::size_t>(p.dim)];
  for (std::size_t k = 1; k <= 2; ++k) {
    HoleFates& h = fates[k];
    // dim(A ∩ B) = dim B - rank(H_k(L_end) -> H_k(M, L_first)); B / (A ∩ B) embeds in H_k(M) / A.
    if (beyond[k] > carried[k] || beyond[k] > h.never_filled_formed ||
        carried[k] - beyond[k] > h.never_filled_initial)
      throw InternalError("hole fates: degree " + std::to_string(k) + " has " +
                          std::to_string(h.never_filled_initial) + " + " +
                          std::to_string(h.never_filled_formed) + " never-filled classes, " +
                          std::to_string(carried[k]) + " carried by the end complex and " +
                          std::to_string(beyond[k]) + " of those beyond the first frame's");
    h.still_open_formed = beyond[k];
    h.still_open_initial = carried[k] - beyond[k];
    h.broken_open_initial = h.never_filled_initial - h.still_open_initial;
    h.broken_open_formed = h.never_filled_formed - h.still_open_formed;
  }
  return fates;
}

} // namespace medusa::persistence
