// A PHAT column representation for the medusa's boundary matrices: the entries in 32 bits (filtration
// indices, filtration.h), up to four of them in the column itself (SmallList: a cell of the medusa
// has at most four facets but its rare instants of dimension 4, docs/MATH.md §6.1), more in one heap
// array; and the dimensions in one byte each.
// PHAT's vector_vector spends a std::vector of 64-bit entries, a heap block and a pointer per column
// and 64 bits per dimension, about 80 bytes a cell against 25 here: at a million cells the
// whole-medusa matrix has 21 million columns. Reduction goes through PHAT's pivot column
// (compact_pivot_column below), as bit_tree_pivot_column's does, so the pairs are the same
// (tests/persistence/test_compact_column.cpp checks them against PHAT's representations).
#pragma once

#include "medusa/core/error.h"
#include "medusa/medusa/small_list.h"

#include <phat/helpers/misc.h>
#include <phat/representations/Container_traits.h>
#include <phat/representations/Pivot_representation.h>
#include <phat/representations/Uniform_representation.h>
#include <phat/representations/bit_tree_pivot_column.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

namespace medusa::persistence {

class CompactColumn {
public:
  using Entry = std::uint32_t;

  const Entry* begin() const { return entries_.begin(); }
  const Entry* end() const { return entries_.end(); }
  std::size_t size() const { return entries_.size(); }

  // PHAT's column interface (phat/representations/vector_column_rep.h).
  void offer_thread_local_storage(thread_local_storage<phat::column>*) {} // PHAT declares it globally
  void _set_nr_of_rows(int) {}
  void _get_col(phat::column& col) const { col.assign(begin(), end()); }
  void _set_col(const phat::column& col) {
    for (phat::index row : col)
      if (row < 0 || row >= phat::index{UINT32_MAX})
        throw InternalError("boundary matrix: row " + std::to_string(row) + " is no filtration index");
    entries_.assign(col.begin(), col.end());
  }
  bool _is_empty() const { return entries_.empty(); }
  phat::index _get_max_index() const { return entries_.empty() ? -1 : phat::index{entries_.back()}; }
  void _remove_max() { entries_.pop_back(); }
  // A column the reduction clears (twist) lets its heap array go, if it had one.
  void _clear() { entries_ = Entries(); }
  void _sync() {}
  // The sum over Z/2 (symmetric difference); PHAT's pivot representations add in their pivot column
  // instead, so this serves Uniform_representation alone.
  void _add_to(const CompactColumn& source) {
    std::vector<Entry> sum;
    sum.reserve(size() + source.size());
    std::set_symmetric_difference(begin(), end(), source.begin(), source.end(), std::back_inserter(sum));
    entries_.assign(sum.begin(), sum.end());
  }
  // A column the reduction left short enough goes back into place and lets its heap array go.
  void _finalize() {
    if (!entries_.is_inline() && entries_.size() <= in_place)
      entries_ = Entries(entries_.begin(), entries_.end());
  }

private:
  // Four in place: every cell of the medusa but its instants of dimension 4 (five facets) and the
  // columns fill-in grows.
  static constexpr std::uint32_t in_place = 4;
  using Entries = SmallList<Entry, in_place>;
  Entries entries_;
};
static_assert(sizeof(CompactColumn) == 24, "a column per cell of the medusa");

} // namespace medusa::persistence

namespace phat {
// The dimensions of compact_pivot_column, a byte each (phat::dimension) where PHAT's
// Dimension_container_traits keeps an index (64 bits).
template <> class Dimension_container_traits<std::vector<dimension>> {
public:
  using Dimension_container = std::vector<dimension>;
  dimension& dim_at(Dimension_container& data, index idx) const {
    return data[static_cast<std::size_t>(idx)];
  }
  const dimension& dim_at(const Dimension_container& data, index idx) const {
    return data[static_cast<std::size_t>(idx)];
  }
  index get_size(const Dimension_container& data) const { return static_cast<index>(data.size()); }
  void resize(Dimension_container& data, index nr_of_columns) const {
    data.resize(static_cast<std::size_t>(nr_of_columns));
  }
};
} // namespace phat

namespace medusa::persistence {
// What bit_tree_pivot_column is (PHAT's default) over compact columns.
using compact_vector = phat::Uniform_representation<std::vector<CompactColumn>, std::vector<phat::dimension>>;
using compact_pivot_column = phat::Pivot_representation<compact_vector, phat::bit_tree_column>;
} // namespace medusa::persistence
