// Forward and reverse time filtrations of the alpha medusa and of its sub-medusas per cell type
// (docs/MATH.md §7.2-§7.4), with the boundary columns in filtration order (docs/MATH.md §7.5).
#pragma once

#include "medusa/medusa/cell.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace medusa::persistence {

enum class Direction : std::uint8_t {
  forward = 0, // sublevel sets of time: (birth batch, birth rank, dim, vertices) (docs/MATH.md §7.2)
  reverse = 1  // superlevel sets: (-death batch, -death rank, dim, vertices) (docs/MATH.md §7.3)
};

// Cell type value meaning "the whole medusa", not a sub-medusa M_X.
constexpr int all_types = -1;

// A filtration over a cell vector: entry j is the j-th cell in filtration order. It refers to the
// cell vector it was built from by position, so keep that vector alive and unchanged.
struct Filtration {
  Direction direction = Direction::forward;
  int cell_type = all_types;      // X for M_X (docs/MATH.md §7.4), all_types for M
  std::vector<std::size_t> cells; // position in the input cell vector, per filtration index
  std::vector<int> dims;          // medusa dimension (vertices - 1, docs/MATH.md §6.1) per filtration index
  std::vector<std::vector<std::int64_t>> columns; // facet filtration indices, ascending (docs/MATH.md §7.5)

  std::size_t size() const { return cells.size(); }
};

// The filtration of the whole medusa. Throws InputError for duplicate cell ids or unknown facet ids,
// InternalError when a facet does not precede its coface or is not a facet of it.
Filtration make_filtration(const std::vector<medusa::Cell>& cells, Direction direction);

// The filtration of the sub-medusa M_X: cells all of whose vertices have type X, where
// vertex_type[v] is the type of vertex v; re-indexed consecutively in the inherited order (docs/MATH.md
// §7.4). Throws InputError for a vertex outside the type table.
Filtration make_type_filtration(const std::vector<medusa::Cell>& cells, const std::vector<int>& vertex_type,
                                int type, Direction direction);

} // namespace medusa::persistence
