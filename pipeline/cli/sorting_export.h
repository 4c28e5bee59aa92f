// The classical sorting measures of `medusa curves` (docs/MATH.md §6.9) as CSV and as SVG panels.
#pragma once

#include "curve_plot.h"

#include "medusa/medusa/sorting_measures.h"

#include <ostream>
#include <vector>

namespace medusa::cli {

// One row per sample and per label (all, then each type): docs/FORMAT.md, "run.sorting.csv".
void write_sorting_csv(std::ostream& out, const std::vector<medusa::SortingSample>& samples);

// One panel per quantity (heterotypic fraction, same-type fraction, clusters, largest cluster, mean
// cluster size), one curve per label, thinned to a few samples per pixel column of [t0, t_end].
std::vector<CurvePanel> sorting_panels(const std::vector<medusa::SortingSample>& samples, double t0,
                                       double t_end);

} // namespace medusa::cli
