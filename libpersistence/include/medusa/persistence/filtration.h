// Forward and reverse time filtrations of the alpha medusa and of its sub-medusas per cell type
// (docs/MATH.md §7.2-§7.4), with the boundary columns in filtration order (docs/MATH.md §7.5).
#pragma once

#include "medusa/medusa/cell.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace medusa::persistence {

enum class Direction : std::uint8_t {
  forward = 0, // sublevel sets of time: (birth batch, birth rank, dim, vertices) (docs/MATH.md §7.2)
  reverse = 1  // superlevel sets: (-death batch, -death rank, dim, vertices) (docs/MATH.md §7.3)
};

// Cell type value meaning "the whole medusa", not a sub-medusa M_X.
constexpr int all_types = -1;

// Filtrations index cells in 32 bits (a whole-medusa filtration of a million cells over 20 frames holds
// about 21 million, and every index is held once per cell and once per facet): a filtration holds
// at most max_filtration_size cells and is built over fewer cells than that, so that no position,
// index or "no cell" mark (the largest value) overflows. check_filtration_size throws InputError
// otherwise.
using FiltrationIndex = std::uint32_t;
inline constexpr std::size_t max_filtration_size = std::size_t{UINT32_MAX} - 1;
void check_filtration_size(std::size_t filtration_size, std::size_t cell_count);

// The boundary columns of a filtration, one after another in one array: column j is
// entries[offsets[j], offsets[j + 1]). A whole-medusa filtration has one column of at most five
// entries per cell, and a vector per column would add 24 bytes of header and a heap block's slack to
// each (about 30 bytes a cell; bench/README.md, "The report at scale"). Columns are appended in
// filtration order.
class BoundaryColumns {
public:
  // One column: its facet indices, ascending (docs/MATH.md §7.5).
  class Column {
  public:
    Column(const FiltrationIndex* first, const FiltrationIndex* last) : first_(first), last_(last) {}
    const FiltrationIndex* begin() const { return first_; }
    const FiltrationIndex* end() const { return last_; }
    std::size_t size() const { return static_cast<std::size_t>(last_ - first_); }
    bool empty() const { return first_ == last_; }
    std::int64_t operator[](std::size_t i) const { return first_[i]; }
    std::int64_t back() const { return last_[-1]; }
    std::vector<std::int64_t> to_vector() const { return {first_, last_}; }

  private:
    const FiltrationIndex* first_;
    const FiltrationIndex* last_;
  };

  std::size_t size() const { return offsets_.size() - 1; }
  std::size_t entries() const { return entries_.size(); }
  Column operator[](std::size_t j) const {
    return {entries_.data() + offsets_[j], entries_.data() + offsets_[j + 1]};
  }
  void reserve(std::size_t columns, std::size_t entries) {
    offsets_.reserve(columns + 1);
    entries_.reserve(entries);
  }
  // Appends the next column; `column` must be ascending and each entry an index of the filtration
  // (InternalError otherwise, appending nothing: every builder checks its size first).
  void push_back(const std::vector<std::int64_t>& column);
  friend bool operator==(const BoundaryColumns& a, const BoundaryColumns& b) {
    return a.offsets_ == b.offsets_ && a.entries_ == b.entries_;
  }

private:
  std::vector<std::size_t> offsets_{0};
  std::vector<FiltrationIndex> entries_;
};

// A filtration over a cell vector: entry j is the j-th cell in filtration order. It refers to the
// cell vector it was built from by position, so keep that vector alive and unchanged.
struct Filtration {
  Direction direction = Direction::forward;
  int cell_type = all_types;          // X for M_X (docs/MATH.md §7.4), all_types for M
  std::vector<FiltrationIndex> cells; // position in the input cell vector, per filtration index
  std::vector<std::int8_t> dims; // medusa dimension (vertices - 1, docs/MATH.md §6.1) per filtration index
  BoundaryColumns columns;       // facet filtration indices per filtration index (docs/MATH.md §7.5)

  std::size_t size() const { return cells.size(); }
};

// The filtration of the whole medusa. Throws InputError for duplicate cell ids or unknown facet ids,
// InternalError when a facet does not precede its coface or is not a facet of it.
Filtration make_filtration(const std::vector<medusa::Cell>& cells, Direction direction);

// The filtration of the sub-medusa M_X: cells all of whose vertices have type X, where
// vertex_type[v] is the type of vertex v; re-indexed consecutively in the inherited order (docs/MATH.md
// §7.4). Throws InputError for a vertex outside the type table.
Filtration make_type_filtration(const std::vector<medusa::Cell>& cells, const std::vector<int>& vertex_type,
                                int type, Direction direction);

} // namespace medusa::persistence
