// All diagrams of one run in one call: forward and reverse, for the whole medusa and for the
// sub-medusa of each requested cell type (MATH.md 7.2-7.4), each audited (Euler characteristic,
// homology degrees).
#pragma once

#include "medusa/persistence/diagram.h"

#include <vector>

namespace medusa::persistence {

// Order: whole forward, whole reverse, then forward and reverse for each type in `types`. Throws
// InternalError when an audit fails (check_euler, check_homology_degrees). Runs on `threads` worker
// threads (1 = sequential in the calling thread): the filtrations are independent, and so are their
// reductions (each thread owns its PHAT boundary matrix), so the result is the same for every thread
// count; at most `threads` filtrations are in memory at once. When several filtrations fail, the
// error of the first one in the order above is thrown.
std::vector<Diagram> compute_medusa_diagrams(const std::vector<complex::Cell>& cells,
                                             const std::vector<int>& vertex_type,
                                             const std::vector<int>& types, unsigned threads = 1);

// The two phases of compute_medusa_diagrams, for callers that time or report them apart: every
// filtration in the order above, then their reductions (each filtration is freed once reduced). All
// filtrations are in memory at once after the first phase.
std::vector<Filtration> make_medusa_filtrations(const std::vector<complex::Cell>& cells,
                                                const std::vector<int>& vertex_type,
                                                const std::vector<int>& types, unsigned threads = 1);
std::vector<Diagram> reduce_medusa_filtrations(const std::vector<complex::Cell>& cells,
                                               std::vector<Filtration>&& filtrations, unsigned threads = 1);

} // namespace medusa::persistence
