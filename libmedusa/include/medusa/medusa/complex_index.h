// K_t from a medusa: stabbing queries over the cell lifetimes (docs/MATH.md §6.6).
#pragma once

#include "medusa/medusa/interval_tree.h"
#include "medusa/medusa/medusa.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace medusa {

// Answers "which cells form K at this time" for a whole medusa or for the sub-medusa of one cell type
// (docs/MATH.md §7.4). Conventions of docs/MATH.md §6.6: at batch b, K(b+) = cells with birth <= (b, +inf) <
// death, i.e. birth batch <= b < death batch; K(b-) = cells with birth < (b, 0) <= death, i.e. birth
// batch < b <= death batch. Instant cells belong to neither. The medusa must outlive the index.
class ComplexIndex {
public:
  explicit ComplexIndex(const Medusa& medusa, std::optional<int> type = std::nullopt);

  // Cell ids, increasing.
  std::vector<CellId> after(std::uint64_t batch) const;  // K(b+)
  std::vector<CellId> before(std::uint64_t batch) const; // K(b-)
  // The state reported at frame k (docs/MATH.md §0): K(t_k+) for k before the last frame, and
  // K(t_end-) at the last frame. Needs the input's frame count; throws InputError when out of range.
  std::vector<CellId> at_frame(std::size_t k) const;
  // The batch after which frame k is reached: its frame batch, or the last batch before it.
  std::uint64_t frame_batch(std::size_t k) const;
  // The state at real time t: K(t+) after the last batch whose (approximate) time is <= t, or
  // K(t_end-) at t >= t_end. Throws InputError for t before t_0.
  std::vector<CellId> at_time(double t) const;

  const Medusa& medusa() const { return medusa_; }
  std::optional<int> type() const { return type_; }

private:
  const Medusa& medusa_;
  std::optional<int> type_;
  IntervalTree after_;
  IntervalTree before_;
};

// The batch after which frame k is reached (ComplexIndex::frame_batch without an index).
std::uint64_t frame_batch(const Medusa& medusa, std::size_t k);

// ComplexIndex::at_frame without an index: one pass over the cells. For a query or two it is cheaper
// than the index, and it holds nothing but the answer (the index of a million-cell run is gigabytes).
std::vector<CellId> cells_at_frame(const Medusa& medusa, std::size_t k,
                                   std::optional<int> type = std::nullopt);

} // namespace medusa
