// What became of the cells of an essential loop's or cavity's representative (docs/MATH.md §7.6): the
// class is never filled, since the forward filtration keeps the past, but the ring or shell of cells
// it is listed with can still be whole at the end, have broken open at some time, or never have been
// whole at one time (a loop in space-time). A statement about those cells, not about the class: another
// cycle of the same class can outlive this one.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/cell_lists.h"
#include "medusa/persistence/class_records.h"

#include <limits>

namespace medusa::cli {

struct RingFate {
  enum class State { whole_at_end, broke, never_whole };
  State state = State::whole_at_end;
  double broke_at = 0; // MCS at which the first of its cells left (State::broke)
};

// `cycle`: the representative's cells; `born`: the class's birth, the birth of its last cell.
// "whole at the end", "broke" or "never whole", as `medusa classes --format json` and the report write it.
const char* ring_state_name(RingFate::State state);

RingFate ring_fate(const medusa::Medusa& medusa, persistence::CellLists::List cycle,
                   const medusa::VirtualTime& born);

// The order of essential loops and cavities, whose lifetimes are all infinite, in a list of the
// longest-lived: how long the ring or shell stayed whole after the class's `birth` (MCS). +inf when it
// is whole at the end, broke_at - birth when it broke, -inf when it was never whole. A ring that broke
// open soon after it formed is not what a reader of "longest-lived" is looking for, though the class
// lives on in the space-time medusa.
double ring_whole_for(const RingFate& fate, double birth);

// ring_whole_for of an essential class of the forward filtration in degree `dim`, its representative
// `cycle` born at `birth` (MCS) in medusa cell `birth_cell`: a cluster that never joins an older one
// (degree 0) ranks with the rings whole at the end.
double essential_order(const medusa::Medusa& medusa, int dim, persistence::CellLists::List cycle,
                       medusa::CellId birth_cell, double birth);

// How long a class of the forward filtration was seen in the tissue, the order of the report's tables
// and of `medusa classes --sort seen`: a filled cluster, loop or cavity its lifetime; a never-filled one
// the time after its birth until its ring or shell broke open (essential_order), or until the end of the
// run `t_end`; -inf for one never whole at one time (a loop of space-time only).
double time_seen(bool essential, double lifetime, double essential_order, double birth, double t_end);

// Was a class with this time_seen never whole at one time (seen -inf)? The outputs write it so
// ("never whole", an empty CSV field, null), not as a time.
inline bool never_whole(double seen) { return seen == -std::numeric_limits<double>::infinity(); }

// time_seen of a class of the forward filtration.
double time_seen(const medusa::Medusa& medusa, const persistence::ClassRecord& record);

} // namespace medusa::cli
