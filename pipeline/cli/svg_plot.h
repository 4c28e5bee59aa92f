// A persistence barcode as a standalone SVG: one horizontal bar per pair, grouped by diagram and
// degree, on the time axis [t0, t_end]; essential bars run to the axis end (forward) or start
// (reverse) and end in an arrow. max_bars > 0 draws only the max_bars longest bars of each degree of
// each diagram (the title says so): a large run has tens of thousands, which no viewer shows.
#pragma once

#include "medusa/persistence/diagram.h"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// What `medusa run` draws, and `medusa barcode --format svg` unless told otherwise.
constexpr std::size_t default_max_bars = 200;

// With a run id, the root element carries it as data-medusa-run (docs/FORMAT.md).
void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, double t0,
                       double t_end, std::size_t max_bars = 0, const std::string& run_id = "");

} // namespace medusa::cli
