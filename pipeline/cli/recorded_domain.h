// The periodic domain a store records (docs/FORMAT.md: periodic_axes, periodic_length_*), for rerunning
// the kinetic stage on the store's trajectories on the torus, as `medusa report` does for its radius
// sweep (docs/MATH.md §8).
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/medusa/run_info.h"

#include <cstdint>
#include <string>

namespace medusa::cli {

// The periodic axes and periods (grid units) `run` records; no axis for an open run. The origin is not
// recorded and is left at 0: the covering complex and its quotient (docs/MATH.md §8.3-§8.5) depend on
// the periods only, the trajectories being unwrapped. The lattice lengths are the periods in lattice
// units (period / scale, rounded down), for messages. Throws StoreError naming `store` for axes other
// than x, y, z or a periodic axis without a positive period.
io::PeriodicDomain recorded_domain(const medusa::RunInfo& run, std::int64_t scale, const std::string& store);

// "periodic along x, y (period 50 x 50 lattice units)", or "" for an open run: what `medusa info` and
// the report say of the domain; `aside` goes inside the parentheses, after the periods.
std::string periodic_domain_text(const medusa::RunInfo& run, std::int64_t scale,
                                 const std::string& aside = "");

} // namespace medusa::cli
