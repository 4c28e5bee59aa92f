// The worked flip example of docs/MATH.md §B as an event stream: a = 0, b = 1, c = 2, d = 3, e = 4.
#pragma once

#include "stream.h"

namespace medusa::test {

inline constexpr double appendix_b_t_star = 96.7774;

inline Stream appendix_b_stream() {
  Stream s;
  s.t0 = event_time(0, 0.0, 0, 0.0, true);
  // K(t_0+): all finite simplices of abcd and abce.
  s.initial = closure({Simplex{0, 1, 2, 3}, Simplex{0, 1, 2, 4}});
  s.frames_after_initial = {0};
  Step flip;
  flip.rank = 1;
  flip.kind = kinetic::StepKind::flip23;
  flip.left = {Simplex{0, 1, 2}, Simplex{0, 1, 2, 3}, Simplex{0, 1, 2, 4}};
  flip.entered = {Simplex{3, 4},       Simplex{0, 3, 4},    Simplex{1, 3, 4},   Simplex{2, 3, 4},
                  Simplex{0, 1, 3, 4}, Simplex{1, 2, 3, 4}, Simplex{0, 2, 3, 4}};
  flip.flip = kinetic::FlipGroup{{0, 1, 2, 3, 4}, true};
  flip.delaunay_removed = {Simplex{0, 1, 2, 3}, Simplex{0, 1, 2, 4}};
  flip.delaunay_created = {Simplex{0, 1, 3, 4}, Simplex{1, 2, 3, 4}, Simplex{0, 2, 3, 4}};
  s.batches.push_back({event_time(1, appendix_b_t_star, 0, 0.967774389), {flip}, {}});
  s.t_end = event_time(2, 100.0, 1, 0.0, true);
  return s;
}

} // namespace medusa::test
