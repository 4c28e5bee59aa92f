// The store behind `medusa.open`: the medusa read once, its diagrams (stored under /persistence, or
// computed when the store has none), the classes with their cells and the complexes K(t).
#pragma once

#include "medusa/medusa/medusa.h"
#include "medusa/persistence/class_records.h"
#include "medusa/persistence/diagram.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace medusa::python {

class StoreView {
public:
  // Reads and validates the store (medusa::read_store). Throws StoreError.
  explicit StoreView(std::string path);

  const std::string& path() const { return path_; }
  const medusa::Medusa& medusa() const { return medusa_; }
  // The cell types of the run, increasing.
  std::vector<int> types() const;

  // The diagram of one filtration (direction, cell type or all_types), every point. Throws InputError
  // for a type the run has no cells of.
  const persistence::Diagram& diagram(persistence::Direction direction, int cell_type);

  // The classes of that diagram in degree `dim` (or 0-2), with their representatives, shortened on
  // request (docs/MATH.md §7.13; a store written with shortened ones holds only those). On a periodic
  // run, `wraps` (when given) gets per class the axes its loop wraps around ("x", "x,y"; "" for none and
  // for other degrees, docs/MATH.md §8.8), as `medusa classes`; it stays empty on an open run.
  std::vector<persistence::ClassRecord> classes(persistence::Direction direction, int cell_type,
                                                std::optional<int> dim, bool zero_length, bool shorten,
                                                std::vector<std::string>* wraps = nullptr);

  // K(t+) (K(t_end-) at the end, docs/MATH.md §6.6) as simplices of CC3D cell ids, sorted by dimension
  // then ids; the type-X subcomplex when `type` is given. Throws InputError outside [t_0, t_end].
  std::vector<std::vector<std::int64_t>> complex_at(double t, std::optional<int> type) const;

private:
  void check_type(int cell_type) const;

  std::string path_;
  medusa::Medusa medusa_;
  std::map<std::pair<int, int>, persistence::Diagram> diagrams_; // by (direction, type)
  bool stored_read_ = false;
};

} // namespace medusa::python
