// The audit of docs/MATH.md §7.6: in a medusa, classes of positive length and essential classes occur only
// in degrees 0..3 (the complex and its sublevel sets are homotopy equivalent to subsets of R^4).
#pragma once

#include "medusa/persistence/diagram.h"

namespace medusa::persistence {

// Throws InternalError naming the birth cell of the first essential or positive-length class of
// degree above 3.
void check_homology_degrees(const Diagram& diagram);

} // namespace medusa::persistence
