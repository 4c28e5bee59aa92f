// New cells' ids. A cell's facet list holds ids in 32 bits (cell.h), so the builder refuses a run
// whose medusa would pass max_cell_count cells rather than let an id wrap onto another cell.
#pragma once

#include "medusa/core/error.h"
#include "medusa/medusa/cell.h"

#include <string>

namespace medusa {

// The id for a new cell, advancing `next`; InputError once every id a medusa holds is taken.
inline CellId take_cell_id(CellId& next) {
  if (next >= max_cell_count)
    throw InputError("the run makes more than " + std::to_string(max_cell_count) +
                     " medusa cells, the most a medusa holds");
  return next++;
}

} // namespace medusa
