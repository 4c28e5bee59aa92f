// What `medusa report` shows of one store: run facts, the summary of `medusa run`, a headline per cell
// type, the Betti numbers of K_t at the frames, and the forward diagrams' pairs with the CC3D cell ids
// of the cells that formed and killed each class. Serialised as JSON into the report page.
#pragma once

#include "medusa/kinetic/trajectories.h"
#include "medusa/medusa/run_info.h"
#include "medusa/persistence/points.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace medusa::cli {

struct ReportRun {
  std::string name;            // shown in the page
  nlohmann::ordered_json data; // name, path, facts, summary, headlines, verdict, frame_times, slices, panels
  // H0 of the forward filtration on the normalised time axis (docs/MATH.md §7.7), per type label
  // ("all", "1", ...), for the distances between runs.
  std::vector<std::pair<std::string, persistence::PointDiagram>> h0_points;
  int dimension = 3;
  // The event times of its kinetic stage (the store's batch records): what a radius sweep costs, about
  // that many per radius.
  std::size_t event_times = 0;
  // The store's trajectories and run record: the radius sweep of the report reruns the kinetic stage
  // on them.
  kinetic::Trajectories input;
  medusa::RunInfo run_info;
};

// Reads `store` (with its events), computes its diagrams on `threads` threads and the Betti numbers
// of K_t at its frames. Each panel (type x degree) keeps the `max_bars` longest pairs (essential
// classes first; 0 = all) and records how many it has in all. Polls for interrupts.
ReportRun report_run(const std::string& store, const std::string& name, std::size_t max_bars,
                     unsigned threads);

// mixed_dimensions_note (comparison.h) of the runs: "" unless some are planar and some 3D.
std::string mixed_dimensions_note(const std::vector<ReportRun>& runs);

} // namespace medusa::cli
