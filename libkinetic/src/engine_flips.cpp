// Resolving failed certificates at the current time: flips (MATH.md 4.5), Delaunay failures in
// canonical order and radius events (5.2).
#include "engine.h"

#include "face.h"
#include "medusa/kinetic/error.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace medusa::kinetic::detail {

void Engine::flip(const Simplex& facet, std::vector<Step>& steps) {
  const detail::Triangulation::Apices* ap = tri.apices(facet);
  VertexId p = ap->v[0], q = ap->v[1];
  Step step;
  std::vector<Simplex> removed, added;
  std::array<VertexId, 5> group{facet[0], facet[1], facet[2], p, q};
  // A 3-2 flip applies when an edge of the facet has exactly the three tetrahedra facet+p,
  // facet+q and edge+p+q; otherwise the 2-3 flip of the facet.
  bool three_two = false;
  for (std::size_t i = 0; i < 3 && !three_two; ++i) {
    Simplex e = facet.facet(i);
    Simplex t{e[0], e[1], p, q};
    if (tri.has_tet(t)) {
      three_two = true;
      VertexId z = facet[i];
      removed = {Simplex{facet[0], facet[1], facet[2], p}, Simplex{facet[0], facet[1], facet[2], q}, t};
      added = {Simplex{z, p, q, e[0]}, Simplex{z, p, q, e[1]}};
    }
  }
  if (!three_two) {
    removed = {Simplex{facet[0], facet[1], facet[2], p}, Simplex{facet[0], facet[1], facet[2], q}};
    for (std::size_t i = 0; i < 3; ++i) {
      Simplex e = facet.facet(i);
      added.push_back(Simplex{e[0], e[1], p, q});
    }
  }
  bool hull = std::find(group.begin(), group.end(), infinite_vertex) != group.end();
  for (const Simplex& t : added)
    if (is_finite(t) && orientation_sign_plus(t) == 0) {
      // A new tetrahedron would stay flat: no elementary flip resolves this degenerate group
      // (e.g. four points coplanar through the slab); MATH.md 5.2 step 3 asks for a static repair.
      if (!now.is_rational())
        ++stats.repairs_at_algebraic_times;
      Step repair;
      repair.kind = StepKind::repair;
      std::unordered_map<Simplex, bool, SimplexHash> old_k;
      record_tet_changes(repair, old_k);
      repair.groups = degenerate_groups(repair.delaunay_removed, repair.delaunay_created);
      settle_membership(old_k, repair);
      repair.rank = steps.size() + 1;
      steps.push_back(std::move(repair));
      return;
    }
  step.kind = hull ? StepKind::hull_flip : (three_two ? StepKind::flip32 : StepKind::flip23);
  if (!hull) {
    // The 4-simplex is an instant cell iff R_S <= rho and the old tetrahedra are in K (MATH.md 6.3).
    const Simplex& old = removed.front();
    int r = sign_at_now(
        [&](auto tag) { return radius_poly<decltype(tag)>(old, pick(P, Pi, tag), pick(Q, Qi, tag)); });
    bool old_in_k = true;
    for (const Simplex& t : removed)
      old_in_k = old_in_k && in_k(t);
    FlipGroup g;
    std::sort(group.begin(), group.end());
    g.vertices = group;
    g.in_alpha = r <= 0 && old_in_k;
    step.flip = g;
    step.delaunay_removed = removed;
    step.delaunay_created = added;
  }
  std::unordered_map<Simplex, bool, SimplexHash> old_k;
  change_tets(removed, added, old_k);
  settle_membership(old_k, step);
  (hull ? stats.hull_flips : (three_two ? stats.flips32 : stats.flips23))++;
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
}

void Engine::resolve_delaunay(std::vector<Step>& steps) {
  std::size_t guard = 0;
  const std::size_t limit = 20 * traj.cells.size() + 1000;
  while (!pending_delaunay.empty()) {
    auto [facet, id] = *pending_delaunay.begin();
    pending_delaunay.erase(pending_delaunay.begin());
    if (!certs[static_cast<std::size_t>(id)].alive || certs[static_cast<std::size_t>(id)].key != facet)
      continue;
    if (++guard > limit) {
      std::ostringstream os;
      os << "no progress resolving degenerate Delaunay events in slab " << slab << " at u ~ " << now.approx();
      throw InternalError(os.str());
    }
    flip(facet, steps);
  }
}

// Radius events: toggle shortness of the failed certificates, then one settle step.
void Engine::resolve_radius(Step& settle, std::unordered_map<Simplex, bool, SimplexHash>& old_k) {
  std::vector<std::pair<int, std::uint32_t>> failed;
  failed.swap(pending_radius);
  for (auto [id, version] : failed) {
    const Certificate& c = certs[static_cast<std::size_t>(id)];
    if (!c.alive || c.version != version)
      continue;
    Simplex s = c.key;
    for_each_face(s, [&](const Simplex& f) { old_k.emplace(f, in_k(f)); });
    // Faces' membership depends on cofaces: also record the cofaces' faces through the closure.
    Face& f = faces.at(s);
    f.is_short = !f.is_short;
    install_radius(s);
    ++stats.radius_events;
    // Frontier update rules of MATH.md 4.4: facets may leave or enter, cofaces may enter or leave.
    if (s.size() > 2)
      for (std::size_t i = 0; i < s.size(); ++i)
        update_frontier(s.facet(i));
    for (const Simplex& c : cofaces(s))
      update_frontier(c);
  }
  (void)settle;
}

} // namespace medusa::kinetic::detail
