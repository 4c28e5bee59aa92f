// Which classes of the whole space-time medusa the last frame's complex carries beyond those the first
// frame's complex carries (docs/MATH.md §7.12): the count that splits the loops and cavities still open
// at the end into those present at the first frame and those formed later.
#pragma once

#include "medusa/medusa/cell.h"
#include "medusa/persistence/diagram.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace medusa::persistence {

// For k = 1, 2 (index 0 unused): the rank of H_k(L_end) -> H_k(M, L_first) over Z/2, where M is the
// cells c with member[c.id] != 0 (member empty: every cell), L_first the cells of M born at a batch
// <= first_batch (a prefix of the forward filtration) and L_end those dying at a batch >= end_batch
// (a prefix of the reverse filtration). With A and B the images of H_k(L_first) and H_k(L_end) in
// H_k(M), it is dim B - dim(A ∩ B). Cell ids must be their positions in `cells`. One PHAT reduction of
// M with the cone on L_first (docs/MATH.md §7.12); throws InternalError for cells that are not closed
// under facets. `poll` is called every few thousand columns of the reduction, so a caller can stop it
// by throwing.
std::array<std::size_t, 3> end_classes_beyond_first(const std::vector<medusa::Cell>& cells,
                                                    const std::vector<char>& member,
                                                    std::uint64_t first_batch, std::uint64_t end_batch,
                                                    const std::function<void()>& poll = {});

// Loops (k = 1) or cavities (k = 2) of one (sub-)medusa, each of its three fates split by whether the
// class was present at the first frame or formed later (docs/MATH.md §7.12). Filled: the finite
// positive-length pairs of the forward diagram, by birth. Never filled: the essential classes, a basis
// of H_k(M); present at the first frame are the dim A of them born at or before the first frame's batch.
// Still open at the end: the dim B classes the end complex carries (essential classes of the reverse
// diagram born at the end), of which dim(A ∩ B) were present at the first frame. Broke open: the
// never-filled classes not still open, dim A - dim(A ∩ B) of them present at the first frame.
struct HoleFates {
  std::size_t filled_initial = 0, filled_formed = 0;
  std::size_t never_filled_initial = 0, never_filled_formed = 0;
  std::size_t still_open_initial = 0, still_open_formed = 0;
  std::size_t broken_open_initial = 0, broken_open_formed = 0;

  std::size_t initial() const { return filled_initial + never_filled_initial; }
  std::size_t formed() const { return filled_formed + never_filled_formed; }
  std::size_t still_open() const { return still_open_initial + still_open_formed; }
  std::size_t broken_open() const { return broken_open_initial + broken_open_formed; }
};

// The fates of degrees 1 and 2 (index 0 unused) from the forward and reverse diagrams of the cells
// selected by `member` (as in end_classes_beyond_first; the diagrams may hold zero-length pairs or
// not) and one reduction of end_classes_beyond_first. `first_batch` is the batch that reaches the first
// frame, `end_batch` the final one. Throws InternalError when the counts contradict each other.
std::array<HoleFates, 3> hole_fates(const std::vector<medusa::Cell>& cells, const std::vector<char>& member,
                                    const Diagram& forward, const Diagram& reverse, std::uint64_t first_batch,
                                    std::uint64_t end_batch, const std::function<void()>& poll = {});

// The same with end_classes_beyond_first's ranks `beyond` already computed for these cells and batches:
// a caller can reduce the coned medusa before it holds the diagrams, whose pairs would otherwise sit in
// memory beside that reduction.
std::array<HoleFates, 3> hole_fates(const Diagram& forward, const Diagram& reverse, std::uint64_t first_batch,
                                    std::uint64_t end_batch, const std::array<std::size_t, 3>& beyond);

} // namespace medusa::persistence
