#include "triangulation.h"

#include "kinetic_traits.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <sstream>
#include <unordered_set>
#include <utility>

namespace medusa::kinetic::detail {

void Triangulation::clear() {
  memo_ = nullptr;
  top_count_ = 0;
  facets_.clear();
  incident_.clear();
}

void Triangulation::add_top(const Simplex& t, int orientation) {
  memo_ = nullptr;
  for (std::size_t i = 0; i < t.size(); ++i) {
    Apices& a = facets_[t.facet(i)];
    if (i == 0 && a.orientation_slot(t[0]) >= 0) {
      std::ostringstream os;
      os << "top simplex " << t << " added twice";
      throw InternalError(os.str());
    }
    if (a.count == 2) {
      std::ostringstream os;
      os << "facet " << t.facet(i) << " would get a third top simplex " << t;
      throw InternalError(os.str());
    }
    a.v[static_cast<std::size_t>(a.count)] = t[i];
    a.orientation[static_cast<std::size_t>(a.count)] = static_cast<signed char>(orientation);
    ++a.count;
    const std::size_t slot = static_cast<std::size_t>(t[i] + 1);
    if (slot >= incident_.size())
      incident_.resize(slot + 1);
    incident_[slot].push_back(t);
  }
  ++top_count_;
}

void Triangulation::set_orientation(const Simplex& t, int orientation) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    Apices& a = facets_.at(t.facet(i));
    a.orientation[static_cast<std::size_t>(a.orientation_slot(t[i]))] = static_cast<signed char>(orientation);
  }
}

void Triangulation::remove_top(const Simplex& t, std::vector<int>& dropped_certs) {
  memo_ = nullptr;
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto it = facets_.find(t.facet(i));
    if (it == facets_.end() || it->second.orientation_slot(t[i]) < 0) {
      // Only the first facet can fail: when t is present, all its facets hold it.
      std::ostringstream os;
      os << "top simplex " << t << " removed but absent";
      throw InternalError(os.str());
    }
    Apices& a = it->second;
    if (a.v[0] == t[i]) {
      a.v[0] = a.v[1];
      a.orientation[0] = a.orientation[1];
    }
    --a.count;
    if (a.count == 0) {
      if (a.cert >= 0)
        dropped_certs.push_back(a.cert);
      facets_.erase(it);
    }
    auto& list = incident_[static_cast<std::size_t>(t[i] + 1)];
    // Order within the list is not used: swap with the last and pop.
    *std::find(list.begin(), list.end(), t) = list.back();
    list.pop_back();
  }
  --top_count_;
}

void Triangulation::prefetch_top(const Simplex& t) const {
  for (std::size_t i = 0; i < t.size(); ++i)
    facets_.prefetch(t.facet(i));
  for (VertexId v : t) {
    const std::size_t slot = static_cast<std::size_t>(v + 1);
    if (slot < incident_.size() && !incident_[slot].empty())
      __builtin_prefetch(incident_[slot].data());
  }
}

const Triangulation::Apices* Triangulation::apices(const Simplex& facet) const {
  if (memo_ != nullptr && memo_key_ == facet)
    return memo_;
  auto it = facets_.find(facet);
  if (it == facets_.end())
    return nullptr;
  memo_key_ = facet;
  memo_ = &it->second;
  return memo_;
}

Triangulation::Apices* Triangulation::apices(const Simplex& facet) {
  // The record is in this (non-const) triangulation's own table.
  return const_cast<Apices*>(std::as_const(*this).apices(facet));
}

const Triangulation::Apices& Triangulation::two_sided(const Simplex& facet) const {
  const Apices* a = apices(facet);
  if (a == nullptr || a->count != 2) {
    std::ostringstream os;
    os << "facet " << facet << " does not have two top simplices";
    throw InternalError(os.str());
  }
  return *a;
}

const std::vector<Simplex>& Triangulation::tops_of(VertexId v) const {
  static const std::vector<Simplex> none;
  const std::size_t slot = static_cast<std::size_t>(v + 1);
  return slot < incident_.size() ? incident_[slot] : none;
}

std::vector<Simplex> Triangulation::tops_containing(const Simplex& s) const {
  std::vector<Simplex> result;
  for_each_top_containing(s, [&](const Simplex& t) { result.push_back(t); });
  return result;
}

std::vector<Simplex> Triangulation::finite_cofaces(const Simplex& s) const {
  // A coface is s plus one vertex of a finite top simplex holding s (it may come from several).
  std::vector<Simplex> result;
  for_each_top_containing(s, [&](const Simplex& t) {
    if (!is_finite(t))
      return;
    for (VertexId v : t)
      if (!s.contains(v))
        result.push_back(s.with(v));
  });
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

std::string Triangulation::first_violation(int dimension) const {
  const auto named = [](const char* what, const Simplex& s) {
    std::ostringstream os;
    os << what << ' ' << s;
    return os.str();
  };
  for (const auto& [facet, a] : facets_)
    if (a.count != 2)
      return named("top simplices: not two at facet", facet);
  std::size_t listed = 0, incidences = 0, vertices = 0;
  std::unordered_set<Simplex, SimplexHash> edges;
  for (const Simplex& t : tops()) {
    ++listed;
    const int o = orientation(t);
    if ((o == 0) != !is_finite(t))
      return named("a finite top simplex has no orientation, or an infinite one has one:", t);
    for (std::size_t i = 0; i < t.size(); ++i) {
      const Apices* a = apices(t.facet(i));
      if (a == nullptr || a->orientation_with(t[i]) != o || a->orientation_slot(t[i]) < 0)
        return named("a facet does not hold its top simplex, or holds another orientation:", t);
      const std::vector<Simplex>& list = tops_of(t[i]);
      if (std::count(list.begin(), list.end(), t) != 1)
        return named("a top simplex is not listed once at its vertex:", t);
      for (std::size_t j = i + 1; j < t.size(); ++j)
        edges.insert(Simplex{t[i], t[j]});
    }
  }
  for (const std::vector<Simplex>& list : incident_) {
    incidences += list.size();
    vertices += list.empty() ? 0 : 1;
  }
  if (listed != top_count_)
    return "the count of top simplices is not the number listed";
  if (incidences != listed * (static_cast<std::size_t>(dimension) + 1))
    return "a vertex lists a top simplex that is not one";
  const bool euler =
      dimension == 2
          ? KineticTraits2::euler_characteristic_holds(vertices, edges.size(), facets_.size(), listed)
          : KineticTraits3::euler_characteristic_holds(vertices, edges.size(), facets_.size(), listed);
  if (!euler)
    return "the Euler characteristic of the augmented triangulation is not that of a sphere";
  return {};
}

} // namespace medusa::kinetic::detail
