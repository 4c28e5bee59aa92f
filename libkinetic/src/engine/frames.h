// Frames: switching slabs, rebuilding every certificate, insertions and deletions (docs/MATH.md §2.3, §5.6).
#pragma once

#include "engine.h"
#include "medusa/core/error.h"
#include "start_determinants.h"

#include <algorithm>
#include <array>
#include <unordered_set>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> void Engine<K>::set_slab_motion(std::size_t k) {
  slab = k;
  if (motion.use_count() > 1) // roots of the last slab remain: they keep its motion
    motion = std::make_shared<SlabMotion>(*motion);
  for (std::size_t i = 0; i < traj.cells.size(); ++i) {
    const Trajectory& c = traj.cells[i];
    if (!c.present(k))
      continue;
    MovingPoint& m = motion->points[i];
    const GridPoint& x = c.at(k);
    m.a = {x[0], x[1], x[2]};
    if (k + 1 < traj.frames() && c.present(k + 1)) {
      const GridPoint& y = c.at(k + 1);
      m.b = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
    } else {
      m.b = {0, 0, 0}; // ending at this frame: velocity 0 for this instant (docs/MATH.md §5.6)
    }
  }
}

template <class K> void Engine<K>::reinstall_all() {
  certificates.clear_times();
  root_cache.clear();
  // Every facet once, named as its certificate named it (the cell of its first apex), in cell order.
  std::vector<std::pair<CellIndex, int>> owners;
  owners.reserve(cells.size() * (dim + 1) / 2);
  cells.for_each_cell([&](CellIndex c) {
    for (int i = 0; i <= dim; ++i)
      if (c < cells.neighbor(c, i))
        owners.push_back(facet_owner(c, i));
  });
  retire_all_certs();
  cells.clear_certs();
  for (const auto& [c, i] : owners)
    install_facet(c, i);
  faces.for_each([this](const Simplex& s, Face& f) {
    if (f.cert < 0)
      return;
    f.cert = -1;
    Interval at_frame(0); // undecided unless the install's enclosure says otherwise
    install_radius(s, f, &at_frame);
    // R = rho at the frame: a touch there, whatever the sign just after (Engine::resolve_touches).
    if (!(at_frame.inf() > 0 || at_frame.sup() < 0) && radius_vanishes_now(s))
      agenda.touch(f.cert, certificates[f.cert].version);
  });
}

template <class K> void Engine<K>::frame(Observer& observer, std::size_t k) {
  // Slab k-1 ended at t_k; switch to slab k and rebuild every certificate (docs/MATH.md §2.3, §5.6).
  // At t_0 the structure was just built (initialise); only cells present at t_0 alone are deleted.
  std::vector<Step> steps;
  if (k > 0) {
    check_collisions_at_frame(k);
    set_slab_motion(k);
    now = SlabTime();
    reinstall_all();
    if (top_simplex_turns_at_frame()) {
      ++stats.frames_repaired_for_flat_simplices;
      repair(steps);
    }
    resolve_delaunay(steps);
  }
  // Insertions, then deletions, one rank each in increasing cell id (docs/MATH.md §5.6).
  std::vector<std::pair<std::int64_t, VertexId>> born, dying;
  for (std::size_t i = 0; i < traj.cells.size(); ++i) {
    const Trajectory& c = traj.cells[i];
    if (c.first_frame == k && k > 0)
      born.emplace_back(c.cell_id, static_cast<VertexId>(i));
    // A cell present at this frame alone is inserted and then deleted here: it must not stay behind,
    // frozen where it was, for the rest of the run.
    if (c.last_frame() == k && k + 1 < traj.frames() && (alive[i] || c.first_frame == k))
      dying.emplace_back(c.cell_id, static_cast<VertexId>(i));
  }
  std::sort(born.begin(), born.end());
  std::sort(dying.begin(), dying.end());
  for (const auto& cell_vertex : born)
    insert_or_delete(cell_vertex.second, true, steps);
  for (const auto& cell_vertex : dying)
    insert_or_delete(cell_vertex.second, false, steps);
  process_batch(steps); // radius events at the frame, then the final re-evaluation (docs/MATH.md §5.6 step 5)
  check_collisions_in_slab();
  emit_batch(observer, steps, true);
  if (k > 0)
    observer.frame(k, event_time(true));
  if (options.audit)
    audit();
}

// Whether some finite top simplex flat at this frame is inside out (or still flat) just after it, or
// lies next to a hull facet whose three cells are collinear at the frame: then Del(now+) is rebuilt
// (docs/MATH.md §5.11, §5.4), since certificates reading its recorded orientation mean nothing and
// flips chosen on them can leave it inverted. Now is the slab start, where every cell sits at its
// grid position: CGAL's exact static predicate on those positions (start_determinants.h) finds the
// flat ones at a fraction of the cost of an interval evaluation.
template <class K> bool Engine<K>::top_simplex_turns_at_frame() {
  if (!now.is_rational() || now.rational() != 0)
    throw InternalError("the frame test of flat top simplices runs at a slab start only");
  std::array<const MovingPoint*, 4> p{};
  // One switch to round-to-nearest for every top simplex, not two per test (start_determinants.h);
  // the rare flat one's follow-up tests set the mode they need themselves.
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  bool turns = false;
  cells.for_each_cell([&](CellIndex c) {
    if (turns || cells.vertex(c, 0) == infinite_vertex)
      return;
    const Simplex t = cells.top(c);
    for (std::size_t i = 0; i < t.size(); ++i)
      p[i] = &pt(t[i]);
    turns = orientation_vanishes_at_start_in_nearest(p.data(), t.size()) &&
            (orientation_sign_plus(t) != cells.orientation(c) || degenerate_hull_facet_at(t));
  });
  return turns;
}

// One insertion or deletion of vertex v at the current frame, as its own rank (docs/MATH.md §5.6), with
// the Delaunay changes made by a static rebuild and the membership re-evaluated around them.
template <class K> void Engine<K>::insert_or_delete(VertexId v, bool insert, std::vector<Step>& steps) {
  Step step;
  step.kind = insert ? StepKind::insertion : StepKind::deletion;
  step.vertex = v;
  OldMembership old_k;
  old_k.emplace(Simplex{v}, !insert);
  alive[static_cast<std::size_t>(v)] = insert ? 1 : 0;
  if (!record_local_change(step, old_k, v, insert))
    record_top_changes(step, old_k);
  settle_membership(old_k, step);
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
  ++(insert ? stats.insertions : stats.deletions);
  resolve_delaunay(steps);
}

template <class K> void Engine<K>::record_top_changes(Step& step, OldMembership& old_k) {
  const std::vector<Simplex> old_tops = all_tops();
  const std::unordered_set<Simplex, SimplexHash> before(old_tops.begin(), old_tops.end());
  rebuild_static(&old_k);
  const std::vector<Simplex> new_tops = all_tops();
  const std::unordered_set<Simplex, SimplexHash> after(new_tops.begin(), new_tops.end());
  for (const Simplex& t : old_tops)
    if (is_finite(t) && !after.count(t))
      step.delaunay_removed.push_back(t);
  for (const Simplex& t : new_tops)
    if (is_finite(t) && !before.count(t))
      step.delaunay_created.push_back(t);
  // Cells are listed in the order of their indices, which means nothing: the stream lists them sorted.
  std::sort(step.delaunay_removed.begin(), step.delaunay_removed.end());
  std::sort(step.delaunay_created.begin(), step.delaunay_created.end());
}

} // namespace medusa::kinetic::detail
