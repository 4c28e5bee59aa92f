#include "medusa/persistence/cell_lists.h"

#include "medusa/core/error.h"

#include <algorithm>
#include <utility>

namespace medusa::persistence {

namespace {
// Blocks grow from 2 KiB to 8 MiB of ids: small sets of lists stay small, and a large one leaves at
// most one block's spare room unused at its end (a list longer than a block gets a block of its own).
// A list that does not fit the last block leaves the rest of it unused: little for representatives,
// most of which are a few cells, though lists of just over half a block would each waste nearly half.
constexpr std::size_t first_block = 256;
constexpr std::size_t last_block = std::size_t{1} << 20;
} // namespace

CellLists::CellLists(std::initializer_list<std::vector<medusa::CellId>> lists) {
  reserve(lists.size());
  for (const std::vector<medusa::CellId>& ids : lists)
    push_back(ids);
}

CellLists CellLists::from_offsets(std::vector<std::uint64_t> offsets, std::vector<medusa::CellId> ids,
                                  const std::string& path, const std::string& where) {
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != ids.size() ||
      !std::is_sorted(offsets.begin(), offsets.end()))
    throw StoreError("store " + path + ": " + where + " offsets do not match its rows and values");
  CellLists lists;
  lists.offsets_ = std::move(offsets);
  if (!ids.empty()) {
    lists.block_first_.push_back(0);
    lists.blocks_.push_back(std::move(ids));
  }
  return lists;
}

CellLists::List CellLists::operator[](std::size_t i) const {
  const std::uint64_t first = offsets_[i], last = offsets_[i + 1];
  if (first == last)
    return {nullptr, nullptr};
  // Blocks are never empty, so the list's block is the last one starting at or before its first id.
  const auto b = static_cast<std::size_t>(std::upper_bound(block_first_.begin(), block_first_.end(), first) -
                                          block_first_.begin() - 1);
  const medusa::CellId* ids = blocks_[b].data() + (first - block_first_[b]);
  return {ids, ids + (last - first)};
}

CellLists::List CellLists::at(std::size_t i) const {
  if (i >= size())
    throw InternalError("CellLists::at: list " + std::to_string(i) + " of " + std::to_string(size()));
  return (*this)[i];
}

const std::vector<std::uint64_t>& CellLists::offsets() const {
  static const std::vector<std::uint64_t> none = {0};
  return offsets_.empty() ? none : offsets_;
}

void CellLists::drop_tail(std::size_t size) {
  blocks_.back().resize(size);
  if (size == 0) {
    blocks_.pop_back();
    block_first_.pop_back();
  }
}

std::vector<medusa::CellId>& CellLists::block_for(std::size_t n) {
  if (blocks_.empty() || blocks_.back().capacity() - blocks_.back().size() < n) {
    const std::size_t previous = blocks_.empty() ? 0 : blocks_.back().capacity();
    const std::size_t capacity = std::max(n, std::clamp(2 * previous, first_block, last_block));
    block_first_.push_back(offsets().back());
    blocks_.emplace_back();
    blocks_.back().reserve(capacity);
  }
  return blocks_.back();
}

bool operator==(const CellLists& a, const CellLists& b) {
  if (a.offsets() != b.offsets())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i])
      return false;
  return true;
}

bool operator==(CellLists::List a, CellLists::List b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

} // namespace medusa::persistence
