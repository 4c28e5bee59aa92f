// What `medusa compare` compares: one diagram per store (one cell type, homology degree and
// filtration direction), as points on the normalised time axis of docs/MATH.md §7.7, and the metric.
#pragma once

#include "medusa/kinetic/trajectories.h"
#include "medusa/persistence/distance.h"
#include "medusa/persistence/distance_matrix.h"
#include "medusa/persistence/points.h"

#include <mutex>
#include <string>
#include <vector>

namespace medusa::cli {

struct ComparedDiagram {
  std::string name; // the store's file name without folder and `.h5`
  persistence::PointDiagram points;
  double t0 = 0, t_end = 0; // the run's first and last frame time (MCS) before normalisation
  int dimension = 3;        // 2 for a planar run
};

struct ComparisonSelection {
  std::string type = "all"; // a cell type id or name, or "all" (the whole medusa)
  int dim = 0;
  std::string filtration = "forward";
};

// Reads `store`, computes its diagrams (docs/MATH.md §7.2-§7.4) and returns the selected one mapped to points
// (reverse diagrams to -t, docs/MATH.md §7.3) with the time normalisation t -> (t - t0) / (t_end - t0).
// InputError if the type (an id or name, resolved in this store) has no cells in it.
ComparedDiagram compared_diagram(const std::string& store, const ComparisonSelection& selection);

// The same for several selections of one filtration direction, from one reading of the store and one
// computation of its diagrams; one result per selection, in order.
std::vector<ComparedDiagram> compared_diagrams(const std::string& store,
                                               const std::vector<ComparisonSelection>& selections);

// What compare reads of each run before it computes anything: its cells (their types and the types'
// names) and the radius it was analysed at.
struct RunFacts {
  kinetic::Trajectories input;
  std::string radius; // as the store records it (the decimal text given, or the automatic radius)
  double radius_value = 0;
};
RunFacts read_run_facts(const std::string& store);

// Warnings about runs compared as if alike when they may not be: a type id compared by id that the
// runs name differently (the runs' own names for the selections' ids), and radii more than 5% apart.
std::vector<std::string> comparability_warnings(const std::vector<std::string>& names,
                                                const std::vector<RunFacts>& runs,
                                                const std::vector<ComparisonSelection>& selections);

// Unique run names: file stems, or the paths as given when two stems coincide.
std::vector<std::string> run_names(const std::vector<std::string>& stores);

// "bottleneck" or "wasserstein:p" (p >= 1), with the essential classes counted (+inf when their
// numbers differ) unless ignored. Safe to call from several threads; records the largest certified
// relative error of an approximate Wasserstein finite part.
class ComparisonMetric {
public:
  // Throws InputError for an unknown metric or p < 1.
  ComparisonMetric(const std::string& spec, bool ignore_essential);
  double operator()(const persistence::PointDiagram& a, const persistence::PointDiagram& b) const;

  std::string description() const;
  // What a distance means, in words, for the terminal: what 0 means, and for the bottleneck distance
  // what a value d says about the matching of classes (docs/MATH.md §7.7).
  std::string reading() const;
  double largest_relative_error() const;

private:
  bool wasserstein_ = false;
  double p_ = 1.0;
  std::string p_text_;
  bool ignore_essential_ = false;
  mutable std::mutex mutex_;
  mutable double relative_error_ = 0;
};

// Checks a metric spec for the command line: empty string if valid, else the reason.
std::string metric_spec_error(const std::string& spec);

// "" when the runs (names[i] of dimension dimensions[i]) all have one dimension; otherwise which are
// planar and which 3D, and what that means for comparing them (said by `medusa compare` and `report`).
std::string mixed_dimensions_note(const std::vector<std::string>& names, const std::vector<int>& dimensions);

} // namespace medusa::cli
