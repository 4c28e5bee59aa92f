// The batches and frames of a run as the medusa records them (docs/MATH.md §5.2, §5.6, §6.2).
#pragma once

#include <cstddef>
#include <cstdint>

namespace medusa {

// One batch of the event stream: every event at one exact time. Batch 0 is t_0.
struct BatchRecord {
  std::uint64_t batch = 0;
  std::uint64_t slab = 0;  // slab k: t in [t_k, t_{k+1}]
  double u = 0.0;          // double approximation of the slab parameter
  double time = 0.0;       // double approximation of the exact time
  bool at_frame = false;   // u = 0 exactly: a frame batch (docs/MATH.md §5.6)
  std::uint32_t ranks = 0; // number of steps (highest rank); 0 for batch 0
};

// Frame k reached, after its frame batch if it has one.
struct FrameRecord {
  std::uint64_t frame = 0;
  std::uint64_t batch = 0; // EventTime::batch reported with the frame
  double time = 0.0;
};

} // namespace medusa
