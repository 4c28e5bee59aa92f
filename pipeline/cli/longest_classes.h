// The longest-lived filled loop and cavity of the whole medusa and of each cell type, with the
// CompuCell3D cells of their representatives (docs/MATH.md §7.11), for the summary of `medusa run`.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/representatives.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace medusa::cli {

struct LongestFilled {
  int cell_type = persistence::all_types;
  int dim = 1;        // 1 loop, 2 cavity
  std::size_t id = 0; // the class id of `medusa classes` (its row in the stored diagram)
  double birth = 0, death = 0;
  std::vector<std::int64_t> cells; // CC3D ids of the representative, sorted
};

// For a forward diagram and k = 1, 2: among its finite positive-length pairs of degree k with a
// representative in `classes` (rows into the pairs as stored, zero-length pairs included), the one of
// largest lifetime |death - birth|, the first in diagram order among equal ones: the top row of
// `medusa classes --dim k --sort lifetime` among finite classes. None for a degree without a filled
// class, nothing for a reverse diagram.
std::vector<LongestFilled> longest_filled_classes(const medusa::Medusa& medusa,
                                                  const persistence::Diagram& diagram,
                                                  const persistence::ClassRepresentatives& classes);

} // namespace medusa::cli
