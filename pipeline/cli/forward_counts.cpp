#include "forward_counts.h"

#include <algorithm>

namespace medusa::cli {

ForwardCounts forward_counts(const persistence::Diagram& forward) {
  ForwardCounts c;
  for (const persistence::PersistencePair& p : forward.pairs) {
    if (p.zero_length)
      continue;
    if (p.dim == 0) {
      c.clusters_at_start += p.birth_time.batch == 0 ? 1 : 0;
      if (p.essential)
        ++c.clusters_at_end;
      else
        c.merge_times.push_back(p.death);
    } else if (p.dim == 1) {
      ++c.loops;
      c.loops_filled += p.essential ? 0 : 1;
    } else if (p.dim == 2) {
      ++c.cavities;
      c.cavities_filled += p.essential ? 0 : 1;
    }
  }
  std::sort(c.merge_times.begin(), c.merge_times.end());
  return c;
}

} // namespace medusa::cli
