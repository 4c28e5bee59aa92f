#include "ring_fate.h"

#include <algorithm>
#include <limits>

namespace medusa::cli {

const char* ring_state_name(RingFate::State state) {
  switch (state) {
  case RingFate::State::whole_at_end: return "whole at the end";
  case RingFate::State::broke: return "broke";
  case RingFate::State::never_whole: return "never whole";
  }
  return "";
}

double ring_whole_for(const RingFate& fate, double birth) {
  switch (fate.state) {
  case RingFate::State::whole_at_end: return std::numeric_limits<double>::infinity();
  case RingFate::State::broke: return fate.broke_at - birth;
  case RingFate::State::never_whole: return -std::numeric_limits<double>::infinity();
  }
  return 0;
}

double time_seen(bool essential, double lifetime, double essential_order, double birth, double t_end) {
  return essential ? std::min(essential_order, t_end - birth) : lifetime;
}

double time_seen(const medusa::Medusa& medusa, const persistence::ClassRecord& r) {
  const double t_end =
      medusa.input.frame_times.empty() ? 0.0 : static_cast<double>(medusa.input.frame_times.back());
  const double order = r.essential ? essential_order(medusa, r.dim, persistence::CellLists::List(r.cycle),
                                                     r.birth_cell, r.birth)
                                   : 0.0;
  return time_seen(r.essential, r.lifetime(), order, r.birth, t_end);
}

double essential_order(const medusa::Medusa& medusa, int dim, persistence::CellLists::List cycle,
                       medusa::CellId birth_cell, double birth) {
  if (dim == 0)
    return std::numeric_limits<double>::infinity();
  return ring_whole_for(ring_fate(medusa, cycle, medusa.cell(birth_cell).birth), birth);
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
