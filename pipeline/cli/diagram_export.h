// Diagram exports: plain text pairs, GUDHI .pers, CSV and JSON.
#pragma once

#include "cell_type.h"

#include "medusa/persistence/diagram.h"

#include <ostream>
#include <string>
#include <vector>

namespace medusa::cli {

// A time as text: round-trip precision, "inf" / "-inf" for essential classes.
std::string format_time(double t);

// A CSV field as RFC 4180 writes it: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

// `birth death dim` per pair, with a comment line naming each diagram ("# type 1 (Condensing), forward,
// ...": the type's name from `names` where the run has one).
void write_pairs_text(std::ostream& out, const std::vector<persistence::Diagram>& diagrams,
                      const TypeNames& names);
// GUDHI's .pers layout: `dim birth death` per pair, nothing else.
void write_pers(std::ostream& out, const std::vector<persistence::Diagram>& diagrams);
// Header `birth,death,dimension,type,direction,type_name`, one row per pair; type is "all" or the type
// id, type_name the type's name in the run ("" for all and for a type without one). With a run id, a
// first line `# medusa run <id>` names the store the pairs come from (docs/FORMAT.md).
void write_csv(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, const TypeNames& names,
               const std::string& run_id = "");
// {"diagrams": [{"type", "type_name", "direction", "pairs": [{"dimension", "birth", "death"}]}]};
// infinite deaths are the strings "inf" / "-inf" (JSON has no infinity).
void write_json(std::ostream& out, const std::vector<persistence::Diagram>& diagrams, const TypeNames& names);

} // namespace medusa::cli
