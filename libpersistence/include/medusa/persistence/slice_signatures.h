// Betti numbers of every time slice K_t of a medusa from one persistence reduction of a coned
// filtration (docs/MATH.md §6.8): the signatures of docs/MATH.md §6.6 in O(reduction of 2N+1 columns)
// instead of one reduction per batch.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/medusa/signatures.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace medusa::persistence {

// The time slice made of the cells with birth batch < born_before and death batch >= dies_from
// (docs/MATH.md §6.6: K(b+) is {b+1, b+1}, K(b-) is {b, b}). Needs born_before >= dies_from.
struct SliceBounds {
  std::uint64_t born_before = 0;
  std::uint64_t dies_from = 0;
};

// Simplex counts, Euler characteristic and Betti numbers over Z/2 of each slice of the cells c with
// member[c.id] != 0 (member empty: every cell), which must be closed under facets. The slices must be
// in time order (born_before and dies_from non-decreasing). `poll` is called between stages and
// every few thousand steps, so a caller can stop by throwing. Throws InternalError when the counts
// contradict each other (Euler characteristic, or more than one essential class of the cone).
std::vector<Signature> slice_signatures(const std::vector<Cell>& cells, const std::vector<char>& member,
                                        const std::vector<SliceBounds>& slices,
                                        const std::function<void()>& poll = {});

// The same samples as medusa::signatures_over_time (after every batch and K(t_end-), with the frames
// each one reports), computed by slice_signatures; `type` selects the sub-medusa M_X (docs/MATH.md §7.4).
std::vector<SignatureSample> signatures_by_reduction(const Medusa& medusa, std::optional<int> type,
                                                     const std::function<void()>& poll = {});

} // namespace medusa::persistence
