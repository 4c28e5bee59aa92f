#include "longest_classes.h"

#include "medusa/core/error.h"
#include "medusa/persistence/class_records.h"

#include <cmath>

namespace medusa::cli {

std::vector<LongestFilled> longest_filled_classes(const medusa::Medusa& medusa,
                                                  const persistence::Diagram& diagram,
                                                  const persistence::ClassRepresentatives& c) {
  std::vector<LongestFilled> out;
  if (diagram.direction != persistence::Direction::forward)
    return out;
  for (int k = 1; k <= 2; ++k) {
    // The lifetime as `medusa classes` computes it (ClassRecord::lifetime), so that ties and
    // rounding pick the same class as its --sort lifetime.
    std::size_t best = c.size();
    double longest = -1;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const persistence::PersistencePair& p = diagram.pairs.at(c.rows[i]);
      if (p.dim != k || p.essential || p.zero_length)
        continue;
      const double lifetime = std::fabs(p.death - p.birth);
      if (lifetime > longest) {
        longest = lifetime;
        best = i;
      }
    }
    if (best == c.size())
      continue;
    // One class through class_records, which turns its cycle into CC3D cell ids.
    persistence::DiagramWithClasses one;
    one.diagram.direction = diagram.direction;
    one.diagram.cell_type = diagram.cell_type;
    one.diagram.pairs = {diagram.pairs[c.rows[best]]};
    one.classes.options = c.options;
    one.classes.rows = {0};
    one.classes.cycles.push_back(c.cycles[best]);
    one.classes.clusters.push_back({});
    const persistence::ClassRecord r = persistence::class_records(medusa, one).front();
    out.push_back({diagram.cell_type, k, c.rows[best], r.birth, r.death, r.cells});
  }
  return out;
}

} // namespace medusa::cli
