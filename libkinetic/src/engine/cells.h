// Look-ups in the triangulation by vertex ids. The engine reaches a facet's cells from its
// certificate (Certificate::cell) and a change's cells from the change; where it holds only a
// simplex (a face of K, the static changes' bookkeeping), a cell holding it is found among the last
// change's cells, or by a walk round one of its vertices (cell_triangulation.h).
#pragma once

#include "engine.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

// A flip makes at most three cells, a local change a few dozen: up to this many are scanned, more
// (a static change's) are not.
constexpr std::size_t max_scanned_created = 8;

template <class K> CellIndex Engine<K>::cell_holding(const Simplex& s) const {
  if (created_cells.size() <= max_scanned_created)
    for (CellIndex c : created_cells)
      if (cells.holds(c, s))
        return c;
  return cells.cell_containing(s);
}

template <class K> CellIndex Engine<K>::cell_holding(const Simplex& s, Face& state) const {
  if (cells.holds(state.cell, s))
    return state.cell;
  state.cell = cell_holding(s);
  return state.cell;
}

template <class K> std::pair<CellIndex, int> Engine<K>::facet_owner(CellIndex c, int i) const {
  const int id = cells.cert(c, i);
  if (id < 0)
    return {c, i}; // a facet a change made, installed from its own cells (install_touched_facets)
  const Certificate& x = certificates[id];
  if (x.cell == c && x.facet_index == i)
    return {c, i};
  if (x.cell == cells.neighbor(c, i) && x.facet_index == cells.mirror_index(c, i))
    return {x.cell, x.facet_index};
  std::ostringstream os;
  os << "the certificate of facet " << cells.facet(c, i) << " names neither of its cells";
  throw InternalError(os.str());
}

template <class K> std::vector<Simplex> Engine<K>::sort_by_top(std::vector<CellIndex>& held) const {
  std::vector<std::pair<Simplex, CellIndex>> pairs;
  pairs.reserve(held.size());
  for (CellIndex c : held)
    pairs.emplace_back(cells.top(c), c);
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Simplex> tops;
  tops.reserve(held.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    tops.push_back(pairs[k].first);
    held[k] = pairs[k].second;
  }
  return tops;
}

template <class K> VertexId Engine<K>::other_apex(const Simplex& f, VertexId apex) const {
  const CellIndex c = cells.find(f.with(apex));
  if (c == no_cell) {
    std::ostringstream os;
    os << "facet " << f << " has no top simplex with apex " << apex;
    throw InternalError(os.str());
  }
  return cells.apex_across(c, cells.index_of(c, apex));
}

template <class K>
void Engine<K>::finite_cofaces(const Simplex& s, Face& state, std::vector<Simplex>& out) const {
  if (const CellIndex start = cell_holding(s, state); start != no_cell)
    cells.finite_cofaces_from(start, s, out);
  else
    out.clear();
}

} // namespace medusa::kinetic::detail
