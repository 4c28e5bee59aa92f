// Which diagrams of a medusa a command works on: direction, cell type, homology degree (docs/MATH.md
// §7.2-7.4), and computing them from the cells.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/diagram.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace medusa::cli {

struct DiagramSelection {
  std::string filtration = "both"; // forward, reverse or both
  // A cell type id or name, "all" for the whole medusa only; unset: the whole medusa and every type.
  std::optional<std::string> type;
  std::optional<int> dim;   // one homology degree, or all
  bool zero_length = false; // keep the zero-length pairs (same batch, on the diagonal)
  unsigned threads = 0;     // for the filtrations and reductions; 0: one per hardware thread
};

// Adds --filtration, --type, --dim, --zero-length and --threads to a subcommand.
void add_selection_options(CLI::App& command, DiagramSelection& selection);

// The check of a --type option before the store is read: not empty, and not "all" unless `all` is
// true. Whether it names a type of the run is resolve_cell_type's to say once the store is open.
CLI::Validator type_validator(bool all = true);

// The worker threads for a --threads value: 0 means one per hardware thread (at least 1).
unsigned worker_threads(unsigned requested);

// Vertex types of the stored input (index = vertex id) and the distinct types, increasing.
std::vector<int> vertex_types(const medusa::Medusa& medusa);
std::vector<int> distinct_types(const std::vector<int>& vertex_type);

// The diagrams of `medusa` that the selection asks for, in compute_medusa_diagrams order, with pairs
// of other degrees and (unless asked) zero-length pairs removed. A type the run does not have is an
// InputError naming `source`, the store.
std::vector<persistence::Diagram>
selected_diagrams(const medusa::Medusa& medusa, const DiagramSelection& selection, const std::string& source);

std::string direction_name(persistence::Direction direction);
// "all" for the whole medusa, else the type id.
std::string type_label(int cell_type);

} // namespace medusa::cli
