#include "medusa/persistence/filtration.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

namespace medusa::persistence {
namespace {

using medusa::Cell;

std::string cell_name(const Cell& c) { return "cell " + std::to_string(c.id); }

// The order of docs/MATH.md §7.2 (forward: birth batch, birth rank, dimension, vertex tuple) or 7.3
// (reverse: latest death first), without the vertex tuple, packed so that sorting reads the cells
// only on ties: cells are large and scattered in memory, and reading them in every comparison was
// most of the time of make_filtration.
struct SortKey {
  std::uint64_t batch = 0; // birth batch, or the complement of the death batch (reverse)
  std::uint32_t rank = 0;  // likewise for the rank within the batch
  int dim = 0;
  FiltrationIndex position = 0; // in the cell vector

  bool same_time_and_dim(const SortKey& o) const {
    return batch == o.batch && rank == o.rank && dim == o.dim;
  }
  bool before(const SortKey& o) const {
    return std::tie(batch, rank, dim) < std::tie(o.batch, o.rank, o.dim);
  }
};

SortKey sort_key(const Cell& c, FiltrationIndex position, Direction direction) {
  SortKey k;
  if (direction == Direction::forward) {
    k.batch = c.birth.batch;
    k.rank = c.birth.rank;
  } else {
    k.batch = std::numeric_limits<std::uint64_t>::max() - c.death.batch;
    k.rank = std::numeric_limits<std::uint32_t>::max() - c.death.rank;
  }
  k.dim = c.dim();
  k.position = position;
  return k;
}

// `selected` holds positions in `cells`, whose size the callers have checked (check_filtration_size).
Filtration build(const std::vector<Cell>& cells, std::vector<FiltrationIndex> selected, Direction direction,
                 int cell_type) {
  // Cells read from a store have ids 0..N-1 in order (libmedusa's Medusa::cells): then an id is its
  // position and the facet lookups need no hash table, which dominated the cost of this function.
  bool ids_are_positions = true;
  for (std::size_t i = 0; i < cells.size() && ids_are_positions; ++i)
    ids_are_positions = cells[i].id == i;
  std::unordered_map<medusa::CellId, std::size_t> position;
  if (!ids_are_positions) {
    position.reserve(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (!position.emplace(cells[i].id, i).second)
        throw InputError("filtration: duplicate " + cell_name(cells[i]));
  }
  const std::size_t unknown = cells.size();
  const auto locate = [&](medusa::CellId id) {
    if (ids_are_positions)
      return id < cells.size() ? static_cast<std::size_t>(id) : unknown;
    const auto it = position.find(id);
    return it == position.end() ? unknown : it->second;
  };

  std::vector<SortKey> keys;
  keys.reserve(selected.size());
  for (FiltrationIndex i : selected)
    keys.push_back(sort_key(cells[i], i, direction));
  std::sort(keys.begin(), keys.end(), [&](const SortKey& a, const SortKey& b) {
    if (!a.same_time_and_dim(b))
      return a.before(b);
    return cells[a.position].vertices < cells[b.position].vertices;
  });
  // The key is a total order on a valid medusa (docs/MATH.md §7.2): equal keys mean one simplex with two
  // overlapping lifetimes.
  for (std::size_t j = 1; j < keys.size(); ++j)
    if (keys[j - 1].same_time_and_dim(keys[j]) &&
        cells[keys[j - 1].position].vertices == cells[keys[j].position].vertices)
      throw InternalError("filtration: " + cell_name(cells[keys[j].position]) + " has the same key as " +
                          cell_name(cells[keys[j - 1].position]));
  for (std::size_t j = 0; j < keys.size(); ++j)
    selected[j] = keys[j].position;
  // The keys go before the columns come: at a million cells they are half a gigabyte.
  std::vector<SortKey>().swap(keys);

  constexpr FiltrationIndex none = UINT32_MAX;
  std::vector<FiltrationIndex> index_of(cells.size(), none);
  for (std::size_t j = 0; j < selected.size(); ++j)
    index_of[selected[j]] = static_cast<FiltrationIndex>(j);

  Filtration f;
  f.direction = direction;
  f.cell_type = cell_type;
  f.cells = std::move(selected);
  f.dims.resize(f.cells.size());
  std::size_t entries = 0;
  for (FiltrationIndex position : f.cells)
    entries += cells[position].facets.size();
  f.columns.reserve(f.cells.size(), entries);
  std::vector<std::int64_t> column;
  for (std::size_t j = 0; j < f.cells.size(); ++j) {
    const Cell& c = cells[f.cells[j]];
    f.dims[j] = static_cast<std::int8_t>(c.dim());
    const std::size_t expected = c.dim() >= 1 ? c.vertices.size() : 0;
    if (c.facets.size() != expected)
      throw InternalError("filtration: " + cell_name(c) + " has " + std::to_string(c.facets.size()) +
                          " facets, expected " + std::to_string(expected));
    column.clear();
    for (medusa::CellId facet_id : c.facets) {
      const std::size_t at = locate(facet_id);
      if (at == unknown)
        throw InputError("filtration: " + cell_name(c) + " names unknown facet cell " +
                         std::to_string(facet_id));
      const Cell& facet = cells[at];
      if (facet.vertices.size() + 1 != c.vertices.size() ||
          !std::includes(c.vertices.begin(), c.vertices.end(), facet.vertices.begin(), facet.vertices.end()))
        throw InternalError("filtration: " + cell_name(facet) + " is not a facet of " + cell_name(c));
      const FiltrationIndex row = index_of[at];
      // A face of a type-X cell is type-X, so a missing row is a broken sub-medusa (docs/MATH.md §7.4).
      if (row == none || row >= j)
        throw InternalError("filtration: facet " + cell_name(facet) + " does not precede its coface " +
                            cell_name(c));
      column.push_back(row);
    }
    std::sort(column.begin(), column.end());
    if (std::adjacent_find(column.begin(), column.end()) != column.end())
      throw InternalError("filtration: " + cell_name(c) + " lists a facet twice");
    f.columns.push_back(column);
  }
  return f;
}

} // namespace

void check_filtration_size(std::size_t filtration_size, std::size_t cell_count) {
  if (filtration_size > max_filtration_size || cell_count > max_filtration_size)
    throw InputError("filtration: " + std::to_string(std::max(filtration_size, cell_count)) +
                     " cells; a filtration takes at most " + std::to_string(max_filtration_size));
}

void BoundaryColumns::push_back(const std::vector<std::int64_t>& column) {
  for (std::int64_t row : column)
    if (row < 0 || static_cast<std::uint64_t>(row) >= max_filtration_size)
      throw InternalError("filtration: boundary entry " + std::to_string(row) + " is no filtration index");
  entries_.insert(entries_.end(), column.begin(), column.end());
  offsets_.push_back(entries_.size());
}

Filtration make_filtration(const std::vector<Cell>& cells, Direction direction) {
  check_filtration_size(cells.size(), cells.size());
  std::vector<FiltrationIndex> all(cells.size());
  std::iota(all.begin(), all.end(), FiltrationIndex{0});
  return build(cells, std::move(all), direction, all_types);
}

Filtration make_type_filtration(const std::vector<Cell>& cells, const std::vector<int>& vertex_type, int type,
                                Direction direction) {
  check_filtration_size(cells.size(), cells.size());
  std::vector<FiltrationIndex> selected;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    bool all_x = true;
    for (kinetic::VertexId v : cells[i].vertices) {
      if (v < 0 || static_cast<std::size_t>(v) >= vertex_type.size())
        throw InputError("filtration: " + cell_name(cells[i]) + " has vertex " + std::to_string(v) +
                         " outside the type table of " + std::to_string(vertex_type.size()) + " vertices");
      all_x = all_x && vertex_type[static_cast<std::size_t>(v)] == type;
    }
    if (all_x)
      selected.push_back(static_cast<FiltrationIndex>(i));
  }
  return build(cells, std::move(selected), direction, type);
}

} // namespace medusa::persistence
