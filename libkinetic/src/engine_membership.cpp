// Triangulation changes and the alpha complex on them: replacing tetrahedra, cofaces, the frontier
// of radius certificates (MATH.md 4.4), the Gabriel test and membership re-evaluation (4.5).
#include "engine.h"

#include "face.h"
#include "medusa/kinetic/certificate_polynomials.h"
#include "medusa/kinetic/error.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <vector>

namespace medusa::kinetic::detail {

bool Engine::in_k(const Simplex& s) const {
  if (s.size() == 1)
    return alive[static_cast<std::size_t>(s[0])] != 0;
  auto it = faces.find(s);
  return it != faces.end() && it->second.in_k;
}

// Replaces tetrahedra; records the old membership of every touched finite simplex. The caller may
// pass the orientations sign^+ of the added top simplices (0 for infinite ones) it has computed.
void Engine::change_tets(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                         OldMembership& old_k, const int* added_orientations) {
  // The finite faces and the facets of the changed top simplices, each once, in canonical order.
  std::vector<Simplex> touched_faces, touched_facets;
  for (const auto* list : {&removed, &added})
    for (const Simplex& t : *list) {
      for_each_face(t, [&](const Simplex& f) { touched_faces.push_back(f); });
      for (std::size_t i = 0; i < t.size(); ++i)
        touched_facets.push_back(t.facet(i));
    }
  for (auto* v : {&touched_faces, &touched_facets}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  for (const Simplex& f : touched_faces)
    old_k.emplace(f, in_k(f));
  // Each face counts the top simplices (infinite ones included) that hold it, so its presence in
  // Del after the change needs no search of the triangulation.
  std::vector<Simplex> created;
  for (const Simplex& t : removed) {
    tri.remove_tet(t);
    orient.erase(t);
    for_each_face(t, [&](const Simplex& f) {
      if (f.size() > 1)
        --faces.at(f).tets;
    });
  }
  for (std::size_t i = 0; i < added.size(); ++i) {
    const Simplex& t = added[i];
    tri.add_tet(t);
    if (is_finite(t)) {
      int s = added_orientations != nullptr ? added_orientations[i] : orientation_sign_plus(t);
      if (s == 0) {
        std::ostringstream os;
        os << "cells " << t
           << (dim == 2 ? " stay collinear but form a Delaunay triangle"
                        : " stay coplanar but form a Delaunay tetrahedron");
        throw GeometryError(os.str());
      }
      orient[t] = s;
    }
    for_each_face(t, [&](const Simplex& f) {
      if (f.size() == 1)
        return;
      auto [it, fresh] = faces.try_emplace(f);
      if (fresh)
        created.push_back(f);
      ++it->second.tets;
    });
  }
  for (const Simplex& f : touched_faces) {
    auto it = faces.find(f);
    if (it != faces.end() && it->second.tets == 0) {
      kill_cert(it->second.cert);
      faces.erase(it);
    }
  }
  for (const Simplex& f : created) {
    if (f.size() == 2 && slab + 1 < traj.frames())
      check_collision(f);
    faces.at(f).is_short = compute_short(f);
  }
  // Frontier membership of every surviving touched simplex: their cofaces changed (MATH.md 4.4,
  // "after any change of Del"). Cofaces of new simplices are new, hence touched as well.
  for (const Simplex& f : touched_faces)
    if (f.size() > 1 && faces.count(f))
      update_frontier(f);
  for (const Simplex& f : touched_facets)
    install_facet(f);
}

bool Engine::is_short(const Simplex& s) const {
  if (s.size() == 1)
    return true;
  auto it = faces.find(s);
  return it != faces.end() && it->second.is_short;
}

// The (k+1)-cofaces of a finite simplex in Del (finite ones only), sorted.
std::vector<Simplex> Engine::cofaces(const Simplex& s) const {
  std::vector<Simplex> result;
  for_each_coface(s, [&](const Simplex& c) {
    result.push_back(c);
    return false;
  });
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

// The frontier (MATH.md 4.4): maximal short simplices and minimal long ones.
bool Engine::in_frontier(const Simplex& s) const {
  if (is_short(s))
    return !for_each_coface(s, [&](const Simplex& c) { return is_short(c); });
  if (s.size() == 2)
    return true;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!is_short(s.facet(i)))
      return false;
  return true;
}

// Creates or drops the radius certificate of s so that exactly the frontier carries one.
void Engine::update_frontier(const Simplex& s) {
  Face& f = faces.at(s);
  bool want = in_frontier(s);
  if (want && f.cert < 0)
    install_radius(s);
  else if (!want && f.cert >= 0) {
    kill_cert(f.cert);
    f.cert = -1;
  }
}

bool Engine::gabriel_now(const Simplex& s) {
  // Not strictly inside the smallest circumball: sign^+ of G1/G2 >= 0 (MATH.md 3.4, 4.1 Lemma 4.2),
  // for every link vertex (each tested once).
  std::array<VertexId, 64> seen{};
  std::size_t n_seen = 0;
  bool gabriel = true;
  tri.for_each_tet_containing(s, [&](const Simplex& t) {
    for (VertexId x : t) {
      if (!gabriel || x == infinite_vertex || s.contains(x))
        continue;
      if (std::find(seen.begin(), seen.begin() + static_cast<std::ptrdiff_t>(n_seen), x) !=
          seen.begin() + static_cast<std::ptrdiff_t>(n_seen))
        continue;
      if (n_seen < seen.size())
        seen[n_seen++] = x;
      int g = sign_plus_now([&](auto tag) {
        using NT = decltype(tag);
        return s.size() == 2 ? certificate::gabriel_edge<NT>(pt(s[0]), pt(s[1]), pt(x))
                             : certificate::gabriel_triangle<NT>(pt(s[0]), pt(s[1]), pt(s[2]), pt(x));
      });
      if (g < 0)
        gabriel = false;
    }
  });
  return gabriel;
}

bool Engine::has_coface_in_k(const Simplex& s) const {
  return for_each_coface(s, [&](const Simplex& c) { return in_k(c); });
}

// Re-evaluates membership (MATH.md 4.5 "re-eval") on the touched simplices, in decreasing
// dimension, and fills the step's entered/left lists.
void Engine::settle_membership(const OldMembership& old_k, Step& step) {
  std::vector<Simplex> order;
  order.reserve(old_k.size());
  for (const auto& kv : old_k)
    order.push_back(kv.first);
  std::sort(order.begin(), order.end(), [](const Simplex& a, const Simplex& b) { return b < a; });
  for (const Simplex& s : order) {
    if (s.size() == 1)
      continue;
    auto it = faces.find(s);
    if (it == faces.end())
      continue;
    Face& f = it->second;
    if (s.size() == top_size())
      f.in_k = f.is_short; // top simplices are always Gabriel (MATH.md 4.1)
    else
      // Every simplex of K is short (its smallest circumsphere is no larger than an empty sphere of
      // radius <= rho, MATH.md 4.1), so a long one is out without looking at its cofaces.
      f.in_k = f.is_short && (has_coface_in_k(s) || gabriel_now(s));
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    bool before = old_k.at(*it), after = in_k(*it);
    if (before && !after)
      step.left.push_back(*it);
    else if (!before && after)
      step.entered.push_back(*it);
  }
}

std::vector<Simplex> Engine::current_complex() const {
  std::vector<Simplex> k;
  for (std::size_t i = 0; i < alive.size(); ++i)
    if (alive[i])
      k.push_back(Simplex{static_cast<VertexId>(i)});
  for (const auto& kv : faces)
    if (kv.second.in_k)
      k.push_back(kv.first);
  std::sort(k.begin(), k.end());
  return k;
}

} // namespace medusa::kinetic::detail
