// Representatives of persistence classes: for each point of a diagram, a Z/2 cycle of medusa cells
// that the class is born with, and for H0 the cluster of cells that forms the component
// (docs/MATH.md §7.11).
#pragma once

#include "medusa/medusa/cell.h"
#include "medusa/persistence/cell_lists.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/filtration.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace medusa::persistence {

// Which points of a diagram get a representative.
struct RepresentativeOptions {
  int max_dim = 2;          // homology degrees 0..max_dim
  bool zero_length = false; // also the zero-length pairs (on the diagonal)
  // Degrees >= 1: shorten each cycle greedily by boundaries of the filtration (docs/MATH.md §7.13);
  // shorter, homologous before the death, not necessarily the shortest.
  bool shorten = false;
};

// The representatives of one diagram, aligned with its points: entry i belongs to
// `diagram.pairs[rows[i]]`, rows ascending.
struct ClassRepresentatives {
  RepresentativeOptions options;
  std::vector<std::size_t> rows;
  // Cell ids of a Z/2 cycle z, ascending in filtration order, so the birth cell comes last: every
  // cell of z enters no later than the birth cell, z is a cycle (its boundary is zero over Z/2), and
  // its class is born with the birth cell and is not a boundary before the death cell (never, for an
  // essential class). Degree 0: the birth vertex and, for a finite pair, the oldest vertex of the
  // component it merges into (z = older + younger, a boundary from the death edge on).
  CellLists cycles;
  // Degree 0 only (empty otherwise): the vertex cells of the component born with the class, ascending
  // in filtration order: just before the death edge merges it into an older component, or, for an
  // essential class, at the end of the filtration.
  CellLists clusters;

  std::size_t size() const { return rows.size(); }
};

struct DiagramWithClasses {
  Diagram diagram;
  ClassRepresentatives classes;
};

// Reduces the filtration (PHAT, twist reduction) and builds the diagram, as compute_diagram does, and
// the representatives of its points selected by `options`. Finite pairs of degree >= 1 take the
// reduced column of the death cell; essential classes of degree >= 1 a cycle found from the reduced
// columns (docs/MATH.md §7.11); degree 0 comes from a union-find pass in filtration order. Throws
// InternalError when a derived representative fails its defining property (a bug).
DiagramWithClasses compute_diagram_with_classes(const std::vector<medusa::Cell>& cells,
                                                const Filtration& filtration,
                                                const RepresentativeOptions& options = {},
                                                const std::function<void()>& poll = {});

// Shortens the representatives `classes` of `diagram` in place, as options.shorten does, and marks them
// shortened; `diagram` and `classes` are those of `filtration` over `cells` (stored ones, for example).
// Throws InputError for a cycle cell outside the filtration, InternalError when a shortened cycle
// fails its defining properties (a bug).
void shorten_representatives(const std::vector<medusa::Cell>& cells, const Filtration& filtration,
                             const Diagram& diagram, ClassRepresentatives& classes);

} // namespace medusa::persistence
