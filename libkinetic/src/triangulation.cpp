#include "triangulation.h"

#include "medusa/kinetic/error.h"

#include <algorithm>
#include <sstream>

namespace medusa::kinetic::detail {

void Triangulation::clear() {
  tets_.clear();
  facets_.clear();
  incident_.clear();
}

void Triangulation::add_tet(const Simplex& t) {
  if (!tets_.insert(t).second) {
    std::ostringstream os;
    os << "top simplex " << t << " added twice";
    throw InternalError(os.str());
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    Apices& a = facets_[t.facet(i)];
    if (a.count == 2) {
      std::ostringstream os;
      os << "facet " << t.facet(i) << " would get a third top simplex " << t;
      throw InternalError(os.str());
    }
    a.v[a.count++] = t[i];
    incident_[t[i]].push_back(t);
  }
}

void Triangulation::remove_tet(const Simplex& t) {
  if (tets_.erase(t) == 0) {
    std::ostringstream os;
    os << "top simplex " << t << " removed but absent";
    throw InternalError(os.str());
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto it = facets_.find(t.facet(i));
    Apices& a = it->second;
    if (a.v[0] == t[i]) {
      a.v[0] = a.v[1];
    }
    --a.count;
    if (a.count == 0)
      facets_.erase(it);
    auto& list = incident_[t[i]];
    list.erase(std::find(list.begin(), list.end(), t));
    if (list.empty())
      incident_.erase(t[i]);
  }
}

const Triangulation::Apices* Triangulation::apices(const Simplex& facet) const {
  auto it = facets_.find(facet);
  return it == facets_.end() ? nullptr : &it->second;
}

VertexId Triangulation::other_apex(const Simplex& facet, VertexId apex) const {
  const Apices* a = apices(facet);
  if (a == nullptr || a->count != 2) {
    std::ostringstream os;
    os << "facet " << facet << " does not have two top simplices";
    throw InternalError(os.str());
  }
  return a->v[0] == apex ? a->v[1] : a->v[0];
}

const std::vector<Simplex>& Triangulation::tets_of(VertexId v) const {
  static const std::vector<Simplex> none;
  auto it = incident_.find(v);
  return it == incident_.end() ? none : it->second;
}

std::vector<Simplex> Triangulation::tets_containing(const Simplex& s) const {
  std::vector<Simplex> result;
  for (const Simplex& t : tets_of(s[0])) {
    bool all = true;
    for (VertexId v : s)
      all = all && t.contains(v);
    if (all)
      result.push_back(t);
  }
  return result;
}

} // namespace medusa::kinetic::detail
