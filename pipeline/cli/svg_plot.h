// A persistence barcode as a standalone SVG: one horizontal bar per pair, grouped by diagram and
// degree, on the time axis [t0, t_end]; essential bars run to the axis end (forward) or start
// (reverse) and end in an arrow.
#pragma once

#include "medusa/persistence/diagram.h"

#include <ostream>
#include <vector>

namespace medusa::cli {

void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, double t0,
                       double t_end);

} // namespace medusa::cli
