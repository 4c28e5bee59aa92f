#include "medusa/medusa/store_reader.h"

#include "medusa/core/error.h"
#include "vertex_text.h"

#include <algorithm>
#include <map>
#include <string>

namespace medusa {

namespace {

[[noreturn]] void invalid(const std::string& name, const std::string& what) {
  throw StoreError("store " + name + ": " + what);
}

std::string cell_text(const Cell& c) {
  return "cell " + std::to_string(c.id) + " " + vertex_text(c.vertices);
}

} // namespace

void validate_medusa(const Medusa& m, const std::string& name) {
  for (std::size_t i = 1; i < m.batches.size(); ++i)
    if (m.batches[i].batch <= m.batches[i - 1].batch)
      invalid(name, "batch indices do not increase at entry " + std::to_string(i));
  if (!m.batches.empty() && m.end.batch <= m.batches.back().batch)
    invalid(name, "the end batch " + std::to_string(m.end.batch) + " does not follow the last batch");
  const std::size_t n = m.cells.size();
  const std::size_t known = m.input.cells.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Cell& c = m.cells[i];
    if (c.id != i)
      invalid(name, "cell at position " + std::to_string(i) + " has id " + std::to_string(c.id));
    if (c.vertices.empty())
      invalid(name, "cell " + std::to_string(i) + " has no vertex");
    for (std::size_t k = 0; k < c.vertices.size(); ++k)
      if (c.vertices[k] < 0 || static_cast<std::size_t>(c.vertices[k]) >= known ||
          (k > 0 && c.vertices[k] <= c.vertices[k - 1]))
        invalid(name, cell_text(c) + " has unsorted or unknown vertices");
    const bool instant = c.kind != CellKind::regular;
    if (instant ? c.birth != c.death : !(c.birth < c.death))
      invalid(name, cell_text(c) + " has an invalid lifetime");
    if (m.end < c.death)
      invalid(name, cell_text(c) + " dies after the end of the run");
    const std::size_t expected = c.vertices.size() == 1 ? 0 : c.vertices.size();
    if (c.facets.size() != expected)
      invalid(name, cell_text(c) + " has " + std::to_string(c.facets.size()) + " facets");
    // docs/MATH.md §6.4: facet i is the cell of the tuple without vertex i whose lifetime contains c's.
    for (std::size_t k = 0; k < c.facets.size(); ++k) {
      if (c.facets[k] >= n)
        invalid(name, cell_text(c) + " has an unknown facet " + std::to_string(c.facets[k]));
      const Cell& f = m.cells[c.facets[k]];
      CellVertices face;
      for (std::size_t i = 0; i < c.vertices.size(); ++i)
        if (i != k)
          face.push_back(c.vertices[i]);
      if (f.vertices != face)
        invalid(name, cell_text(c) + " has facet " + cell_text(f) + " in position " + std::to_string(k));
      if (c.birth < f.birth || f.death < c.death)
        invalid(name, cell_text(c) + " outlives its facet " + cell_text(f));
    }
    // d d = 0 over Z/2: every codimension-2 face cell is reached exactly twice.
    if (c.vertices.size() >= 3) {
      std::vector<CellId> second;
      for (CellId f : c.facets)
        second.insert(second.end(), m.cells[f].facets.begin(), m.cells[f].facets.end());
      std::sort(second.begin(), second.end());
      for (std::size_t k = 0; k < second.size(); k += 2)
        if (k + 1 >= second.size() || second[k] != second[k + 1] ||
            (k + 2 < second.size() && second[k + 2] == second[k]))
          invalid(name, cell_text(c) + " violates d d = 0");
    }
  }
  // Cells of one simplex have disjoint lifetimes (docs/MATH.md §6.2).
  std::vector<const Cell*> sorted;
  sorted.reserve(n);
  for (const Cell& c : m.cells)
    sorted.push_back(&c);
  std::sort(sorted.begin(), sorted.end(), [](const Cell* a, const Cell* b) {
    if (a->vertices != b->vertices)
      return a->vertices < b->vertices;
    return a->birth < b->birth;
  });
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i]->vertices == sorted[i - 1]->vertices && !(sorted[i - 1]->death < sorted[i]->birth))
      invalid(name,
              cell_text(*sorted[i]) + " overlaps the lifetime of cell " + std::to_string(sorted[i - 1]->id));
}

} // namespace medusa
