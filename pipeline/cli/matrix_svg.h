// Standalone SVG pictures of a comparison (docs/MATH.md §7.7): the distance matrix as a heatmap and its
// hierarchical clustering as a dendrogram. Infinite distances (different numbers of essential classes)
// are drawn apart: hatched grey cells, merges on a separate "inf" level above the finite ones.
#pragma once

#include "medusa/persistence/clustering.h"
#include "medusa/persistence/distance_matrix.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

void write_heatmap_svg(std::ostream& out, const persistence::DistanceMatrix& distances,
                       const std::vector<std::string>& names, const std::string& title);

void write_dendrogram_svg(std::ostream& out, const persistence::Dendrogram& dendrogram,
                          const std::vector<std::string>& names, const std::string& title);

// The leaves in the left-to-right order of the dendrogram (first subtree before second).
std::vector<std::size_t> leaf_order(const persistence::Dendrogram& dendrogram);

// Escapes &, <, > and " for SVG text and attributes.
std::string xml_escape(const std::string& text);

} // namespace medusa::cli
