// All diagrams of one run in one call: forward and reverse, for the whole medusa and for the
// sub-medusa of each requested cell type (MATH.md 7.2-7.4), each audited (Euler characteristic,
// homology degrees).
#pragma once

#include "medusa/persistence/diagram.h"

#include <vector>

namespace medusa::persistence {

// Order: whole forward, whole reverse, then forward and reverse for each type in `types`. Throws
// InternalError when an audit fails (check_euler, check_homology_degrees).
std::vector<Diagram> compute_medusa_diagrams(const std::vector<complex::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types);

} // namespace medusa::persistence
