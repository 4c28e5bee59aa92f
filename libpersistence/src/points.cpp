#include "medusa/persistence/points.h"

#include "medusa/core/error.h"

#include <cmath>
#include <string>

namespace medusa::persistence {

PointDiagram to_points(const Diagram& diagram, int k, bool keep_zero_length) {
  const double sign = diagram.direction == Direction::forward ? 1.0 : -1.0;
  PointDiagram points;
  for (const auto& p : diagram.pairs) {
    if (p.dim != k || (p.zero_length && !keep_zero_length))
      continue;
    if (p.essential)
      points.essential.push_back(sign * p.birth);
    else
      points.finite.push_back({sign * p.birth, sign * p.death});
  }
  return points;
}

PointDiagram normalise_time(const PointDiagram& points, Direction direction, double t0, double t_end) {
  if (!(t0 < t_end))
    throw InputError("normalise_time: t0 = " + std::to_string(t0) +
                     " is not before t_end = " + std::to_string(t_end));
  const double span = t_end - t0;
  const double shift = direction == Direction::forward ? -t0 : t_end;
  auto map = [&](double x) { return (x + shift) / span; };
  PointDiagram result;
  result.finite.reserve(points.finite.size());
  for (const auto& p : points.finite)
    result.finite.push_back({map(p.birth), map(p.death)});
  for (double b : points.essential)
    result.essential.push_back(map(b));
  return result;
}

void check_points(const PointDiagram& points, const char* what) {
  for (std::size_t i = 0; i < points.finite.size(); ++i) {
    const Point& p = points.finite[i];
    if (!std::isfinite(p.birth) || !std::isfinite(p.death) || p.birth > p.death)
      throw InputError(std::string(what) + ": finite point " + std::to_string(i) + " (" +
                       std::to_string(p.birth) + ", " + std::to_string(p.death) +
                       ") is not a finite point with birth <= death");
  }
  for (std::size_t i = 0; i < points.essential.size(); ++i)
    if (!std::isfinite(points.essential[i]))
      throw InputError(std::string(what) + ": essential point " + std::to_string(i) +
                       " has a non-finite birth");
}

} // namespace medusa::persistence
