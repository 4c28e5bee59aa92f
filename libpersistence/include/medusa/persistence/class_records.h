// The classes of one diagram as records a user reads: times, the CompuCell3D cells of the birth and
// death cells, and of the representative (docs/MATH.md §7.11), from a store.
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/representatives.h"

#include <cstdint>
#include <string>
#include <vector>

namespace medusa::persistence {

struct ClassRecord {
  std::size_t id = 0; // row of the point in its diagram (as stored under /persistence)
  int dim = 0;
  double birth = 0, death = 0; // filtration values (MCS); death +-inf for an essential class
  bool essential = false;
  bool zero_length = false;
  medusa::CellId birth_cell = 0, death_cell = 0; // medusa cell ids (death_cell unused if essential)
  medusa::CellKind birth_kind = medusa::CellKind::regular, death_kind = medusa::CellKind::regular;
  std::vector<std::int64_t> birth_cells, death_cells; // CC3D cell ids of their vertices, sorted
  // CC3D cell ids of the representative, sorted and distinct: the cluster for H0, the cells on the
  // cycle otherwise.
  std::vector<std::int64_t> cells;
  std::vector<medusa::CellId> cycle;                // medusa cell ids of the cycle, in filtration order
  std::vector<std::vector<std::int64_t>> simplices; // the cycle's cells as sorted CC3D id tuples

  // |death - birth|, +inf for an essential class.
  double lifetime() const;
};

// The diagram (direction, cell type or all_types) of the medusa read from `store_path`, with the
// representatives of its classes in degrees 0..options.max_dim: those stored under /persistence when
// they cover the options, else computed from the cells (and then not stored). With options.shorten
// the cycles are shortened (docs/MATH.md §7.13); stored shortened cycles are returned as they are, and
// result.classes.options.shorten says which kind was returned. Throws InputError for
// a type that does not occur in the store, StoreError for a malformed /persistence group.
DiagramWithClasses diagram_with_classes(const std::string& store_path, const medusa::Medusa& medusa,
                                        Direction direction, int cell_type,
                                        const RepresentativeOptions& options);

// One record per represented class, in diagram order.
std::vector<ClassRecord> class_records(const medusa::Medusa& medusa, const DiagramWithClasses& classes);
// The record of represented class i (0 <= i < classes.classes.size()): a record holds its cycle's
// cells as CC3D id tuples, so a caller that shows a few classes of a large run builds only those.
ClassRecord class_record(const medusa::Medusa& medusa, const DiagramWithClasses& classes, std::size_t i);
// The lifetime ClassRecord::lifetime() gives class i, without building its record.
double class_lifetime(const DiagramWithClasses& classes, std::size_t i);

// "regular", "flip", "join" or "repair".
std::string cell_kind_name(medusa::CellKind kind);

} // namespace medusa::persistence
