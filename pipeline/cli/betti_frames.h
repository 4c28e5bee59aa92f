// Betti numbers of the time slices K_t at the input frames (docs/MATH.md §6.6), for the whole complex
// and for each cell type's subcomplex (docs/MATH.md §7.4): what `medusa curves --frames-only` reports,
// shared by `medusa report` and `medusa sweep`.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/medusa/signatures.h"

#include <string>
#include <vector>

namespace medusa::cli {

struct TypeSlices {
  std::string label;               // "all" or the type id
  std::vector<Signature> at_frame; // one per input frame: the state reported at frame k
};

// Whole complex first, then the types in increasing order. Needs the medusa's batch and frame
// records (a store read with its events, or a collected medusa); polls for interrupts.
std::vector<TypeSlices> slices_at_frames(const Medusa& medusa);

} // namespace medusa::cli
