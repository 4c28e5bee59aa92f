// Lists of medusa cell ids held end to end, as the store holds them (docs/FORMAT.md,
// /persistence/<diagram>/classes): an offset per list into the ids of all lists one after another. A
// diagram of a large medusa has millions of representatives, most of a few cells: held as a vector each,
// every list would cost a vector and an allocation beside its ids; held end to end, it costs one offset.
//
// The ids are held in blocks, each list within one block, so that appending never moves what is held:
// one array grown by doubling would hold everything twice while it moves, at the moment it is largest.
#pragma once

#include "medusa/medusa/cell.h"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace medusa::persistence {

class CellLists {
public:
  // One list, read only; valid until its CellLists changes.
  class List {
  public:
    using value_type = medusa::CellId;
    using const_iterator = const medusa::CellId*;
    using iterator = const_iterator;

    List(const medusa::CellId* first, const medusa::CellId* last) : first_(first), last_(last) {}
    // A view of a vector's ids, as a list (the vector outlives the view).
    explicit List(const std::vector<medusa::CellId>& ids)
        : first_(ids.data()), last_(ids.data() + ids.size()) {}
    const_iterator begin() const { return first_; }
    const_iterator end() const { return last_; }
    std::size_t size() const { return static_cast<std::size_t>(last_ - first_); }
    bool empty() const { return first_ == last_; }
    medusa::CellId operator[](std::size_t i) const { return first_[i]; }
    medusa::CellId front() const { return *first_; }
    medusa::CellId back() const { return *(last_ - 1); }
    std::vector<medusa::CellId> to_vector() const { return {first_, last_}; }

  private:
    const medusa::CellId* first_;
    const medusa::CellId* last_;
  };

  class const_iterator {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = List;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = List;

    const_iterator(const CellLists* lists, std::size_t i) : lists_(lists), i_(i) {}
    List operator*() const { return (*lists_)[i_]; }
    const_iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator==(const const_iterator& other) const { return i_ == other.i_; }
    bool operator!=(const const_iterator& other) const { return i_ != other.i_; }

  private:
    const CellLists* lists_;
    std::size_t i_;
  };

  CellLists() = default;
  CellLists(std::initializer_list<std::vector<medusa::CellId>> lists);
  CellLists(const CellLists&) = default;
  CellLists& operator=(const CellLists&) = default;
  // A moved-from CellLists is empty.
  CellLists(CellLists&& other) noexcept { swap(other); }
  CellLists& operator=(CellLists&& other) noexcept {
    CellLists moved(std::move(other));
    swap(moved);
    return *this;
  }
  void swap(CellLists& other) noexcept {
    offsets_.swap(other.offsets_);
    blocks_.swap(other.blocks_);
    block_first_.swap(other.block_first_);
  }
  // Lists as the store holds them: list i is ids[offsets[i] .. offsets[i + 1]). Throws StoreError naming
  // `where` in `path` unless the offsets start at 0, ascend and end at ids.size().
  static CellLists from_offsets(std::vector<std::uint64_t> offsets, std::vector<medusa::CellId> ids,
                                const std::string& path, const std::string& where);

  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  bool empty() const { return size() == 0; }
  List operator[](std::size_t i) const;
  // As operator[], but throws InternalError past the last list.
  List at(std::size_t i) const;
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size()}; }

  // Appends a list: any sized range of cell ids, or to_id of each element of a sized range.
  template <class Range> void push_back(const Range& ids) {
    push_back(ids, [](medusa::CellId id) { return id; });
  }
  template <class Range, class ToId> void push_back(const Range& range, ToId to_id);
  void push_back(List ids) { push_back<List>(ids); }
  void push_back(std::initializer_list<medusa::CellId> ids) { push_back<>(ids); }
  void reserve(std::size_t lists) { offsets_.reserve(lists + 1); }
  // Replaces the lists, in order: f(i, list i, out) appends to `out` what list i becomes (or nothing,
  // to drop it). Each block is let go once its last list has been read, so that the lists are not held
  // twice; so if f throws, the lists are left empty.
  template <class F> void rebuild(F f);
  // Keeps the lists i for which keep(i) holds, in order.
  template <class Keep> void keep_if(Keep keep) {
    rebuild([&](std::size_t i, List list, CellLists& out) {
      if (keep(i))
        out.push_back(list);
    });
  }

  // The store's offsets: list i is ids [offsets()[i], offsets()[i + 1]) of all lists one after another.
  const std::vector<std::uint64_t>& offsets() const;
  // Calls f(id) for the ids of all lists one after another.
  template <class F> void for_each_id(F f) const {
    for (const std::vector<medusa::CellId>& block : blocks_)
      for (medusa::CellId id : block)
        f(id);
  }

  friend bool operator==(const CellLists& a, const CellLists& b);
  friend bool operator!=(const CellLists& a, const CellLists& b) { return !(a == b); }

private:
  // The block to append n ids to: the last one if they fit, else a new one.
  std::vector<medusa::CellId>& block_for(std::size_t n);
  // Drops the last block's ids from `size` on, and the block if none is left (a list cut short).
  void drop_tail(std::size_t size);

  std::vector<std::uint64_t> offsets_; // size() + 1 of them, or none when there is no list
  std::vector<std::vector<medusa::CellId>> blocks_;
  std::vector<std::uint64_t> block_first_; // offset of each block's first id
};

bool operator==(CellLists::List a, CellLists::List b);
inline bool operator!=(CellLists::List a, CellLists::List b) { return !(a == b); }

template <class Range, class ToId> void CellLists::push_back(const Range& range, ToId to_id) {
  if (offsets_.empty())
    offsets_.push_back(0);
  const auto n = static_cast<std::size_t>(std::size(range));
  if (n == 0) {
    offsets_.push_back(offsets_.back());
    return;
  }
  std::vector<medusa::CellId>& block = block_for(n);
  const std::size_t before = block.size();
  try {
    for (const auto& x : range)
      block.push_back(to_id(x));
  } catch (...) {
    drop_tail(before);
    throw;
  }
  offsets_.push_back(block_first_.back() + block.size());
}

template <class F> void CellLists::rebuild(F f) {
  CellLists out;
  out.reserve(size());
  std::size_t read = 0; // blocks before it are let go
  try {
    for (std::size_t i = 0; i < size(); ++i) {
      f(i, (*this)[i], out);
      while (read < blocks_.size() && block_first_[read] + blocks_[read].size() <= offsets_[i + 1])
        std::vector<medusa::CellId>().swap(blocks_[read++]);
    }
  } catch (...) {
    CellLists().swap(*this);
    throw;
  }
  swap(out);
}

} // namespace medusa::persistence
