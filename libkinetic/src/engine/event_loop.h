// The event loop inside a slab: popping simultaneous failures from the queue, processing a batch
// and emitting its ranked steps to the observer (docs/MATH.md §5.2).
#pragma once

#include "engine.h"

#include <algorithm>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> EventTime Engine<K>::event_time(bool at_frame) const {
  EventTime e;
  e.batch = batch_index;
  e.slab = slab;
  const std::int64_t t0 = traj.frame_times[slab];
  const std::int64_t t1 = slab + 1 < traj.frames() ? traj.frame_times[slab + 1] : t0;
  e.time = now.reported_time(t0, t1);
  e.u = t1 > t0 ? (e.time - static_cast<double>(t0)) / static_cast<double>(t1 - t0) : 0.0;
  e.at_frame = at_frame;
  return e;
}

template <class K> void Engine<K>::emit_batch(Observer& observer, std::vector<Step>& steps, bool at_frame) {
  std::vector<Step> kept;
  for (Step& s : steps)
    if (s.kind != StepKind::settle || !s.entered.empty() || !s.left.empty())
      kept.push_back(std::move(s));
  if (kept.empty())
    return;
  ++batch_index;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    kept[i].rank = i + 1;
    auto by_dim = [](const Simplex& a, const Simplex& b) { return a < b; };
    std::sort(kept[i].entered.begin(), kept[i].entered.end(), by_dim);
    std::sort(kept[i].left.begin(), kept[i].left.end(), by_dim);
  }
  ++stats.batches;
  if (at_frame)
    ++stats.frame_batches;
  observer.batch(event_time(at_frame), kept);
}

// Processes the batch at `now`: Delaunay failures first (canonical order), then radius events,
// then the final re-evaluation (docs/MATH.md §5.2).
template <class K> void Engine<K>::process_batch(std::vector<Step>& steps) {
  resolve_hull_touches();
  resolve_delaunay(steps);
  OldMembership& old_k = batch_scratch;
  old_k.clear();
  Step settle;
  settle.kind = StepKind::settle;
  resolve_touches(old_k);
  while (agenda.has_radius()) {
    resolve_radius(settle, old_k);
    resolve_delaunay(steps);
  }
  // The closure: faces of cofaces matter only through the faces themselves, which old_k holds.
  settle_membership(old_k, settle);
  steps.push_back(std::move(settle));
}

template <class K> void Engine<K>::at_own_time(int cert) {
  if (const SlabTime* u = agenda.fired_time(cert))
    now = *u;
}

// A popped entry at now: its certificate fails, or its simplex touches rho.
template <class K> void Engine<K>::fire(const QueueEntry& e) {
  agenda.fired(static_cast<int>(e.cert), e.u);
  if (e.touch && certificates[e.cert].kind == CertKind::radius)
    agenda.touch(static_cast<int>(e.cert), e.version);
  else if (e.touch)
    agenda.hull_touch(static_cast<int>(e.cert), e.version);
  else {
    switch (certificates[e.cert].substitute) {
    case Substitute::hull_fold: ++stats.hull_ridges_folding; break;
    case Substitute::cell_orientations: ++stats.cospherical_cells_flattening; break;
    case Substitute::none: break;
    }
    mark_invalid(static_cast<int>(e.cert));
  }
}

template <class K> void Engine<K>::run_slab(Observer& observer) {
  while (const QueueEntry* earliest = certificates.earliest()) {
    QueueEntry top = *earliest;
    certificates.pop();
    const Certificate& c = certificates[top.cert];
    now = top.u;
    if (const IsolatedRoot* r = now.isolated(); r != nullptr && r->wide) {
      CGAL::Protect_FPU_rounding<true> guard;
      now.sharpen(cert_poly<Interval>(c));
    }
    now.tighten();
    fire(top);
    while (const QueueEntry* next = certificates.earliest()) {
      if (compare(next->u, now) != 0)
        break;
      QueueEntry e = *next;
      certificates.pop();
      fire(e);
    }
    const SlabTime batch_time = now; // narrowed: the reported time rounds it in doubles (§3.12)
    std::vector<Step> steps;
    process_batch(steps);
    agenda.end_batch();
    now = batch_time;
    emit_batch(observer, steps, false);
    if (options.audit && ++batches_since_audit >= options.audit_stride) {
      batches_since_audit = 0;
      audit();
    }
  }
}

} // namespace medusa::kinetic::detail
