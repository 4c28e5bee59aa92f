#include "medusa/persistence/filtration.h"

#include "medusa/kinetic/error.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

namespace medusa::persistence {
namespace {

using complex::Cell;

std::string cell_name(const Cell& c) { return "cell " + std::to_string(c.id); }

// Strict order of MATH.md 7.2 (forward) or 7.3 (reverse) on two cells.
bool precedes(const Cell& a, const Cell& b, Direction direction) {
  if (direction == Direction::forward) {
    if (a.birth != b.birth)
      return a.birth < b.birth;
  } else if (a.death != b.death) {
    return b.death < a.death;
  }
  if (a.dim() != b.dim())
    return a.dim() < b.dim();
  return a.vertices < b.vertices;
}

Filtration build(const std::vector<Cell>& cells, std::vector<std::size_t> selected, Direction direction,
                 int cell_type) {
  // Cells read from a store have ids 0..N-1 in order (libmedusa's Medusa::cells): then an id is its
  // position and the facet lookups need no hash table, which dominated the cost of this function.
  bool ids_are_positions = true;
  for (std::size_t i = 0; i < cells.size() && ids_are_positions; ++i)
    ids_are_positions = cells[i].id == i;
  std::unordered_map<complex::CellId, std::size_t> position;
  if (!ids_are_positions) {
    position.reserve(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (!position.emplace(cells[i].id, i).second)
        throw InputError("filtration: duplicate " + cell_name(cells[i]));
  }
  const std::size_t unknown = cells.size();
  const auto locate = [&](complex::CellId id) {
    if (ids_are_positions)
      return id < cells.size() ? static_cast<std::size_t>(id) : unknown;
    const auto it = position.find(id);
    return it == position.end() ? unknown : it->second;
  };

  std::sort(selected.begin(), selected.end(),
            [&](std::size_t a, std::size_t b) { return precedes(cells[a], cells[b], direction); });
  // The key is a total order on a valid medusa (MATH.md 7.2): equal keys mean one simplex with two
  // overlapping lifetimes.
  for (std::size_t j = 1; j < selected.size(); ++j)
    if (!precedes(cells[selected[j - 1]], cells[selected[j]], direction))
      throw InternalError("filtration: " + cell_name(cells[selected[j]]) + " has the same key as " +
                          cell_name(cells[selected[j - 1]]));

  std::vector<std::int64_t> index_of(cells.size(), -1);
  for (std::size_t j = 0; j < selected.size(); ++j)
    index_of[selected[j]] = static_cast<std::int64_t>(j);

  Filtration f;
  f.direction = direction;
  f.cell_type = cell_type;
  f.cells = std::move(selected);
  f.dims.resize(f.cells.size());
  f.columns.resize(f.cells.size());
  for (std::size_t j = 0; j < f.cells.size(); ++j) {
    const Cell& c = cells[f.cells[j]];
    f.dims[j] = c.dim();
    const std::size_t expected = c.dim() >= 1 ? c.vertices.size() : 0;
    if (c.facets.size() != expected)
      throw InternalError("filtration: " + cell_name(c) + " has " + std::to_string(c.facets.size()) +
                          " facets, expected " + std::to_string(expected));
    auto& column = f.columns[j];
    column.reserve(c.facets.size());
    for (complex::CellId facet_id : c.facets) {
      const std::size_t at = locate(facet_id);
      if (at == unknown)
        throw InputError("filtration: " + cell_name(c) + " names unknown facet cell " +
                         std::to_string(facet_id));
      const Cell& facet = cells[at];
      if (facet.vertices.size() + 1 != c.vertices.size() ||
          !std::includes(c.vertices.begin(), c.vertices.end(), facet.vertices.begin(), facet.vertices.end()))
        throw InternalError("filtration: " + cell_name(facet) + " is not a facet of " + cell_name(c));
      const std::int64_t row = index_of[at];
      // A face of a type-X cell is type-X, so a missing row is a broken sub-medusa (MATH.md 7.4).
      if (row < 0 || row >= static_cast<std::int64_t>(j))
        throw InternalError("filtration: facet " + cell_name(facet) + " does not precede its coface " +
                            cell_name(c));
      column.push_back(row);
    }
    std::sort(column.begin(), column.end());
    if (std::adjacent_find(column.begin(), column.end()) != column.end())
      throw InternalError("filtration: " + cell_name(c) + " lists a facet twice");
  }
  return f;
}

} // namespace

Filtration make_filtration(const std::vector<Cell>& cells, Direction direction) {
  std::vector<std::size_t> all(cells.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return build(cells, std::move(all), direction, all_types);
}

Filtration make_type_filtration(const std::vector<Cell>& cells, const std::vector<int>& vertex_type, int type,
                                Direction direction) {
  std::vector<std::size_t> selected;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    bool all_x = true;
    for (kinetic::VertexId v : cells[i].vertices) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_type.size())
        throw InputError("filtration: " + cell_name(cells[i]) + " has vertex " + std::to_string(v) +
                         " outside the type table of " + std::to_string(vertex_type.size()) + " vertices");
      all_x = all_x && vertex_type[static_cast<std::size_t>(v)] == type;
    }
    if (all_x)
      selected.push_back(i);
  }
  return build(cells, std::move(selected), direction, type);
}

} // namespace medusa::persistence
