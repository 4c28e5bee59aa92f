#include "certificate_pool.h"

#include "medusa/core/error.h"

#include <sstream>

namespace medusa::kinetic::detail {

int CertificatePool::create(CertKind kind, const Simplex& key) {
  int id;
  if (!free_.empty()) {
    id = free_.back();
    free_.pop_back();
  } else {
    id = static_cast<int>(certs_.size());
    certs_.emplace_back();
  }
  Certificate& c = certs_[index(id)];
  c.kind = kind;
  c.key = key;
  c.alive = true;
  c.substitute = Substitute::none;
  c.cell = -1;
  c.facet_index = 0;
  ++c.version;
  return id;
}

void CertificatePool::retire(int id) {
  Certificate& c = certs_[index(id)];
  if (!c.alive) {
    std::ostringstream os;
    os << "certificate " << id << " of " << c.key << " retired twice";
    throw InternalError(os.str());
  }
  c.alive = false;
  ++c.version;
  free_.push_back(id);
}

// Retired from the last id down, so that the free list hands them out from 0 up: the frame then
// installs certificate i + 1 beside certificate i, in the order it visits the simplices, and retires
// them in that order at the next frame (retiring them in the order of the last slab's flips was a
// cache miss each). Stale (id, version) pairs stay stale.
void CertificatePool::retire_all() {
  free_.clear();
  for (std::size_t id = certs_.size(); id-- > 0;) {
    Certificate& c = certs_[id];
    if (c.alive) {
      c.alive = false;
      ++c.version;
    }
    free_.push_back(static_cast<int>(id));
  }
}

std::size_t CertificatePool::alive_count(CertKind kind) const {
  std::size_t n = 0;
  for (const Certificate& c : certs_)
    n += c.alive && c.kind == kind ? 1 : 0;
  return n;
}

const QueueEntry* CertificatePool::earliest() {
  while (!events_.empty() && !current(events_.top()))
    events_.pop();
  return events_.empty() ? nullptr : &events_.top();
}

SlabTime CertificatePool::first_time(const SlabTime* after, SlabTime otherwise) const {
  for (EventQueue copy = events_; !copy.empty(); copy.pop())
    if (current(copy.top()) && (after == nullptr || *after < copy.top().u))
      return copy.top().u;
  return otherwise;
}

std::string CertificatePool::first_violation() const {
  std::vector<char> is_free(certs_.size(), 0);
  for (int id : free_) {
    if (id < 0 || index(id) >= certs_.size())
      return "a free certificate id is out of range";
    if (is_free[index(id)]++)
      return "certificate " + std::to_string(id) + " is free twice";
    if (certs_[index(id)].alive)
      return "certificate " + std::to_string(id) + " is alive and free";
  }
  for (std::size_t id = 0; id < certs_.size(); ++id)
    if (!is_free[id] && !certs_[id].alive)
      return "certificate " + std::to_string(id) + " is neither alive nor free";
  if (std::string v = events_.first_violation(); !v.empty())
    return v;
  for (EventQueue copy = events_; !copy.empty(); copy.pop())
    if (copy.top().cert >= certs_.size())
      return "a queued time names certificate " + std::to_string(copy.top().cert) + ", which does not exist";
  return {};
}

} // namespace medusa::kinetic::detail
