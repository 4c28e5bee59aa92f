#include "medusa/persistence/class_records.h"

#include "medusa/core/error.h"
#include "medusa/persistence/class_store.h"
#include "medusa/persistence/diagram_store.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace medusa::persistence {
namespace {

std::vector<std::int64_t> cc3d_ids(const medusa::Medusa& medusa, const medusa::Cell& cell) {
  std::vector<std::int64_t> ids;
  for (kinetic::VertexId v : cell.vertices)
    ids.push_back(medusa.input.cells.at(static_cast<std::size_t>(v)).cell_id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::string diagram_name(Direction direction, int cell_type) {
  Diagram d;
  d.direction = direction;
  d.cell_type = cell_type;
  return diagram_group_name(d);
}

Filtration filtration_of(const medusa::Medusa& medusa, const std::vector<int>& vertex_type,
                         Direction direction, int cell_type) {
  return cell_type == all_types ? make_filtration(medusa.cells, direction)
                                : make_type_filtration(medusa.cells, vertex_type, cell_type, direction);
}

} // namespace

double ClassRecord::lifetime() const {
  return essential ? std::numeric_limits<double>::infinity() : std::fabs(death - birth);
}

std::string cell_kind_name(medusa::CellKind kind) {
  switch (kind) {
  case medusa::CellKind::regular: return "regular";
  case medusa::CellKind::flip: return "flip";
  case medusa::CellKind::join: return "join";
  case medusa::CellKind::repair: return "repair";
  }
  return "unknown";
}

DiagramWithClasses diagram_with_classes(const std::string& store_path, const medusa::Medusa& medusa,
                                        Direction direction, int cell_type,
                                        const RepresentativeOptions& options) {
  std::vector<int> vertex_type;
  for (const kinetic::Trajectory& t : medusa.input.cells)
    vertex_type.push_back(t.type);
  if (cell_type != all_types &&
      std::find(vertex_type.begin(), vertex_type.end(), cell_type) == vertex_type.end())
    throw InputError("cell type " + std::to_string(cell_type) + " does not occur in the store " + store_path);
  const std::string name = diagram_name(direction, cell_type);
  if (std::optional<ClassRepresentatives> stored = read_classes(store_path, name);
      stored && stored->options.max_dim >= options.max_dim &&
      (stored->options.zero_length || !options.zero_length)) {
    for (Diagram& d : read_diagrams(store_path, name))
      if (diagram_group_name(d) == name) {
        DiagramWithClasses out{std::move(d), std::move(*stored)};
        // The stored set may be larger than asked for: keep the rows the options select.
        ClassRepresentatives& c = out.classes;
        std::vector<char> keep(c.size());
        for (std::size_t i = 0; i < c.size(); ++i) {
          const PersistencePair& p = out.diagram.pairs[c.rows[i]];
          keep[i] = p.dim <= options.max_dim && (!p.zero_length || options.zero_length);
        }
        const auto kept = [&](std::size_t i) { return keep[i] != 0; };
        c.cycles.keep_if(kept);
        c.clusters.keep_if(kept);
        std::size_t rows = 0;
        for (std::size_t i = 0; i < keep.size(); ++i)
          if (kept(i))
            c.rows[rows++] = c.rows[i];
        c.rows.resize(rows);
        // Shortened cycles stay so: they are what the store holds, and as valid (docs/MATH.md §7.13).
        const bool shortened = c.options.shorten;
        c.options = options;
        c.options.shorten = shortened;
        if (options.shorten && !shortened)
          shorten_representatives(medusa.cells, filtration_of(medusa, vertex_type, direction, cell_type),
                                  out.diagram, c);
        return out;
      }
    throw StoreError("store " + store_path + ": /persistence/" + name + "/classes without its diagram");
  }
  return compute_diagram_with_classes(medusa.cells, filtration_of(medusa, vertex_type, direction, cell_type),
                                      options);
}

ClassRecord class_record(const medusa::Medusa& medusa, const DiagramWithClasses& classes, std::size_t i) {
  const std::size_t row = classes.classes.rows.at(i);
  const PersistencePair& p = classes.diagram.pairs.at(row);
  ClassRecord r;
  r.id = row;
  r.dim = p.dim;
  r.birth = p.birth;
  r.death = p.death;
  r.essential = p.essential;
  r.zero_length = p.zero_length;
  r.birth_cell = p.birth_cell;
  r.birth_kind = medusa.cell(p.birth_cell).kind;
  r.birth_cells = cc3d_ids(medusa, medusa.cell(p.birth_cell));
  if (!p.essential) {
    r.death_cell = p.death_cell;
    r.death_kind = medusa.cell(p.death_cell).kind;
    r.death_cells = cc3d_ids(medusa, medusa.cell(p.death_cell));
  }
  r.cycle = classes.classes.cycles.at(i).to_vector();
  for (medusa::CellId id : r.cycle) {
    r.simplices.push_back(cc3d_ids(medusa, medusa.cell(id)));
    if (p.dim > 0)
      r.cells.insert(r.cells.end(), r.simplices.back().begin(), r.simplices.back().end());
  }
  for (medusa::CellId id : classes.classes.clusters.at(i)) {
    const auto ids = cc3d_ids(medusa, medusa.cell(id));
    r.cells.insert(r.cells.end(), ids.begin(), ids.end());
  }
  std::sort(r.cells.begin(), r.cells.end());
  r.cells.erase(std::unique(r.cells.begin(), r.cells.end()), r.cells.end());
  return r;
}

double class_lifetime(const DiagramWithClasses& classes, std::size_t i) {
  const PersistencePair& p = classes.diagram.pairs.at(classes.classes.rows.at(i));
  ClassRecord r;
  r.birth = p.birth;
  r.death = p.death;
  r.essential = p.essential;
  return r.lifetime();
}

std::vector<ClassRecord> class_records(const medusa::Medusa& medusa, const DiagramWithClasses& classes) {
  std::vector<ClassRecord> records;
  records.reserve(classes.classes.size());
  for (std::size_t i = 0; i < classes.classes.size(); ++i)
    records.push_back(class_record(medusa, classes, i));
  return records;
}

} // namespace medusa::persistence
