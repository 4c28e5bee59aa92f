// The cells of one type outside its largest cluster at a frame (the components of K_t^X, docs/MATH.md
// §6.9, §7.4): when a type ends in a few clusters, which CompuCell3D cells keep it from being one.
#pragma once

#include "report_answer.h"

#include "medusa/medusa/medusa.h"

#include <cstddef>

namespace medusa::cli {

// The cells of `type` at the state reported at frame k (medusa::cells_at_frame) against their largest
// cluster; `medusa` must hold its input.
ClustersApart clusters_apart(const medusa::Medusa& medusa, std::size_t k, int type);

} // namespace medusa::cli
