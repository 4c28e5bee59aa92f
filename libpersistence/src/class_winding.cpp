#include "medusa/persistence/class_winding.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

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

std::array<std::int64_t, 3> cycle_winding(const medusa::Medusa& medusa, CellLists::List cycle) {
  std::array<std::int64_t, 3> winding{};
  const auto& lengths = medusa.run.periodic_lengths;
  if (medusa.run.periodic_axes.empty() || medusa.input.cells.empty())
    return winding;
  // Each edge {u, v} of the complex on the torus is short (at most 2 rho < L/2 along every axis,
  // docs/MATH.md §8.3) for its whole life, while the unwrapped trajectories move continuously: the
  // number of periods n between v's copy at the edge's end and v itself is constant and is read off
  // the unwrapped difference at any moment of that life, rounded to the nearest period (the rounding
  // has a margin of L/4, far above the doubles' error).
  // Over Z/2 only the parity of the sum of the n_a along the cycle is defined: it is the image of
  // the cycle in H1(torus; Z/2), zero for a boundary (docs/MATH.md §8.8).
  for (medusa::CellId id : cycle) {
    const medusa::Cell& c = medusa.cell(id);
    if (c.dim() != 1)
      return {};
    const auto pu = position_at(medusa.input, c.vertices[0], c.birth.time);
    const auto pv = position_at(medusa.input, c.vertices[1], c.birth.time);
    for (std::size_t a = 0; a < 3; ++a)
      if (lengths[a] > 0)
        winding[a] ^= std::llround((pv[a] - pu[a]) / static_cast<double>(lengths[a])) & 1;
  }
  return winding;
}

std::vector<std::string> class_wrapping_axes(const medusa::Medusa& medusa,
                                             const DiagramWithClasses& classes) {
  const ClassRepresentatives& reps = classes.classes;
  std::vector<std::string> out(reps.size());
  if (medusa.run.periodic_axes.empty())
    return out;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < reps.size(); ++i)
    if (classes.diagram.pairs[reps.rows[i]].dim == 1)
      order.push_back(i);
  // Birth order is the filtration order of the birth cells (docs/MATH.md §7.2, reverse §7.3), read
  // from the cells: a diagram read back from a store holds no filtration indices.
  const bool forward = classes.diagram.direction == Direction::forward;
  const auto birth_cell = [&](std::size_t i) -> const medusa::Cell& {
    return medusa.cell(classes.diagram.pairs[reps.rows[i]].birth_cell);
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const medusa::Cell &x = birth_cell(a), &y = birth_cell(b);
    const medusa::VirtualTime &tx = forward ? x.birth : y.death, &ty = forward ? y.birth : x.death;
    const int dx = x.dim(), dy = y.dim();
    return std::tie(tx.batch, tx.rank, dx, x.vertices) < std::tie(ty.batch, ty.rank, dy, y.vertices);
  });
  // Gaussian elimination over Z/2 in birth order: an essential class may take the sum of its
  // representative and older essential ones, which keeps its birth (the elder rule); so it wraps only
  // where its winding is not that of a sum of older wrapping classes.
  std::vector<std::pair<unsigned, unsigned>> basis; // (winding bits, pivot bit)
  for (std::size_t i : order) {
    const auto w = cycle_winding(medusa, reps.cycles[i]);
    unsigned bits = 0;
    for (std::size_t a = 0; a < 3; ++a)
      bits |= static_cast<unsigned>(w[a] & 1) << a;
    const bool essential = classes.diagram.pairs[reps.rows[i]].essential;
    if (essential)
      for (const auto& [b, pivot] : basis)
        if (bits & pivot)
          bits ^= b;
    if (essential && bits != 0) {
      unsigned pivot = 1;
      while (!(bits & pivot))
        pivot <<= 1;
      basis.emplace_back(bits, pivot);
    }
    std::array<std::int64_t, 3> reduced{};
    for (std::size_t a = 0; a < 3; ++a)
      reduced[a] = (bits >> a) & 1;
    out[i] = winding_axes(reduced);
  }
  return out;
}

std::string winding_axes(const std::array<std::int64_t, 3>& winding) {
  std::string out;
  for (std::size_t a = 0; a < 3; ++a)
    if (winding[a] != 0)
      out += (out.empty() ? "" : ",") + std::string(1, static_cast<char>('x' + a));
  return out;
}

} // namespace medusa::persistence
