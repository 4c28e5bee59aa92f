#include "medusa/persistence/class_winding.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace medusa::persistence {

namespace {

// Position of trajectory v at time t (MCS), linear between frames, held at its first and last frames.
std::array<double, 3> position_at(const kinetic::Trajectories& input, kinetic::VertexId v, double t) {
  const kinetic::Trajectory& c = input.cells.at(static_cast<std::size_t>(v));
  std::size_t k = c.first_frame;
  while (k < c.last_frame() && static_cast<double>(input.frame_times[k + 1]) <= t)
    ++k;
  std::array<double, 3> p{};
  const double t0 = static_cast<double>(input.frame_times[k]);
  const double s = k < c.last_frame()
                       ? std::clamp((t - t0) / (static_cast<double>(input.frame_times[k + 1]) - t0), 0.0, 1.0)
                       : 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    const double x0 = static_cast<double>(c.at(k)[a]);
    p[a] = k < c.last_frame() ? x0 + s * (static_cast<double>(c.at(k + 1)[a]) - x0) : x0;
  }
  return p;
}

} // namespace

std::array<std::int64_t, 3> cycle_winding(const medusa::Medusa& medusa,
                                          const std::vector<medusa::CellId>& cycle) {
  std::array<std::int64_t, 3> winding{};
  const auto& lengths = medusa.run.periodic_lengths;
  if (medusa.run.periodic_axes.empty() || medusa.input.cells.empty())
    return winding;
  // Each edge {u, v} of the complex on the torus is short (at most 2 rho < L/2 along every axis,
  // docs/MATH.md §8.3) for its whole life, while the unwrapped trajectories move continuously: the
  // number of periods n between v's copy at the edge's end and v itself is constant and is read off
  // the unwrapped difference at any moment of that life, rounded to the nearest period (the rounding
  // has a margin of L/4, far above the doubles' error).
  struct Edge {
    kinetic::VertexId u, v;
    std::array<std::int64_t, 3> periods; // going from u to v
    bool used = false;
  };
  std::vector<Edge> edges;
  std::map<kinetic::VertexId, std::vector<std::size_t>> at;
  for (medusa::CellId id : cycle) {
    const medusa::Cell& c = medusa.cell(id);
    if (c.dim() != 1)
      return {};
    Edge e{c.vertices[0], c.vertices[1], {}, false};
    const auto pu = position_at(medusa.input, e.u, c.birth.time);
    const auto pv = position_at(medusa.input, e.v, c.birth.time);
    for (std::size_t a = 0; a < 3; ++a)
      if (lengths[a] > 0)
        e.periods[a] = -std::llround((pv[a] - pu[a]) / static_cast<double>(lengths[a]));
    at[e.u].push_back(edges.size());
    at[e.v].push_back(edges.size());
    edges.push_back(e);
  }
  // Over Z/2 every vertex of the cycle has even degree: walk it as closed walks, each edge once in
  // the direction of travel (the winding of the walks adds up).
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (edges[start].used)
      continue;
    kinetic::VertexId here = edges[start].u;
    std::size_t next = start;
    while (true) {
      Edge& e = edges[next];
      e.used = true;
      const bool forward = e.u == here;
      for (std::size_t a = 0; a < 3; ++a)
        winding[a] += forward ? e.periods[a] : -e.periods[a];
      here = forward ? e.v : e.u;
      const auto& around = at[here];
      const auto it =
          std::find_if(around.begin(), around.end(), [&](std::size_t i) { return !edges[i].used; });
      if (it == around.end())
        break;
      next = *it;
    }
  }
  return winding;
}

std::string winding_axes(const std::array<std::int64_t, 3>& winding) {
  std::string out;
  for (std::size_t a = 0; a < 3; ++a)
    if (winding[a] != 0)
      out += (out.empty() ? "" : ",") + std::string(1, static_cast<char>('x' + a));
  return out;
}

} // namespace medusa::persistence
