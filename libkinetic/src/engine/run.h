// The whole run: construction, the initial complex at t_0 and the loop over slabs.
#pragma once

#include "engine.h"

#include "medusa/core/error.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

template <class K>
Engine<K>::Engine(const Trajectories& t, KineticOptions o) : traj(t), options(std::move(o)) {
  // Vertex ids and cell indices are 32-bit, and Del has some seven top simplices per vertex in 3D.
  constexpr std::size_t max_trajectories = (std::size_t{1} << 28) - 1;
  if (traj.cells.size() > max_trajectories)
    throw InputError("the run has " + std::to_string(traj.cells.size()) +
                     " cell trajectories; the kinetic engine takes at most " +
                     std::to_string(max_trajectories));
  P = options.rho2.num;
  Q = options.rho2.den;
  Pi = Interval(CGAL::to_interval(CGAL::Gmpz(P.get_mpz_t())));
  Qi = Interval(CGAL::to_interval(CGAL::Gmpz(Q.get_mpz_t())));
  motion = std::make_shared<SlabMotion>();
  motion->points.resize(traj.cells.size());
  motion->rho2 = std::make_shared<const SquaredRadius>(options.rho2);
  alive.assign(traj.cells.size(), 0);
}

// A planar run keeps every cell in one plane z = const: the 2D certificates ignore z, so a differing
// z would be silently wrong.
template <class K> void Engine<K>::check_planar() const {
  for (const Trajectory& c : traj.cells)
    for (std::size_t f = 0; f < c.positions.size(); ++f)
      if (c.positions[f][2] != traj.cells.front().positions.front()[2])
        throw InputError("cell " + std::to_string(c.cell_id) + " at frame " +
                         std::to_string(c.first_frame + f) +
                         ": z differs from the other cells' in a two-dimensional run");
}

template <class K> void Engine<K>::initialise(Observer& observer) {
  check_collisions_at_frame(0);
  set_slab_motion(0);
  now = SlabTime();
  for (std::size_t i = 0; i < traj.cells.size(); ++i)
    alive[i] = traj.cells[i].present(0) && traj.cells[i].first_frame == 0;
  rebuild_static(nullptr); // every simplex is settled below: the old memberships are not needed
  std::vector<Step> ignored;
  resolve_delaunay(ignored); // Del(t0+) (docs/MATH.md §5.5): fix what the frozen delta left
  agenda.drop_radius();
  // Membership of every simplex, in decreasing dimension (docs/MATH.md §4.6), one pass over the face
  // table per dimension: the order within a dimension does not matter (settle_membership), and a
  // copy of every face, as a table of old memberships, would be held beside all of them at the
  // kinetic stage's peak.
  auto state_of = [&](const Simplex& x) { return state_in_table(x); };
  for (std::size_t size = top_size(); size >= 2; --size)
    faces.for_each([&](const Simplex& s, Face& f) {
      if (s.size() == size)
        settle(s, f, state_of);
    });
  check_collisions_in_slab();
  observer.initial(event_time(true), current_complex());
  if (options.audit)
    audit();
}

template <class K> void Engine<K>::run(Observer& observer) {
  traj.validate();
  if constexpr (dim == 2)
    check_planar();
  auto clock = std::chrono::steady_clock::now();
  const TimeComparisonCounts comparisons_before = time_comparison_counts();
  initialise(observer);
  for (std::size_t k = 0; k + 1 < traj.frames(); ++k) {
    frame(observer, k);
    run_slab(observer);
    auto t = std::chrono::steady_clock::now();
    stats.seconds_per_frame.push_back(std::chrono::duration<double>(t - clock).count());
    clock = t;
  }
  const TimeComparisonCounts comparisons_after = time_comparison_counts();
  stats.times_sharpened = comparisons_after.sharpened - comparisons_before.sharpened;
  stats.times_compared_algebraically = comparisons_after.algebraic - comparisons_before.algebraic;
  stats.times_compared_as_one_polynomial = comparisons_after.proportional - comparisons_before.proportional;
  stats.times_reported_exactly = comparisons_after.reported_exactly - comparisons_before.reported_exactly;
  // The last frame is reached but never starts a slab (frame() is not called for it): its positions
  // are checked here, as frame() checks the others' (docs/MATH.md §2.5).
  if (traj.frames() > 1)
    check_collisions_at_frame(traj.frames() - 1);
  // t_end: the reported state is K(t_end-) (docs/MATH.md §0).
  slab = traj.frames() - 1;
  now = SlabTime();
  ++batch_index; // t_end is later than every batch: cells alive at the end die there
  observer.finish(event_time(true));
}

} // namespace medusa::kinetic::detail
