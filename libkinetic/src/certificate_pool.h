// The engine's certificates and their failure times, as one part with its own invariants (docs/MATH.md
// §3.1, §3.7): certificate ids are recycled, each id carries a version that every retirement moves on,
// and the queue holds (time, id, version) entries, so that an entry of a retired or reissued
// certificate is stale and skipped. What a certificate certifies, and how its time is found, is the
// engine's; this part only keeps the ids, versions and times consistent.
//
// Invariants (first_violation): the ids are exactly the alive ones and the free ones, each free id
// once; the queue is a heap in exact time order whose entries name existing ids.
#pragma once

#include "certificate.h"
#include "event_queue.h"
#include "medusa/kinetic/large_page_allocator.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

class CertificatePool {
public:
  // ---- certificates

  // A new alive certificate of the kind on key, with no substitute, under a fresh version.
  int create(CertKind kind, const Simplex& key);
  // The certificate dies: its version moves on (its queued entries go stale) and its id is free.
  // InternalError when it is not alive.
  void retire(int id);
  // Every certificate dies at once, and the ids are handed out again from 0 up (Engine::retire_all_certs).
  void retire_all();
  // What a certificate that vanishes for the whole slab is replaced by (Substitute).
  void set_substitute(int id, Substitute s) { certs_[index(id)].substitute = s; }
  // The cell holding a Delaunay certificate's facet, and the facet's index in it (Certificate::cell).
  void set_cell(int id, std::int32_t cell, int facet_index) {
    Certificate& c = certs_[index(id)];
    c.cell = cell;
    c.facet_index = static_cast<std::int8_t>(facet_index);
  }

  const Certificate& operator[](int id) const { return certs_[index(id)]; }
  // Starts loading certificate id's record (none for -1).
  void prefetch(int id) const {
    if (id >= 0)
      __builtin_prefetch(certs_.data() + index(id));
  }
  const Certificate& operator[](std::uint32_t id) const { return certs_[id]; }
  // Is (id, version) the certificate as it is now: alive, and not retired since that version.
  bool current(int id, std::uint32_t version) const {
    const Certificate& c = certs_[index(id)];
    return c.alive && c.version == version;
  }
  bool current(const QueueEntry& e) const { return current(static_cast<int>(e.cert), e.version); }
  std::size_t alive_count(CertKind kind) const;
  // The ids handed out so far, alive or free: every id is below it.
  std::size_t size() const { return certs_.size(); }

  // ---- failure times

  // Queues u as the failure time of certificate id in its present version (touch: a radius or hull
  // orientation touching zero at u without failing, Engine::resolve_touches).
  void schedule(int id, SlabTime u, bool touch = false) {
    events_.push({std::move(u), static_cast<std::uint32_t>(id), certs_[index(id)].version, touch});
  }
  // Drops stale entries from the front; then the earliest current entry, or nullptr when none is
  // left. Valid until the next schedule or pop.
  const QueueEntry* earliest();
  // The entry's certificate record is prefetched for the next earliest(), which reads it first.
  void pop() {
    events_.pop();
    if (const std::uint32_t next = events_.first_cert_hint(); next != EventQueue::none_queued)
      prefetch(static_cast<int>(next));
  }
  // The time of the earliest current entry, or of the earliest one later than `after`; `otherwise`
  // when there is none. Each costs a copy of the queue: for the audit and static repairs only.
  SlabTime earliest_time(SlabTime otherwise) const { return first_time(nullptr, std::move(otherwise)); }
  SlabTime next_time_after(const SlabTime& after, SlabTime otherwise) const {
    return first_time(&after, std::move(otherwise));
  }
  void clear_times() { events_.clear(); }
  std::size_t queued() const { return events_.size(); }

  // The first of the invariants above that fails, or an empty string.
  std::string first_violation() const;

private:
  static std::size_t index(int id) { return static_cast<std::size_t>(id); }
  SlabTime first_time(const SlabTime* after, SlabTime otherwise) const;

  LargeVector<Certificate> certs_;
  std::vector<int> free_;
  EventQueue events_;
};

} // namespace medusa::kinetic::detail
