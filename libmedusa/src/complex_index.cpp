#include "medusa/medusa/complex_index.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <string>

namespace medusa {

ComplexIndex::ComplexIndex(const Medusa& medusa, std::optional<int> type) : medusa_(medusa), type_(type) {
  std::vector<IntervalTree::Interval> after, before;
  after.reserve(medusa.cells.size()); // at most: doubling would hold up to twice as much
  before.reserve(medusa.cells.size());
  for (const Cell& c : medusa.cells) {
    if (type && !medusa.has_type(c, *type))
      continue;
    // docs/MATH.md §6.6 in batch indices: K(b+) stabs [birth, death), K(b-) stabs (birth, death].
    after.push_back({c.birth.batch, c.death.batch, c.id});
    before.push_back({c.birth.batch + 1, c.death.batch + 1, c.id});
  }
  after_ = IntervalTree(std::move(after));
  before_ = IntervalTree(std::move(before));
}

std::vector<CellId> ComplexIndex::after(std::uint64_t batch) const {
  std::vector<CellId> out;
  after_.stab(batch, out);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<CellId> ComplexIndex::before(std::uint64_t batch) const {
  std::vector<CellId> out;
  before_.stab(batch, out);
  std::sort(out.begin(), out.end());
  return out;
}

std::uint64_t ComplexIndex::frame_batch(std::size_t k) const { return medusa::frame_batch(medusa_, k); }

std::uint64_t frame_batch(const Medusa& m, std::size_t k) {
  const std::size_t frames = m.input.frames();
  if (k >= frames)
    throw InputError("medusa: frame " + std::to_string(k) + " is out of range (the run has " +
                     std::to_string(frames) + " frames)");
  if (k + 1 == frames)
    return m.end.batch;
  // Batches are in exact time order; frame k is reached after the batches of earlier slabs and after
  // its own frame batch (slab k, u = 0 exactly), before any other batch of slab k.
  std::uint64_t last = 0;
  bool found = false;
  for (const BatchRecord& b : m.batches) {
    if (b.slab < k || (b.slab == k && b.at_frame)) {
      last = b.batch;
      found = true;
    } else {
      break;
    }
  }
  if (!found)
    throw InternalError("medusa: no batch precedes frame " + std::to_string(k));
  return last;
}

std::vector<CellId> ComplexIndex::at_frame(std::size_t k) const {
  const std::uint64_t b = frame_batch(k);
  return k + 1 == medusa_.input.frames() ? before(b) : after(b);
}

std::vector<CellId> cells_at_frame(const Medusa& m, std::size_t k, std::optional<int> type) {
  const std::uint64_t b = frame_batch(m, k);
  const bool last = k + 1 == m.input.frames();
  std::vector<CellId> out;
  for (const Cell& c : m.cells) {
    // docs/MATH.md §6.6: K(b+) holds birth <= b < death, K(b-) birth < b <= death (in batches).
    const bool in = last ? c.birth.batch < b && b <= c.death.batch : c.birth.batch <= b && b < c.death.batch;
    if (in && (!type || m.has_type(c, *type)))
      out.push_back(c.id);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<CellId> ComplexIndex::at_time(double t) const {
  if (medusa_.batches.empty() || t < medusa_.batches.front().time)
    throw InputError("medusa: time " + std::to_string(t) + " is before the start of the run");
  if (t >= medusa_.end.time)
    return before(medusa_.end.batch);
  std::uint64_t last = medusa_.batches.front().batch;
  for (const BatchRecord& b : medusa_.batches) {
    if (b.time > t)
      break;
    last = b.batch;
  }
  return after(last);
}

} // namespace medusa
