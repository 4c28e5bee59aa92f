// A hash map from simplices to small values, stored flat (open addressing, linear probing,
// backward-shift deletion). The engine looks up the alpha-complex state of every face of every
// changed top simplex at every event (docs/MATH.md §4.4, §4.5); a node-based std::unordered_map costs two
// dependent cache misses per lookup there, this table one. The empty simplex (size 0) marks a free
// slot, so keys must be non-empty.
#pragma once

#include "medusa/core/error.h"
#include "medusa/kinetic/large_page_allocator.h"
#include "medusa/kinetic/simplex.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace medusa::kinetic {

// How a slot holds its key. WholeKeys: the simplex itself (20 bytes, infinite vertices allowed).
struct WholeKeys {
  using Key = Simplex;
  static const Simplex& key(const Simplex& s) { return s; }
  static const Simplex& simplex(const Simplex& k) { return k; }
  static bool used(const Simplex& k) { return k.size() != 0; }
  static bool equal(const Simplex& k, const Simplex& s) { return k == s; }
};

// FiniteKeys: a simplex of vertex ids >= 0 by its four entries alone (16 bytes), its size being where
// the -1 padding starts. The face table holds some 27 simplices per cell and is looked up at every
// flip: with a 16-byte value its slots are 32 bytes, two to a cache line, where 40-byte slots put
// every second look-up across two lines.
struct FiniteKeys {
  struct Key {
    std::array<VertexId, 4> v{{-1, -1, -1, -1}};
  };
  static Key key(const Simplex& s) {
    assert(s.size() != 0 && s[0] >= 0);
    return {s.padded()};
  }
  static Simplex simplex(const Key& k) {
    const std::size_t n = std::size_t(k.v[0] >= 0) + std::size_t(k.v[1] >= 0) + std::size_t(k.v[2] >= 0) +
                          std::size_t(k.v[3] >= 0);
    return Simplex::from_sorted(k.v, n);
  }
  static bool used(const Key& k) { return k.v[0] >= 0; }
  // The padding decides the size.
  static bool equal(const Key& k, const Simplex& s) { return Simplex::same_entries(k.v, s.padded()); }
};

template <class V, class Keys = WholeKeys> class FlatSimplexMap {
public:
  struct Slot {
    typename Keys::Key first;
    V second{};
    bool used() const { return Keys::used(first); }
    decltype(auto) simplex() const { return Keys::simplex(first); }
  };
  using Slots = LargeVector<Slot>;

  template <class SlotT> class Iterator {
  public:
    Iterator(SlotT* p, SlotT* end) : p_(p), end_(end) { skip_free_slots(); }
    SlotT& operator*() const { return *p_; }
    SlotT* operator->() const { return p_; }
    Iterator& operator++() {
      ++p_;
      skip_free_slots();
      return *this;
    }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.p_ == b.p_; }
    friend bool operator!=(const Iterator& a, const Iterator& b) { return a.p_ != b.p_; }

  private:
    friend class FlatSimplexMap;
    // Iterators only ever rest on used slots or at the end: advance past free ones.
    void skip_free_slots() {
      while (p_ != end_ && !p_->used())
        ++p_;
    }
    SlotT* p_;
    SlotT* end_;
  };
  using iterator = Iterator<Slot>;
  using const_iterator = Iterator<const Slot>;

  iterator begin() { return {slots_.data(), slots_.data() + slots_.size()}; }
  iterator end() { return {slots_.data() + slots_.size(), slots_.data() + slots_.size()}; }
  const_iterator begin() const { return {slots_.data(), slots_.data() + slots_.size()}; }
  const_iterator end() const { return {slots_.data() + slots_.size(), slots_.data() + slots_.size()}; }

  std::size_t size() const { return size_; }
  // Room for n entries: inserting up to n - size() new keys then moves no entry, so references to
  // entries stay valid until the next erase (Engine::apply_top_change holds one per touched face).
  // A large reservation (the first triangulation) is made at a load of 3/5, so that the run's
  // fluctuations around that size do not grow the table at once.
  void reserve(std::size_t n) {
    if (full_at(n))
      grow_to(std::max(slots_.size() + slots_.size() / 2, n + n * 2 / 3));
  }
  std::size_t capacity() const { return slots_.size(); }
  // Empties the table. A small one keeps its slots: the engine empties its per-batch tables at
  // every event, and an allocation there costs more than the reset.
  void clear() {
    if (slots_.size() <= 256)
      std::fill(slots_.begin(), slots_.end(), Slot{});
    else
      slots_ = Slots();
    size_ = 0;
  }

  iterator find(const Simplex& s) {
    std::size_t i = locate(s);
    return i == npos ? end() : at_slot(i);
  }
  const_iterator find(const Simplex& s) const {
    std::size_t i = locate(s);
    return i == npos ? end() : const_iterator(slots_.data() + i, slots_.data() + slots_.size());
  }
  std::size_t count(const Simplex& s) const { return locate(s) == npos ? 0 : 1; }
  // Starts loading the home slot of s. A flip looks up some forty simplices in tables of megabytes,
  // each a cache miss of its own; requested together, the misses overlap instead of queueing.
  void prefetch(const Simplex& s) const {
    if (!slots_.empty())
      __builtin_prefetch(slots_.data() + home(s));
  }

  V& at(const Simplex& s) { return const_cast<V&>(static_cast<const FlatSimplexMap&>(*this).at(s)); }
  const V& at(const Simplex& s) const {
    std::size_t i = locate(s);
    if (i == npos)
      throw InternalError("no state recorded for a simplex of the triangulation");
    return slots_[i].second;
  }
  V& operator[](const Simplex& s) { return try_emplace(s).first->second; }
  // Inserts (s, v) unless s is present; true when it was inserted.
  std::pair<iterator, bool> emplace(const Simplex& s, const V& v) {
    auto r = try_emplace(s);
    if (r.second)
      r.first->second = v;
    return r;
  }

  // The slot of s, value-initialised if new; true when it was inserted.
  std::pair<iterator, bool> try_emplace(const Simplex& s) {
    if (full_at(size_ + 1))
      grow_to(slots_.size() + slots_.size() / 2);
    std::size_t i = home(s);
    while (slots_[i].used()) {
      if (Keys::equal(slots_[i].first, s))
        return {at_slot(i), false};
      i = next(i);
    }
    slots_[i].first = Keys::key(s);
    slots_[i].second = V{};
    ++size_;
    return {at_slot(i), true};
  }

  // Removes the entry at it; iterators to other entries may move (backward shift).
  void erase(iterator it) {
    std::size_t i = static_cast<std::size_t>(it.p_ - slots_.data());
    std::size_t j = i;
    for (;;) {
      j = next(j);
      if (!slots_[j].used())
        break;
      std::size_t k = home(slots_[j].simplex());
      // Slot j may move back to i iff its home k is not cyclically within (i, j].
      bool stays = i <= j ? (i < k && k <= j) : (i < k || k <= j);
      if (!stays) {
        slots_[i] = std::move(slots_[j]);
        i = j;
      }
    }
    slots_[i] = Slot{};
    --size_;
  }

  std::size_t erase(const Simplex& s) {
    iterator it = find(s);
    if (it == end())
      return 0;
    erase(it);
    return 1;
  }

private:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  // At most three quarters of the slots are used. Capacities are not powers of two: a table grows by
  // half, so it stays between 1/2 and 3/4 full where doubling leaves it between 3/8 and 3/4 (the
  // face table of a million cells holds 27 million simplices at 32 bytes a slot).
  bool full_at(std::size_t n) const { return 4 * n > 3 * slots_.size(); }
  std::size_t next(std::size_t i) const { return i + 1 == slots_.size() ? 0 : i + 1; }
  // The mixed hash scaled to [0, capacity) (multiply-high), on the hash mixed with a seed of the
  // table's capacity: copying entries from one
  // table into a smaller one visits them in the first table's slot order, and with a shared home
  // function they would arrive clustered in the second (linear probing then degrades to quadratic
  // time). Tables of equal capacity share the seed, which is harmless (the copy lands as laid out in
  // the source), and nothing depends on the process's history: the engine iterates these tables, so
  // a seed drawn from a process-wide counter made a run's certificates depend on what ran before.
  std::size_t home(const Simplex& s) const {
    const std::uint64_t h = (static_cast<std::uint64_t>(SimplexHash()(s)) ^ seed_) * 0x9E3779B97F4A7C15ULL;
    __extension__ using wide = unsigned __int128;
    return static_cast<std::size_t>((static_cast<wide>(h) * slots_.size()) >> 64);
  }
  static std::uint64_t seed_for(std::size_t capacity) {
    std::uint64_t x = static_cast<std::uint64_t>(capacity + 1) * 0xD6E8FEB86659FD93ULL;
    x ^= x >> 32;
    x *= 0xD6E8FEB86659FD93ULL;
    return x ^ (x >> 32);
  }
  iterator at_slot(std::size_t i) { return {slots_.data() + i, slots_.data() + slots_.size()}; }

  std::size_t locate(const Simplex& s) const {
    if (slots_.empty())
      return npos;
    for (std::size_t i = home(s);; i = next(i)) {
      if (!slots_[i].used())
        return npos;
      if (Keys::equal(slots_[i].first, s))
        return i;
    }
  }

  void grow_to(std::size_t capacity) {
    Slots old;
    old.swap(slots_);
    slots_.assign(std::max<std::size_t>(capacity, 64), Slot{});
    seed_ = seed_for(slots_.size());
    size_ = 0;
    for (Slot& e : old)
      if (e.used())
        try_emplace(e.simplex()).first->second = std::move(e.second);
  }

  Slots slots_;
  std::size_t size_ = 0;
  std::uint64_t seed_ = seed_for(0);
};

} // namespace medusa::kinetic
