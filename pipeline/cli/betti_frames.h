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

// One sample per frame, at the frame's time: the sample reported at frame k (docs/MATH.md §6.6), which
// is that after the last batch at or before t_k (K(t_end-) for the last frame). Sample: a
// SignatureSample or a SortingSample over every batch. At the first frame this leaves out the cells
// present at t_0 alone, as the Betti numbers of slices_at_frames do.
template <class Sample>
std::vector<Sample> frame_samples(const std::vector<Sample>& samples, const kinetic::Trajectories& input) {
  std::vector<Sample> by_frame(input.frames());
  for (const Sample& s : samples)
    for (std::size_t k : s.frames) {
      by_frame.at(k) = s;
      by_frame[k].time = static_cast<double>(input.frame_times[k]);
      by_frame[k].frames = {k};
    }
  return by_frame;
}

} // namespace medusa::cli
