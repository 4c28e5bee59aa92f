#include "medusa/persistence/degree_check.h"

#include "medusa/core/error.h"

#include <string>

namespace medusa::persistence {

void check_homology_degrees(const Diagram& diagram) {
  for (const auto& p : diagram.pairs)
    if (p.dim > 3 && (p.essential || !p.zero_length))
      throw InternalError("diagram: cell " + std::to_string(p.birth_cell) + " creates " +
                          (p.essential ? "an essential" : "a positive-length") + " class of degree " +
                          std::to_string(p.dim) + " (docs/MATH.md §7.6 allows degrees 0..3 only)");
}

} // namespace medusa::persistence
