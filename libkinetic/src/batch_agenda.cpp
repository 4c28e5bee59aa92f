#include "batch_agenda.h"

#include <sstream>

namespace medusa::kinetic::detail {

bool BatchAgenda::live(const CertificatePool& pool, const Simplex& facet, int id) {
  if (id < 0 || static_cast<std::size_t>(id) >= pool.size())
    return false;
  const Certificate& c = pool[id];
  return c.alive && c.kind == CertKind::delaunay && c.key == facet;
}

std::string BatchAgenda::first_violation(const CertificatePool& pool, bool between_batches) const {
  for (const auto& [facet, id] : delaunay_) {
    if (!live(pool, facet, id)) {
      std::ostringstream os;
      os << "the failure of certificate " << id << " on facet " << facet
         << " is held, but that is not a live Delaunay certificate on it";
      return os.str();
    }
  }
  if (!between_batches)
    return {};
  if (!delaunay_.empty() || !radius_.empty())
    return "a batch ended with failed certificates left unresolved";
  if (!touches_.empty() || !hull_touches_.empty())
    return "a batch ended with touches left unresolved";
  if (repair_due_)
    return "a batch ended with a static repair due";
  if (!fired_.empty())
    return "a batch ended still holding the times its certificates fired at";
  return {};
}

} // namespace medusa::kinetic::detail
