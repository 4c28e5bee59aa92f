// Diagrams as plain point sets (b, d) with b <= d, the input of distances and summaries. Reverse
// diagrams are mapped to -t (docs/MATH.md §7.3), so the formulas of 7.7 and 7.8 apply unchanged.
#pragma once

#include "medusa/persistence/diagram.h"

#include <vector>

namespace medusa::persistence {

struct Point {
  double birth = 0;
  double death = 0; // birth <= death
};

struct PointDiagram {
  std::vector<Point> finite;     // may include diagonal points and duplicates
  std::vector<double> essential; // births of the essential classes (b, +inf)
};

// The points of degree k: forward as they are, reverse as (-t_birth, -t_death) and (-t_birth, +inf).
// Zero-length pairs are left out unless asked for (docs/MATH.md §7.5).
PointDiagram to_points(const Diagram& diagram, int k, bool keep_zero_length = false);

// The time normalisation of docs/MATH.md §7.7 for comparing runs: t -> (t - t0) / (t_end - t0) on a forward
// diagram, and the matching increasing map of -t, x -> (x + t_end) / (t_end - t0), on a reverse one
// (docs/MATH.md §7.3). Throws InputError unless t0 < t_end.
PointDiagram normalise_time(const PointDiagram& points, Direction direction, double t0, double t_end);

// Throws InputError when a point has a NaN or infinite coordinate or birth > death.
void check_points(const PointDiagram& points, const char* what);

} // namespace medusa::persistence
