#include "ring_fate.h"

namespace medusa::cli {

const char* ring_state_name(RingFate::State state) {
  switch (state) {
  case RingFate::State::whole_at_end: return "whole at the end";
  case RingFate::State::broke: return "broke";
  case RingFate::State::never_whole: return "never whole";
  }
  return "";
}

RingFate ring_fate(const medusa::Medusa& medusa, persistence::CellLists::List cycle,
                   const medusa::VirtualTime& born) {
  // The first of its cells to leave: a cell alive at t_end dies at medusa.end (docs/MATH.md §6.2).
  const medusa::VirtualTime* first = nullptr;
  for (medusa::CellId id : cycle) {
    const medusa::VirtualTime& death = medusa.cell(id).death;
    if (!first || death < *first)
      first = &death;
  }
  RingFate fate;
  if (!first || *first == medusa.end)
    return fate;
  // All of its cells are present at `born` unless one left before (a temporal loop, §7.6).
  fate.state = *first < born ? RingFate::State::never_whole : RingFate::State::broke;
  fate.broke_at = first->time;
  return fate;
}

} // namespace medusa::cli
