// The Euler characteristic check of docs/MATH.md §6.4 / 7.5: sum_k (-1)^k #essential_k = chi.
#pragma once

#include "medusa/persistence/diagram.h"
#include "medusa/persistence/filtration.h"

#include <cstdint>

namespace medusa::persistence {

// chi of the filtered complex: sum over its cells of (-1)^dim.
std::int64_t euler_characteristic(const Filtration& filtration);

// sum_k (-1)^k (number of essential classes of degree k).
std::int64_t essential_euler_characteristic(const Diagram& diagram);

// Throws InternalError when the two differ (the reduction or the complex is broken).
void check_euler(const Diagram& diagram, const Filtration& filtration);

} // namespace medusa::persistence
