// "At which radius?" in `medusa report`: the radius sweep of each store (the CROCKER data of
// `medusa sweep`, docs/MATH.md §6.6), read from a `medusa sweep` file beside the store or computed at
// report time from the trajectories the store keeps, and what it says: per type, at which radii the
// type joins into one cluster during the run, and at which radii the runs differ.
#pragma once

#include "crocker.h"
#include "report_html.h"
#include "report_model.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace medusa::cli {

// Above this many event times a run's default radius sweep (nine reruns of its kinetic stage) is not
// computed at report time: about 9 million events, several minutes on one core.
constexpr std::size_t default_max_sweep_events = 1'000'000;

struct ScaleOptions {
  std::vector<std::string> stores; // the stores, in the order of the runs
  std::vector<std::string> given;  // more CROCKER CSVs of `medusa sweep`
  bool no_sweep = false;           // compute no sweep at report time
  std::vector<std::string> radii;  // radii to sweep at (empty: default_sweep_radii)
  unsigned threads = 0;            // 0: one per hardware thread
  // The default sweep is computed only for runs of at most this many event times (0: any run); the
  // radii given with --sweep-radii are always computed.
  std::size_t max_sweep_events = default_max_sweep_events;
  bool quiet = false; // no progress on stderr
};

// The default radii: r/2 to 3r/2 in steps of r/8 (nine radii), r the given radius, each rounded to
// 0.01 lattice units (exact decimal arithmetic; why this span: docs/MATH.md §7.10); radii that round
// to 0 are left out.
std::vector<std::string> default_sweep_radii(const std::string& radius_text);

struct ScaleSection {
  std::vector<ReportFigure> figures; // the CROCKER plots
  // Per sweep: {name, run, origin, times, radii, types: [{label, name, first, last, betti}]}
  nlohmann::ordered_json sweeps = nlohmann::ordered_json::array();
  // {how, radii, statements: [{label, name, text, radii}]}: the runs compared over their common radii
  nlohmann::ordered_json scale = nlohmann::ordered_json::object();
};

// Adds to each run's data its "scale" lines (per type, at which swept radii it joins into one
// cluster). Polls for interrupts (throws Interrupted).
ScaleSection report_scale(std::vector<ReportRun>& runs, const ScaleOptions& options);

} // namespace medusa::cli
