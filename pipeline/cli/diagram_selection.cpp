#include "diagram_selection.h"
#include "cell_type.h"
#include "interrupt.h"

#include "medusa/core/error.h"
#include "medusa/persistence/medusa_diagrams.h"

#include <algorithm>
#include <thread>

namespace medusa::cli {

unsigned worker_threads(unsigned requested) {
  return requested > 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

CLI::Validator type_validator(bool all) {
  return CLI::Validator(
      [all](std::string& value) {
        // A name is checked against the store's types once it is open (resolve_cell_type).
        if (value.empty())
          return std::string("a cell type is its id or its name, as `medusa info <store>` lists them") +
                 (all ? ", or 'all'" : "");
        if (!all && value == "all")
          return std::string("'all' is no cell type here: leave out --type for every cell");
        return std::string();
      },
      "TYPE");
}

void add_selection_options(CLI::App& command, DiagramSelection& selection) {
  command
      .add_option("--filtration", selection.filtration, "forward, reverse or both (docs/MATH.md §7.2, §7.3)")
      ->check(CLI::IsMember({"forward", "reverse", "both"}))
      ->capture_default_str();
  command
      .add_option(
          "--type", selection.type,
          "only the sub-medusa of this cell type, by id or name as `medusa info` lists them (docs/MATH.md "
          "§7.4), or 'all' for the whole medusa only")
      ->check(type_validator());
  command.add_option("--dim", selection.dim, "only this homology degree")->check(CLI::Range(0, 3));
  command.add_flag("--zero-length", selection.zero_length,
                   "keep zero-length pairs (birth and death in the same batch)");
  command
      .add_option("--threads", selection.threads,
                  "threads for the filtrations and reductions (0: one per hardware thread; the result "
                  "does not depend on it)")
      ->capture_default_str();
}

std::vector<int> vertex_types(const medusa::Medusa& medusa) {
  std::vector<int> types;
  types.reserve(medusa.input.cells.size());
  for (const kinetic::Trajectory& t : medusa.input.cells)
    types.push_back(t.type);
  return types;
}

std::vector<int> distinct_types(const std::vector<int>& vertex_type) {
  std::vector<int> types = vertex_type;
  std::sort(types.begin(), types.end());
  types.erase(std::unique(types.begin(), types.end()), types.end());
  return types;
}

std::vector<persistence::Diagram> selected_diagrams(const medusa::Medusa& medusa,
                                                    const DiagramSelection& selection,
                                                    const std::string& source) {
  const std::vector<int> vertex_type = vertex_types(medusa);
  std::vector<int> types = distinct_types(vertex_type);
  std::optional<int> wanted; // the one diagram type asked for (all_types: the whole medusa)
  if (selection.type) {
    wanted = resolve_cell_type(*selection.type, medusa.input, source);
    types = *wanted == persistence::all_types ? std::vector<int>{} : std::vector<int>{*wanted};
  }
  persistence::DiagramRunOptions options;
  options.threads = worker_threads(selection.threads);
  options.poll = check_interrupted;
  std::vector<persistence::Diagram> all =
      persistence::compute_medusa_diagrams(medusa.cells, vertex_type, types, options);
  std::vector<persistence::Diagram> chosen;
  for (persistence::Diagram& d : all) {
    if (wanted && d.cell_type != *wanted)
      continue;
    if (selection.filtration != "both" && direction_name(d.direction) != selection.filtration)
      continue;
    std::vector<persistence::PersistencePair> kept;
    for (persistence::PersistencePair& p : d.pairs)
      if ((!selection.dim || p.dim == *selection.dim) && (selection.zero_length || !p.zero_length))
        kept.push_back(std::move(p));
    d.pairs = std::move(kept);
    chosen.push_back(std::move(d));
  }
  return chosen;
}

std::string direction_name(persistence::Direction direction) {
  return direction == persistence::Direction::forward ? "forward" : "reverse";
}

std::string type_label(int cell_type) {
  return cell_type == persistence::all_types ? "all" : std::to_string(cell_type);
}

} // namespace medusa::cli
