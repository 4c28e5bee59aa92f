// The plain-words summary `medusa run` prints: sizes, events, medusa cells per dimension, and for the
// whole tissue and each cell type what became of its clusters, loops and cavities (class_fates.h;
// docs/MATH.md §6.6, §7.2-§7.6).
#pragma once

#include "class_fates.h"
#include "longest_classes.h"

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// `radius_note` says how the radius was chosen (--radius auto), if it was.
// `medusa` must hold its batches (read_store with events); `diagrams` are those of
// compute_medusa_diagrams (forward and reverse, whole medusa and each type), `from_cells` the
// fates_from_cells of each (InternalError if one is missing). Returns the warnings the
// run's radius calls for (no contact at any time; a type that is one cluster from the first frame with
// nothing joining it), one line each, for stderr. `longest` (longest_filled_classes) names the cells
// of the longest-lived filled loop and cavity of each type, with the commands that show them in the
// store `store`.
std::vector<std::string>
write_run_summary(std::ostream& out, const medusa::Medusa& medusa, const kinetic::KineticStatistics& stats,
                  const std::vector<persistence::Diagram>& diagrams,
                  const std::vector<FatesFromCells>& from_cells, const std::string& radius_text,
                  const std::string& radius_note = "", const std::vector<LongestFilled>& longest = {},
                  const std::string& store = "");

// The lines of write_run_summary for one forward diagram (the whole medusa or one type): clusters,
// loops and cavities and what became of them. `diagrams` must hold the reverse diagram of the same
// type; `medusa` must hold its batches.
void describe_forward_diagram(std::ostream& out, const medusa::Medusa& medusa,
                              const std::vector<persistence::Diagram>& diagrams,
                              const persistence::Diagram& forward);

} // namespace medusa::cli
