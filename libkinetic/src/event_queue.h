// The event queue: certificate failure times in exact order, earliest first (docs/MATH.md §3.7, §5.2).
// Entries of retired or reinstalled certificates stay in the queue and are skipped by version.
#pragma once

#include "algebraic_time.h"
#include "medusa/kinetic/large_page_allocator.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

struct QueueEntry {
  QueueEntry(SlabTime time, std::uint32_t c, std::uint32_t v, bool t = false)
      : u(std::move(time)), cert(c), version(v), touch(t) {}
  SlabTime u;
  std::uint32_t cert = 0;
  std::uint32_t version = 0;
  // A radius touch (Engine::resolve_touches): the certificate does not fail at u, but the faces of its
  // simplex are settled again there.
  bool touch = false;
};

// A binary heap of small keys over a pool of entries. A time (SlabTime) is large and holds shared
// pointers, so the heap moves 24-byte keys instead: a queue holds about one entry per certificate
// scheduled in the slab (100,000 at 10,000 cells), and each push or pop moves about log2 of that
// many. Most comparisons are decided on the keys' doubles; only overlapping ones read the pool.
class EventQueue {
public:
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }
  // The earliest entry; valid until the next push or pop.
  const QueueEntry& top() const { return pool_[heap_.front().slot]; }
  // The certificate of the earliest entry, read from its key (the entry itself may still be loading).
  std::uint32_t top_cert() const { return heap_.front().cert; }

  void push(QueueEntry e) {
    std::uint32_t slot;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
      pool_[slot] = std::move(e);
    } else {
      slot = static_cast<std::uint32_t>(pool_.size());
      pool_.push_back(std::move(e));
    }
    Key k;
    k.slot = slot;
    k.cert = pool_[slot].cert;
    pool_[slot].u.enclosure(k.lo, k.hi);
    heap_.push_back(k);
    std::push_heap(heap_.begin(), heap_.end(), LaterFirst{&pool_});
  }

  void pop() {
    std::pop_heap(heap_.begin(), heap_.end(), LaterFirst{&pool_});
    const std::uint32_t slot = heap_.back().slot;
    heap_.pop_back();
    // The next pop's entry is needed only once the batch it ends is resolved: it loads meanwhile.
    if (!heap_.empty())
      __builtin_prefetch(pool_.data() + heap_.front().slot);
    // The slot keeps its time until reused (a default time would allocate a rational): at most
    // the queue's largest size of them.
    free_.push_back(slot);
  }

  void clear() {
    heap_.clear();
    pool_.clear();
    free_.clear();
  }

  // The first invariant that fails, or an empty string: every pool slot is in the heap or free, once;
  // no entry is later than its children; each heap key encloses its entry's time (refinement only
  // narrows a time's enclosure).
  std::string first_violation() const {
    std::vector<char> seen(pool_.size(), 0);
    for (const Key& k : heap_)
      if (k.slot >= pool_.size() || seen[k.slot]++)
        return "the event queue holds a slot twice or out of range";
    for (std::uint32_t slot : free_)
      if (slot >= pool_.size() || seen[slot]++)
        return "the event queue's free slot is in use or out of range";
    if (heap_.size() + free_.size() != pool_.size())
      return "the event queue lost a slot";
    const LaterFirst later{&pool_};
    for (std::size_t i = 1; i < heap_.size(); ++i)
      if (later(heap_[(i - 1) / 2], heap_[i]))
        return "the event queue is out of time order";
    for (const Key& k : heap_) {
      double lo, hi;
      pool_[k.slot].u.enclosure(lo, hi);
      if (lo < k.lo || k.hi < hi)
        return "a queued time left the enclosure it was queued with";
      if (k.cert != pool_[k.slot].cert)
        return "a heap key names another certificate than its entry";
    }
    return {};
  }

private:
  struct Key {
    // An enclosure of the time when the entry was made. Refinement only narrows the time's own
    // enclosure, so this one stays valid.
    double lo = 0.0, hi = 0.0;
    std::uint32_t slot = 0;
    std::uint32_t cert = 0; // the entry's, in what would be padding: prefetched before the entry is read
  };
  static_assert(sizeof(Key) == 24, "the heap moves keys of three words");
  struct LaterFirst {
    const LargeVector<QueueEntry>* pool;
    bool operator()(const Key& a, const Key& b) const {
      if (b.hi < a.lo)
        return true;
      if (a.hi < b.lo)
        return false;
      return compare((*pool)[b.slot].u, (*pool)[a.slot].u) < 0;
    }
  };

  LargeVector<Key> heap_;
  LargeVector<QueueEntry> pool_;
  std::vector<std::uint32_t> free_;
};

} // namespace medusa::kinetic::detail
