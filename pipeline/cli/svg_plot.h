// Persistence diagrams as standalone SVG pictures, one panel per diagram (cell type and direction)
// and homology degree, each with its own time axis in MCS:
//  * barcode: the finite bars, sorted by birth (a class born at MCS b and filled or joined at MCS d is
//    a bar from b to d); the essential classes (never filled, never joined) are counted in the
//    panel's title, not drawn. max_bars > 0 draws only the max_bars longest finite bars of a panel
//    (the title says so): a large run has tens of thousands, which no viewer shows.
//  * diagram: each finite class as a point (birth, death) above the diagonal, which is drawn; the
//    farther from the diagonal, the longer the class lived. Essential classes are counted in the title.
//    max_points > 0: a panel of more than max_points finite classes is drawn as a density instead,
//    squares of 3 pixels shaded by how many classes fall in each (the title says so), so that a run
//    of a million cells draws a picture of megabytes, not gigabytes.
// Reverse diagrams are drawn on the time axis too (born late, die earlier; docs/MATH.md §7.3).
// Panels and bars carry data-* attributes (type, direction, degree, counts, birth, death) for checks.
#pragma once

#include "cell_type.h"

#include "medusa/persistence/diagram.h"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// What `medusa run` draws, and `medusa barcode --format svg` unless told otherwise.
constexpr std::size_t default_max_bars = 200;
// What `medusa run` draws point by point in a diagram panel, and `medusa barcode --format diagram-svg`.
constexpr std::size_t default_max_points = 5000;

// Panels are titled with the types' names from `names` where the run has them. With a run id, the root
// element carries it as data-medusa-run (docs/FORMAT.md).
void write_barcode_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                       const TypeNames& names, double t0, double t_end, std::size_t max_bars = 0,
                       const std::string& run_id = "");

void write_diagram_svg(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                       const TypeNames& names, double t0, double t_end, std::size_t max_points = 0,
                       const std::string& run_id = "");

} // namespace medusa::cli
