// The plain-words summary `medusa run` prints: sizes, events, medusa cells per dimension, and the
// most persistent features of each cell type's forward diagram (docs/MATH.md §7.2, §7.4).
#pragma once

#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

void write_run_summary(std::ostream& out, const medusa::Medusa& medusa,
                       const kinetic::KineticStatistics& stats,
                       const std::vector<persistence::Diagram>& diagrams, const std::string& radius_text);

// One line per degree H0..H2 of a forward diagram in plain words; `dimension` is the run's (2 or 3):
// H2 is a cavity of the tissue in 3D, a bubble of space-time in the plane.
void describe_forward_diagram(std::ostream& out, const persistence::Diagram& diagram, double t0, double t_end,
                              int dimension);

} // namespace medusa::cli
