// Diagram exports: plain text pairs, GUDHI .pers, CSV and JSON.
#pragma once

#include "medusa/persistence/diagram.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// A time as text: round-trip precision, "inf" / "-inf" for essential classes.
std::string format_time(double t);

// `birth death dim` per pair, with a comment line naming each diagram.
void write_pairs_text(std::ostream& out, const std::vector<persistence::Diagram>& diagrams);
// GUDHI's .pers layout: `dim birth death` per pair, nothing else.
void write_pers(std::ostream& out, const std::vector<persistence::Diagram>& diagrams);
// Header `birth,death,dimension,type,direction`, one row per pair; type is "all" or the type id. With
// a run id, a first line `# medusa run <id>` names the store the pairs come from (docs/FORMAT.md).
void write_csv(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
               const std::string& run_id = "");
// {"diagrams": [{"type", "direction", "pairs": [{"dimension", "birth", "death"}]}]}; infinite
// deaths are the strings "inf" / "-inf" (JSON has no infinity).
void write_json(std::ostream& out, const std::vector<persistence::Diagram>& diagrams);

} // namespace medusa::cli
