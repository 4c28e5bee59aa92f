// Trajectories on a periodic lattice unwrapped into the covering space (docs/MATH.md §8.2).
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/trajectories.h"

#include <string>
#include <vector>

namespace medusa::io {

// Each trajectory's positions, given wrapped into the domain, become continuous: along every periodic
// axis the step between consecutive frames is the minimum image of the wrapped step, in
// [-period/2, period/2). The first position of each trajectory stays where it is. A step of exactly
// half the period is ambiguous (both directions are minimal) and throws InputError naming the cell,
// both MCS and the file of the later frame (`sources[frame]`, or `sources[0]` for a single source).
void unwrap_trajectories(kinetic::Trajectories& trajectories, const PeriodicDomain& domain,
                         const std::vector<std::string>& sources);

} // namespace medusa::io
