// A plain-text serialisation of a diagram: one line per point, doubles in round-trip precision, so
// that equal diagrams give byte-identical text (determinism checks, exports).
#pragma once

#include "medusa/persistence/diagram.h"

#include <ostream>
#include <vector>

namespace medusa::persistence {

// Header line, then per point: dim birth death birth_batch birth_rank death_batch death_rank
// birth_index death_index birth_cell death_cell essential zero_length birth_vertices | death_vertices.
// `cells` is the cell vector the diagram was built from (for the vertex tuples).
void write_diagram_text(std::ostream& out, const Diagram& diagram, const std::vector<medusa::Cell>& cells);

} // namespace medusa::persistence
