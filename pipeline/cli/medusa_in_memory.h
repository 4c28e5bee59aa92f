// The kinetic stage and the medusa builder of `medusa run` for one radius, collected in memory instead
// of streamed to a store: what `medusa sweep` runs once per radius, on threads of its own.
#pragma once

#include "medusa/io/periodic_domain.h"
#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/run_info.h"

#include <string>

namespace medusa::cli {

// The medusa of `trajectories` at radius `info.radius_text` (decimal text, exact, docs/MATH.md §1).
// Polls for interrupts (throws Interrupted). Safe to call from several threads at once. With periodic
// axes in `domain`, the complex on the torus (docs/MATH.md §8): the radius must pass
// periodic::check_periodic_radius.
medusa::Medusa medusa_in_memory(const kinetic::Trajectories& trajectories, const medusa::RunInfo& info,
                                const io::PeriodicDomain& domain = {});

} // namespace medusa::cli
