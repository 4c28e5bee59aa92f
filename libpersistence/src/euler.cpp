#include "medusa/persistence/euler.h"

#include "medusa/core/error.h"

#include <string>

namespace medusa::persistence {

std::int64_t euler_characteristic(const Filtration& filtration) {
  std::int64_t chi = 0;
  for (int dim : filtration.dims)
    chi += dim % 2 == 0 ? 1 : -1;
  return chi;
}

std::int64_t essential_euler_characteristic(const Diagram& diagram) {
  std::int64_t chi = 0;
  for (const auto& p : diagram.pairs)
    if (p.essential)
      chi += p.dim % 2 == 0 ? 1 : -1;
  return chi;
}

void check_euler(const Diagram& diagram, const Filtration& filtration) {
  const std::int64_t from_cells = euler_characteristic(filtration);
  const std::int64_t from_classes = essential_euler_characteristic(diagram);
  if (from_cells != from_classes)
    throw InternalError("diagram: Euler characteristic of the cells is " + std::to_string(from_cells) +
                        " but the essential classes give " + std::to_string(from_classes) + " (cell type " +
                        std::to_string(diagram.cell_type) + ")");
}

} // namespace medusa::persistence
