// The answer at the top of `medusa report`, in plain words: for each cell type, its clusters (b0 of K_t
// at the frames, docs/MATH.md §6.6) at the first frame, whether and from when it is one cluster to the
// end, and when its clusters joined (the finite H0 classes of the forward filtration, docs/MATH.md
// §7.6); for each run, whether a type gathers into one cluster by the page's stated criterion.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace medusa::cli {

// The page's criterion, stated on it: a type gathers when it is in several clusters at the first frame
// and one cluster at every frame from some frame to the last.
struct TypeCourse {
  std::string text;                  // "7 clusters at MCS 0, one cluster from MCS 100 to the end (...)"
  std::optional<double> gathered_at; // the first frame of that last stretch, if the type gathers
  bool one_from_start = false;       // one cluster at every frame, the first included
  std::size_t first_clusters = 0;    // clusters at the first frame
  std::size_t last_clusters = 0;     // clusters at the last frame
};

// `times` the frame times, `b0` the clusters at each frame, `joins` the join times (increasing),
// `joined_at_first` the clusters of the first frame already joined to another in space-time through
// cells present at that frame only (ClusterFates::joined_at_first): their merges in the frames after
// it are no joins, and the text says so.
TypeCourse type_course(const std::vector<std::int64_t>& times, const std::vector<std::size_t>& b0,
                       const std::vector<double>& joins, std::size_t joined_at_first = 0);

// A type's cells at the last frame against its largest cluster there (clusters_apart.h computes it).
struct ClustersApart {
  std::size_t cells = 0;           // cells of the type in K at the frame
  std::size_t largest = 0;         // cells in its largest cluster
  bool tied = false;               // two clusters share the largest size: no cell is "apart"
  std::vector<std::int64_t> apart; // CC3D ids of the cells outside the largest cluster, increasing
  std::size_t others = 0;          // the clusters they are in (clusters at the frame, less the largest)
};

// "the largest holds 98 of its 99 cells; cell 166 is outside it", or "...; cells 44, 122, 174 and 215
// are outside it, in 3 other clusters", naming at most `named` cells (beyond
// them, or when the largest is tied, only the share); empty for a type in one cluster or without cells.
std::string clusters_apart_text(const ClustersApart& c, std::size_t named = 5);

struct TypeVerdictInput {
  std::string title; // "type 1 (Condensing)"
  TypeCourse course;
  std::string contacts; // "heterotypic contacts 0.667 → 0.268", from the first slice to the last
  std::string apart;    // clusters_apart_text at the last frame: said when the type does not gather
};

// "sorts: type 1 (Condensing) gathers into one cluster by MCS 100 and stays one to the end", or why
// not, for the run's types (the whole tissue left out). When no type gathers, the verdict says how far
// each got (clusters at the first and last frame, and its contacts) rather than only "no": a type that
// goes from 22 clusters to 2 while its heterotypic contacts fall has sorted most of the way.
std::string run_verdict(const std::vector<TypeVerdictInput>& types, const std::string& radius);

} // namespace medusa::cli
