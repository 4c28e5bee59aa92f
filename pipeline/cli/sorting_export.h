// The classical sorting measures of `medusa curves` (docs/MATH.md §6.9) as CSV and as SVG panels.
#pragma once

#include "cell_type.h"
#include "curve_plot.h"

#include "medusa/medusa/sorting_measures.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// One row per sample and per label (all, then each type), the type's name last: docs/FORMAT.md,
// "run.sorting.csv".
void write_sorting_csv(std::ostream& out, const std::vector<medusa::SortingSample>& samples,
                       const TypeNames& names);

// One panel per quantity (heterotypic fraction, same-type fraction, clusters, largest cluster, mean
// cluster size), one curve per label named as cell_type_title names it, thinned to a few samples per
// pixel column of [t0, t_end].
std::vector<CurvePanel> sorting_panels(const std::vector<medusa::SortingSample>& samples, double t0,
                                       double t_end, const TypeNames& names);

// "heterotypic contacts 0.670 -> 0.537, same-type neighbours 0.498 -> 0.633": the two fractions from
// `first` to `last` (three decimals, "n/a" without a denominator), joined by `arrow`.
std::string contact_fractions(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                              const std::string& arrow);

// "largest cluster 44 of 48 -> 93 of 93 cells": how much of the type (the tissue) its largest cluster
// holds, from `first` to `last`; a type nearly one cluster from the start gathers with little sorting.
std::string largest_cluster_share(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                                  const std::string& arrow);

// Its first half: "heterotypic contacts 0.670 -> 0.537".
std::string heterotypic_contacts(const medusa::SortingMeasures& first, const medusa::SortingMeasures& last,
                                 const std::string& arrow);

} // namespace medusa::cli
