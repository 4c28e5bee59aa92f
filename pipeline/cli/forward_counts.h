// The numbers a biologist reads off a forward diagram (docs/MATH.md §7.6), as `medusa run`'s summary
// counts them: clusters alive just after t0 and at the end, the merge times, loops and cavities.
#pragma once

#include "medusa/persistence/diagram.h"

#include <cstddef>
#include <vector>

namespace medusa::cli {

struct ForwardCounts {
  std::size_t clusters_at_start = 0;       // H0 born in batch 0 and not killed there
  std::size_t clusters_at_end = 0;         // essential H0 classes
  std::vector<double> merge_times;         // deaths of the finite H0 classes of positive length, increasing
  std::size_t loops = 0, loops_filled = 0; // H1 of positive length; those that die
  std::size_t cavities = 0, cavities_filled = 0; // H2 likewise (space-time bubbles in a planar run)
};

// Needs the pairs' virtual birth times (a computed diagram, not one read back from /persistence).
ForwardCounts forward_counts(const persistence::Diagram& forward);

} // namespace medusa::cli
