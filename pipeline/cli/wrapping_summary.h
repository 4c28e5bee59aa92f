// The summary's words on loops that wrap around a periodic domain (docs/MATH.md §8.8).
#pragma once

#include "medusa/medusa/medusa.h"

#include <ostream>
#include <string>

namespace medusa::cli {

// For a periodic run, one line saying how many loops of the forward diagram of all cells wrap around
// the domain along which axes (they are not holes in the tissue), from the representatives in the
// store at `store_path`; nothing for an open run.
void write_wrapping_loops(std::ostream& out, const medusa::Medusa& medusa, const std::string& store_path);

} // namespace medusa::cli
