// The event queue: certificate failure times in exact order, earliest first (docs/MATH.md §3.7, §5.2).
// Entries of retired or reinstalled certificates stay in the queue and are skipped by version.
#pragma once

#include "algebraic_time.h"
#include "medusa/kinetic/large_page_allocator.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
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

// Failure times of a slab, which lie in [0, 1] and leave in increasing order, as a binary heap of the
// near ones over buckets of the later ones (docs/MATH.md §3.7). A time (SlabTime) is large and holds
// shared pointers, so both move 24-byte keys over a pool of entries; most comparisons are decided on
// the keys' doubles, and only overlapping ones read the pool.
//
// A key goes to the bucket of its enclosure's lower end, or to the heap when that is below the
// horizon, the start of the first bucket not yet emptied into the heap. Before the earliest entry is
// read, buckets are emptied into the heap, in order, until the heap's first time ends below the
// horizon: every later time then starts at or above it, so the heap's first is the earliest of all,
// and equal times never lie on both sides (in which order equal times leave does not change a
// batch, docs/MATH.md §5.2). At 100,000 cells a slab queues millions of times, about
// half of them for certificates retired before their time; a single heap of them all made each pop a
// walk down twenty-odd levels, the lower ones each a cache miss, where the heap of the near ones stays
// in cache.
class EventQueue {
public:
  static constexpr std::size_t bucket_count = 1024;

  // Empties buckets into the heap as reading the earliest entry requires (hence not const).
  bool empty() {
    settle();
    return heap_.empty();
  }
  std::size_t size() const { return heap_.size() + later_; }
  // The earliest entry; valid until the next push or pop.
  const QueueEntry& top() {
    settle();
    return pool_[heap_.front().slot];
  }
  // The certificate of the heap's first entry, read from its key (the entry itself may still be
  // loading), or none_queued: a hint of what the next pop reads, for prefetching.
  static constexpr std::uint32_t none_queued = ~std::uint32_t{0};
  std::uint32_t first_cert_hint() const { return heap_.empty() ? none_queued : heap_.front().cert; }

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
    if (k.lo < horizon_) {
      heap_.push_back(k);
      std::push_heap(heap_.begin(), heap_.end(), LaterFirst{&pool_});
    } else {
      buckets_[bucket_of(k.lo)].push_back(k);
      ++later_;
    }
  }

  // Removes the earliest entry (the queue must not be empty).
  void pop() {
    settle();
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

  // Empties the queue for the next slab; the buckets keep their room.
  void clear() {
    heap_.clear();
    pool_.clear();
    free_.clear();
    for (auto& bucket : buckets_)
      bucket.clear();
    later_ = 0;
    next_bucket_ = 0;
    horizon_ = 0.0;
  }

  // The first invariant that fails, or an empty string: every pool slot is in the heap, in a bucket
  // or free, once; no heap entry is later than its children; each bucket not yet emptied holds the
  // keys whose lower ends fall in it, at or above the horizon; each key encloses its entry's time
  // (refinement only narrows a time's enclosure) and names its certificate.
  std::string first_violation() const {
    std::vector<char> seen(pool_.size(), 0);
    const auto check = [&](const Key& k) -> std::string {
      if (k.slot >= pool_.size() || seen[k.slot]++)
        return "the event queue holds a slot twice or out of range";
      double lo, hi;
      pool_[k.slot].u.enclosure(lo, hi);
      if (lo < k.lo || k.hi < hi)
        return "a queued time left the enclosure it was queued with";
      if (k.cert != pool_[k.slot].cert)
        return "a queue key names another certificate than its entry";
      return {};
    };
    for (const Key& k : heap_)
      if (std::string v = check(k); !v.empty())
        return v;
    std::size_t later = 0;
    for (std::size_t b = 0; b < bucket_count; ++b) {
      if (b < next_bucket_ && !buckets_[b].empty())
        return "an emptied bucket of the event queue holds keys";
      for (const Key& k : buckets_[b]) {
        if (std::string v = check(k); !v.empty())
          return v;
        if (k.lo < horizon_ || bucket_of(k.lo) != b)
          return "a key of the event queue is in the wrong bucket";
      }
      later += buckets_[b].size();
    }
    if (later != later_)
      return "the event queue miscounts its later keys";
    for (std::uint32_t slot : free_)
      if (slot >= pool_.size() || seen[slot]++)
        return "the event queue's free slot is in use or out of range";
    if (heap_.size() + later_ + free_.size() != pool_.size())
      return "the event queue lost a slot";
    const LaterFirst later_first{&pool_};
    for (std::size_t i = 1; i < heap_.size(); ++i)
      if (later_first(heap_[(i - 1) / 2], heap_[i]))
        return "the event queue is out of time order";
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
  static_assert(sizeof(Key) == 24, "the queue moves keys of three words");
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

  static std::size_t bucket_of(double lo) {
    const double b = lo * static_cast<double>(bucket_count);
    return b < static_cast<double>(bucket_count - 1) ? static_cast<std::size_t>(std::max(b, 0.0))
                                                     : bucket_count - 1;
  }
  // Empties buckets into the heap until its first time ends below the horizon, or none is left.
  void settle() {
    while (later_ > 0 && (heap_.empty() || !(heap_.front().hi < horizon_))) {
      std::vector<Key>& bucket = buckets_[next_bucket_];
      ++next_bucket_;
      horizon_ = next_bucket_ < bucket_count ? static_cast<double>(next_bucket_) / bucket_count
                                             : std::numeric_limits<double>::infinity();
      if (bucket.empty())
        continue;
      later_ -= bucket.size();
      const std::size_t before = heap_.size();
      heap_.insert(heap_.end(), bucket.begin(), bucket.end());
      bucket.clear();
      if (before == 0) {
        std::make_heap(heap_.begin(), heap_.end(), LaterFirst{&pool_});
      } else {
        for (std::size_t n = before + 1; n <= heap_.size(); ++n)
          std::push_heap(heap_.begin(), heap_.begin() + static_cast<std::ptrdiff_t>(n), LaterFirst{&pool_});
      }
    }
  }

  LargeVector<Key> heap_;
  LargeVector<QueueEntry> pool_;
  std::vector<std::uint32_t> free_;
  std::array<std::vector<Key>, bucket_count> buckets_;
  std::size_t later_ = 0;       // keys in buckets
  std::size_t next_bucket_ = 0; // the first bucket not yet emptied into the heap
  double horizon_ = 0.0;        // where it starts: next_bucket_ / bucket_count (infinity past the last)
};

} // namespace medusa::kinetic::detail
