// Resolving failed certificates at the current time: flips (MATH.md 4.5), Delaunay failures in
// canonical order and radius events (5.2).
#include "engine.h"

#include "dimension_policy.h"
#include "face.h"
#include "medusa/kinetic/certificate_polynomials.h"
#include "medusa/kinetic/error.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <vector>

namespace medusa::kinetic::detail {

void Engine::flip(const Simplex& facet, std::vector<Step>& steps) {
  const detail::Triangulation::Apices* ap = tri.apices(facet);
  VertexId p = ap->v[0], q = ap->v[1];
  Step step;
  std::vector<VertexId> group(facet.begin(), facet.end());
  group.push_back(p);
  group.push_back(q);
  FlipChange change = flip_change(dim, facet, p, q, tri);
  const std::vector<Simplex>&removed = change.removed, &added = change.added;
  const bool three_two = change.three_two;
  bool hull = std::find(group.begin(), group.end(), infinite_vertex) != group.end();
  std::array<int, 3> orientations{};
  for (std::size_t i = 0; i < added.size(); ++i)
    if (is_finite(added[i]) && (orientations[i] = orientation_sign_plus(added[i])) == 0) {
      // A new top simplex would stay flat: no elementary flip resolves this degenerate group (e.g.
      // four points coplanar through the slab); MATH.md 5.2 step 3 asks for a static repair.
      repair(steps);
      return;
    }
  step.kind = hull        ? StepKind::hull_flip
              : dim == 2  ? StepKind::flip22
              : three_two ? StepKind::flip32
                          : StepKind::flip23;
  if (!hull) {
    // The simplex of the group (a 4-simplex; a 3-simplex in 2D) is an instant cell iff R_S <= rho and
    // the old top simplices are in K (MATH.md 6.3). The old top simplices are inscribed in the
    // group's sphere (circle) at now, so the radius of any of them is R_S.
    bool old_in_k = true;
    for (const Simplex& t : removed)
      old_in_k = old_in_k && in_k(t);
    const Simplex& old = removed.front();
    FlipGroup g;
    std::sort(group.begin(), group.end());
    g.vertices = group;
    g.in_alpha = old_in_k && sign_at_now([&](auto tag) {
                               return radius_poly<decltype(tag)>(old, pick(P, Pi, tag), pick(Q, Qi, tag));
                             }) <= 0;
    step.flip = g;
    step.delaunay_removed = removed;
    step.delaunay_created = added;
  }
  apply_tet_change(removed, added, orientations.data());
  settle_touched(step);
  finish_tet_change();
  (hull ? stats.hull_flips : dim == 2 ? stats.flips22 : (three_two ? stats.flips32 : stats.flips23))++;
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
}

// Static repair of the whole triangulation at now+ as one step (MATH.md 5.2 step 3, 5.4).
void Engine::repair(std::vector<Step>& steps) {
  if (!now.is_rational())
    ++stats.repairs_at_algebraic_times;
  Step step;
  step.kind = StepKind::repair;
  OldMembership old_k;
  record_tet_changes(step, old_k);
  // The non-simplicial Delaunay faces at now give instant cells (MATH.md 6.3), in either dimension
  // (engine_degenerate_groups.cpp).
  step.groups = degenerate_groups(step.delaunay_removed, step.delaunay_created);
  settle_membership(old_k, step);
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
}

// Whether the 2-2 flip of a failed edge yields a triangulation at now+ (MATH.md 5.2 step 2, "if its
// configuration is flippable"): the new edge pq must not exist yet (a vertex of degree 3 cannot lose
// an edge by a flip), a finite quadrilateral xpyq must be strictly convex (x and y strictly on either
// side of pq just after now), and a new finite triangle of a hull flip must not stay flat. A failed
// certificate in generic motion always passes; simultaneous degenerate failures may not.
bool Engine::flippable_2(const Simplex& facet) {
  const detail::Triangulation::Apices* ap = tri.apices(facet);
  VertexId p = ap->v[0], q = ap->v[1];
  if (tri.apices(Simplex{p, q}) != nullptr)
    return false;
  if (is_finite(facet) && p != infinite_vertex && q != infinite_vertex) {
    auto side = [&](VertexId x) {
      return sign_plus_now(
          [&](auto tag) { return certificate::orientation_2<decltype(tag)>(pt(p), pt(q), pt(x)); });
    };
    return side(facet[0]) * side(facet[1]) < 0;
  }
  for (const Simplex& t : flip_change(dim, facet, p, q, tri).added)
    if (is_finite(t) && orientation_sign_plus(t) == 0)
      return false;
  return true;
}

void Engine::resolve_delaunay(std::vector<Step>& steps) {
  std::size_t guard = 0;
  const std::size_t limit = 20 * traj.cells.size() + 1000;
  while (!pending_delaunay.empty()) {
    if (++guard > limit) {
      std::ostringstream os;
      os << "no progress resolving degenerate Delaunay events in slab " << slab << " at u ~ " << now.approx();
      throw InternalError(os.str());
    }
    if (dim == 2) {
      // The first flippable failure in canonical order; a static repair when none is (MATH.md 5.2
      // steps 2 and 3).
      bool flipped = false;
      for (auto it = pending_delaunay.begin(); it != pending_delaunay.end();) {
        auto [facet, id] = *it;
        if (!certs[static_cast<std::size_t>(id)].alive || certs[static_cast<std::size_t>(id)].key != facet) {
          it = pending_delaunay.erase(it);
          continue;
        }
        if (flippable_2(facet)) {
          pending_delaunay.erase(it);
          flip(facet, steps);
          flipped = true;
          break;
        }
        ++it;
      }
      if (!flipped && !pending_delaunay.empty())
        repair(steps);
      continue;
    }
    auto [facet, id] = *pending_delaunay.begin();
    pending_delaunay.erase(pending_delaunay.begin());
    if (!certs[static_cast<std::size_t>(id)].alive || certs[static_cast<std::size_t>(id)].key != facet)
      continue;
    flip(facet, steps);
  }
}

// Radius events: toggle shortness of the failed certificates, then one settle step.
void Engine::resolve_radius(Step& settle, OldMembership& old_k) {
  // Swapped with a kept buffer: certificates failing meanwhile go to pending_radius, and neither
  // vector is reallocated per event.
  std::vector<std::pair<int, std::uint32_t>>& failed = radius_scratch;
  failed.clear();
  failed.swap(pending_radius);
  for (auto [id, version] : failed) {
    const Certificate& c = certs[static_cast<std::size_t>(id)];
    if (!c.alive || c.version != version)
      continue;
    Simplex s = c.key;
    for_each_face(s, [&](const Simplex& f) { old_k.emplace(f, in_k(f)); });
    // Faces' membership depends on cofaces: also record the cofaces' faces through the closure.
    Face& f = faces.at(s);
    count_in_facets(s, f.is_short ? -1 : +1, 0);
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
