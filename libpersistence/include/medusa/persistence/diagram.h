// Persistence diagrams of a time filtration: finite pairs from PHAT plus the essential classes, each
// point with its times and the cells that created and killed it (docs/MATH.md §7.3, §7.5).
#pragma once

#include "medusa/medusa/cell.h"
#include "medusa/persistence/boundary_matrix.h"
#include "medusa/persistence/filtration.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace medusa::persistence {

// One point of a diagram. Times are filtration values: the real birth time of a cell in the forward
// filtration (t_birth <= t_death), its real death time in the reverse one (t_birth >= t_death).
// The degree sits beside the two flags: a diagram holds one pair per cell of a large medusa, and
// this order saves the padding of 8 bytes a pair.
struct PersistencePair {
  double birth = 0; // filtration value of the birth cell
  double death = 0; // filtration value of the death cell; +inf (forward) / -inf (reverse) if essential
  medusa::VirtualTime birth_time; // virtual filtration time of the birth cell
  medusa::VirtualTime death_time; // virtual filtration time of the death cell (default if essential)
  std::int64_t birth_index = 0;   // filtration indices
  std::int64_t death_index = -1;  // -1 if essential
  medusa::CellId birth_cell = 0;  // the cells that formed and killed the class
  medusa::CellId death_cell = 0;  // 0 if essential
  // Positions of those cells in the cell vector the diagram was built from (their vertices are
  // looked up there, see birth_vertices(): a diagram holds one point per cell of a large medusa, so
  // it does not copy vertex tuples). death_position is unused if essential. 32 bits, as a medusa
  // holds at most max_cell_count cells.
  std::uint32_t birth_position = 0;
  std::uint32_t death_position = 0;
  int dim = 0;              // homology degree = dimension of the birth cell (docs/MATH.md §7.5)
  bool essential = false;   // never killed: a class of the whole (sub-)medusa
  bool zero_length = false; // birth and death in the same batch (docs/MATH.md §7.5), on the diagonal
};
static_assert(sizeof(PersistencePair) <= 96, "PersistencePair grew: a diagram holds one per cell");

// All points of one filtration, sorted by (dim, birth_index). Degrees above 3 only hold zero-length
// pairs for a valid medusa (docs/MATH.md §7.6) and are kept as they come.
struct Diagram {
  Direction direction = Direction::forward;
  int cell_type = all_types;
  std::vector<PersistencePair> pairs;
};

// Builds the diagram from the finite index pairs of `reduce`: adds every positive column that appears
// in no pair as an essential class, and flags zero-length pairs by batch index (never by doubles).
Diagram make_diagram(const std::vector<medusa::Cell>& cells, const Filtration& filtration,
                     const std::vector<IndexPair>& pairs);

// Reduces the filtration with PHAT and builds its diagram.
template <class Representation = compact_pivot_column, class Algorithm = phat::twist_reduction>
Diagram compute_diagram(const std::vector<medusa::Cell>& cells, const Filtration& filtration) {
  return make_diagram(cells, filtration, reduce<Representation, Algorithm>(filtration));
}

// The same diagram by PolledTwistReduction: `poll` is called every few thousand columns, so a caller can
// stop a long reduction by throwing.
inline Diagram compute_diagram(const std::vector<medusa::Cell>& cells, const Filtration& filtration,
                               const std::function<void()>& poll) {
  return make_diagram(cells, filtration, reduce(filtration, poll));
}

// The vertices of the cells that formed and killed the class, from the cell vector the diagram was
// built from; death_vertices is empty for an essential class. InternalError when the position is
// outside `cells` (a diagram paired with another cell vector).
const medusa::CellVertices& birth_vertices(const PersistencePair& p, const std::vector<medusa::Cell>& cells);
const medusa::CellVertices& death_vertices(const PersistencePair& p, const std::vector<medusa::Cell>& cells);

// The points of degree k; zero-length pairs only when asked for.
std::vector<PersistencePair> pairs_in_dimension(const Diagram& diagram, int k, bool keep_zero_length = false);

// The diagram without its zero-length pairs.
Diagram without_zero_length(const Diagram& diagram);
// The same in place, its memory returned: most pairs of a large medusa are zero-length, and its
// diagrams are among the largest structures after the kinetic stage.
void drop_zero_length(Diagram& diagram);

} // namespace medusa::persistence
