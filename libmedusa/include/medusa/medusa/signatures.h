// Signatures of K_t over time (docs/MATH.md §6.6): simplex counts, Euler characteristic and Betti
// numbers, for the whole complex and per cell type.
#pragma once

#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/medusa.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace medusa {

struct Signature {
  std::array<std::size_t, 4> f{};     // simplices of dimension 0..3
  long long euler = 0;                // f0 - f1 + f2 - f3
  std::array<std::size_t, 4> betti{}; // over Z/2
};

// The signature of a set of cells that is a complex (every facet of a member is a member), as
// returned by ComplexIndex. Throws InternalError if a facet is missing or a cell has dimension > 3.
// `poll` is called every few thousand cells (betti_numbers), so a caller can stop by throwing.
Signature signature_of(const Medusa& medusa, const std::vector<CellId>& cells,
                       const std::function<void()>& poll = {});

// One sample of the piecewise constant signature: K(batch+) after a batch, or K(t_end-) at the end.
struct SignatureSample {
  std::uint64_t batch = 0;
  bool before = false; // true only for the final sample K(t_end-)
  double time = 0.0;
  std::vector<std::size_t> frames; // the frames whose reported state this is
  Signature signature;
};

// Samples after every batch and at t_end: the signature changes only at batches (6.6), so these are
// all its values; every frame maps to one sample.
std::vector<SignatureSample> signatures_over_time(const ComplexIndex& index);

// Fills the frames of samples laid out as signatures_over_time lays them out (one per batch of the
// medusa in order, then K(t_end-)): frame k goes to the sample of its frame batch, the last frame to
// the final sample. Throws InternalError when a frame maps to no batch.
void assign_frames(const Medusa& medusa, std::vector<SignatureSample>& samples);

} // namespace medusa
