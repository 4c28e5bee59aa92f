// Resolving failed certificates at the current time: flips (docs/MATH.md §4.5), Delaunay failures in
// canonical order and radius events (5.2).
#pragma once

#include "engine.h"

#include "certificate_polynomials.h"
#include "face.h"
#include "medusa/core/error.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> void Engine<K>::flip(int cert, const FlipChange& change, std::vector<Step>& steps) {
  const Simplex facet = certificates[cert].key; // copies: the flip retires the certificate
  const HeldFlip held{certificates[cert].cell, certificates[cert].facet_index, &change};
  const Apices ap = cells.apices(held.cell, held.index);
  VertexId p = ap.v[0], q = ap.v[1];
  Step step;
  std::vector<VertexId> group(facet.begin(), facet.end());
  group.push_back(p);
  group.push_back(q);
  const std::vector<Simplex>&removed = change.removed, &added = change.added;
  const bool three_two = change.three_two;
  bool hull = std::find(group.begin(), group.end(), infinite_vertex) != group.end();
  std::array<int, 3> orientations{};
  for (std::size_t i = 0; i < added.size(); ++i)
    if (is_finite(added[i]) && (orientations[i] = orientation_sign_plus(added[i])) == 0) {
      // A new top simplex would stay flat: no elementary flip resolves this degenerate group (e.g.
      // four points coplanar through the slab); docs/MATH.md §5.2 step 3 asks for a static repair.
      repair(steps);
      return;
    }
  step.kind = hull        ? StepKind::hull_flip
              : dim == 2  ? StepKind::flip22
              : three_two ? StepKind::flip32
                          : StepKind::flip23;
  if (!hull) {
    // The simplex of the group (a 4-simplex; a 3-simplex in 2D) is an instant cell iff R_S <= rho and
    // the old top simplices are in K (docs/MATH.md §6.3). The old top simplices are inscribed in the
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
  }
  // A hull flip removes (case A) or creates (case B) the finite top simplex that is flat at now.
  record_delaunay_change(step, removed, added);
  apply_top_change(removed, {}, added, orientations.data(), &held);
  install_touched_facets();
  settle_touched(step);
  finish_top_change();
  (hull ? stats.hull_flips : dim == 2 ? stats.flips22 : (three_two ? stats.flips32 : stats.flips23))++;
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
}

// Static repair of the whole triangulation at now+ as one step (docs/MATH.md §5.2 step 3, 5.4).
template <class K> void Engine<K>::repair(std::vector<Step>& steps) {
  if (!now.is_rational())
    ++stats.repairs_at_algebraic_times;
  Step step;
  step.kind = StepKind::repair;
  OldMembership old_k;
  record_top_changes(step, old_k);
  // The non-simplicial Delaunay faces at now give instant cells (docs/MATH.md §6.3), in either dimension
  // (engine/degenerate_groups.h).
  step.groups = degenerate_groups(step.delaunay_removed, step.delaunay_created);
  settle_membership(old_k, step);
  step.rank = steps.size() + 1;
  steps.push_back(std::move(step));
}

// Whether the elementary flip of a failed facet yields a triangulation at now+ (docs/MATH.md §5.2 step 2,
// "if its configuration is flippable"). A failed certificate in generic motion always passes;
// simultaneous degenerate failures (six or more cospherical points, an edge of degree four, a cycle
// of flips) may not, and step 3 then asks for a static repair. `change` receives the flip.
template <class K> bool Engine<K>::flippable(int cert, FlipChange& change) {
  const Simplex& facet = certificates[cert].key;
  const CellIndex c = certificates[cert].cell;
  const int i = certificates[cert].facet_index;
  const VertexId p = cells.vertex(c, i), q = cells.apex_across(c, i);
  // The top simplices of the flip are c (facet + p), its neighbour across the facet (facet + q) and,
  // for a 3-2 flip, the neighbour of c across the facet without the facet's vertex off the edge.
  const auto cell_across_from = [&](VertexId z) { return cells.neighbor(c, cells.index_of(c, z)); };
  // Whether the simplex s through p and q is in the triangulation. A finite one is if it has a face
  // state (FaceStates records exactly the finite faces of Del): one look-up where a walk would
  // enter a whole vertex star, cell by cell, to tell that it is absent. One through the infinite
  // vertex (a hull flip) is found by a walk round its finite apex.
  const auto present = [&](const Simplex& s) {
    if (is_finite(s))
      return faces.find(s) != nullptr;
    return (p != infinite_vertex ? cells.cell_containing_from(c, p, s)
                                 : cells.cell_containing_from(cells.neighbor(c, i), q, s)) != no_cell;
  };
  change = K::flip(facet, p, q, [&](const Simplex& t) {
    for (VertexId z : facet)
      if (!t.contains(z))
        return cells.apex_across(c, cells.index_of(c, z)) == q;
    return false;
  });
  // A finite flip replaces top simplices that cover a region at now+ by others covering it. A top
  // simplex flat at now may be inside out just after it: the triangulation around it is then not
  // embedded at now+, the local tests below can pass a flip that leaves it so, and later certificates,
  // read against the orientations recorded, miss the inversion (e.g. four cells on one line at an
  // instant; docs/MATH.md §5.10). Only a static repair decides such a neighbourhood. Hull flips are exempt:
  // their certificates are orientations (docs/MATH.md §3.2), so the top simplex a hull flip removes (case A)
  // or adds (case B) is flat at now by definition.
  if (is_finite(facet) && p != infinite_vertex && q != infinite_vertex)
    for (const Simplex& t : change.removed)
      if (flat_at_now(t))
        return false;
  if constexpr (dim == 2) {
    // 2-2: the new edge pq must not exist yet (a vertex of degree 3 cannot lose an edge by a flip),
    // and a finite quadrilateral xpyq must be strictly convex (x and y strictly on either side of pq).
    if (present(Simplex{p, q}))
      return false;
    if (is_finite(facet) && p != infinite_vertex && q != infinite_vertex) {
      auto side = [&](VertexId x) {
        return sign_plus_now(
            [&](auto tag) { return certificate::orientation_2<decltype(tag)>(pt(p), pt(q), pt(x)); });
      };
      return side(facet[0]) * side(facet[1]) < 0;
    }
  }
  // The flip must not create a simplex that is there already (a 2-3 flip's edge pq, a 3-2 flip's
  // triangle z p q). A triangulation embedded at now+ never has one, but one with top simplices flat
  // at now may not be embedded: at a frame, new velocities can turn a flat tetrahedron inside out,
  // and on a flat hull (a lattice) simultaneous failures set this up too. The local tests below do
  // not see it (tests/kinetic/test_kinetic_dense_lattice.cpp).
  if (dim == 3 && present(change.three_two ? Simplex{change.z, p, q} : Simplex{p, q}))
    return false;
  if (dim == 3 && is_finite(facet) && p != infinite_vertex && q != infinite_vertex) {
    // 2-3: the segment pq crosses the triangle's interior; 3-2 (the edge e0e1 of the facet has the
    // third tetrahedron e0 e1 p q): the edge crosses the triangle z p q of its ring. A line ab crosses
    // a triangle xyz (whose plane separates a and b, as it does here) iff orient(a, b, x, y),
    // orient(a, b, y, z) and orient(a, b, z, x) have one sign, none zero.
    auto crosses = [&](VertexId a, VertexId b, VertexId x, VertexId y, VertexId z) {
      auto side = [&](VertexId u, VertexId v) {
        {
          // At now's enclosure first: in generic motion no four of the group are coplanar at now.
          CGAL::Protect_FPU_rounding<true> guard;
          const auto at = points_at_now();
          const Interval o = certificate::orientation<Interval>(at(a), at(b), at(u), at(v));
          if (o.inf() > 0 || o.sup() < 0) {
            ++stats.sign_evaluations;
            return o.inf() > 0 ? 1 : -1;
          }
        }
        return sign_plus_now(
            [&](auto tag) { return certificate::orientation<decltype(tag)>(pt(a), pt(b), pt(u), pt(v)); });
      };
      const int s = side(x, y);
      return s != 0 && side(y, z) == s && side(z, x) == s;
    };
    return change.three_two ? crosses(change.edge[0], change.edge[1], change.z, p, q)
                            : crosses(p, q, facet[0], facet[1], facet[2]);
  }
  // A hull flip: around the infinite vertex the orientations above do not decide; the combinatorics
  // (checked first) do, and its new finite top simplices must not stay flat. One flat at now without
  // turning there (Engine::flat_without_turning_at_now) shows that the batch's flips have left the
  // triangulation not embedded just after now, where the certificates of later flips may all hold
  // and leave it so: the batch repairs at once (BatchAgenda::request_repair).
  // Nor may it take away a hull facet whose top simplex below is flat at now: that simplex may be
  // inside out just after now, its own hull certificate (pending in this batch) is what tells, and
  // once the facet is interior every certificate reads the stale orientation (docs/MATH.md §5.10;
  // e.g. three hull cells on one line at an instant).
  for (std::size_t k = 0; k < change.removed.size(); ++k) {
    const Simplex& t = change.removed[k];
    if (is_finite(t))
      continue;
    const CellIndex held = k == 0 ? c : k == 1 ? cells.neighbor(c, i) : cell_across_from(change.z);
    const Simplex hull_facet = t.facet(0);
    const Simplex below = hull_facet.with(cells.apex_across(held, cells.index_of(held, infinite_vertex)));
    if (!is_finite(below) ||
        std::find(change.removed.begin(), change.removed.end(), below) != change.removed.end())
      continue; // a case-A flip removes the flat simplex itself
    if (flat_at_now(below))
      return false;
  }
  for (const Simplex& t : change.added) {
    if (!is_finite(t))
      continue;
    if (orientation_sign_plus(t) == 0)
      return false;
    if (flat_without_turning_at_now(t)) {
      agenda.request_repair();
      return false;
    }
  }
  return true;
}

template <class K> void Engine<K>::resolve_delaunay(std::vector<Step>& steps) {
  // A batch of simultaneous degenerate failures can cycle through flips (docs/MATH.md §5.2 step 3, "a cycle
  // of flips"): past this many elementary flips in one batch, a static repair settles it.
  const std::size_t limit = 20 * traj.cells.size() + 1000;
  std::size_t flips_in_batch = 0, repairs_in_batch = 0;
  FlipChange change;
  if (options.audit)
    if (std::string v = agenda.first_violation(certificates, false); !v.empty())
      audit_failure(v);
  auto accept = [&](const Simplex&, int id) { return flippable(id, change); };
  while (agenda.has_delaunay() || agenda.repair_due()) {
    // The first flippable failure in canonical order; a static repair when none is, when the flips
    // do not converge (docs/MATH.md §5.2 steps 2 and 3), or when a hull ridge was found folded at now.
    if (flips_in_batch < limit && !agenda.repair_due())
      if (const auto failed = agenda.take_first_delaunay(certificates, accept)) {
        at_own_time(failed->second);
        flip(failed->second, change, steps);
        ++flips_in_batch;
        continue;
      }
    if (!agenda.has_delaunay() && !agenda.repair_due())
      continue;
    // A repair gives Del(now+) (docs/MATH.md §5.4), so failures left after it can only be those its
    // rational stand-in for now+ (rational_before_next_event) settled differently; a few more rounds
    // of flips settle them, and more than that is a bug.
    if (++repairs_in_batch > 3) {
      std::ostringstream os;
      os << "no progress resolving degenerate Delaunay events in slab " << slab << " at u ~ " << now.approx();
      throw InternalError(os.str());
    }
    agenda.start_repair();
    repair(steps);
    flips_in_batch = 0;
  }
}

// Radius touches: a frontier simplex whose radius reaches rho at now without crossing it (a root of
// even multiplicity, or a root at a frame). Its shortness stays, but a face with R = rho at now whose
// link vertex crosses its smallest circumsphere changes membership then (docs/MATH.md §4.7). So the
// faces of every top simplex containing the touching simplex are settled again at now+ (the final
// re-evaluation of docs/MATH.md §5.2 step 4), and its certificate is installed again for its next
// root (tests/kinetic/test_kinetic_dense_lattice.cpp).
template <class K> void Engine<K>::resolve_touches(OldMembership& old_k) {
  std::vector<BatchAgenda::Entry> touches;
  agenda.take_touches(touches);
  for (auto [id, version] : touches) {
    if (!certificates.current(id, version))
      continue;
    const Certificate& c = certificates[id];
    const Simplex s = c.key; // install_radius replaces the certificate
    at_own_time(id);
    ++stats.radius_touches;
    for_each_top_containing(
        s, [&](const Simplex& t) { for_each_face(t, [&](const Simplex& f) { old_k.emplace(f, in_k(f)); }); });
    install_radius(s);
  }
}

// Hull touches: a hull certificate (an orientation, docs/MATH.md §3.2) whose root at now has even
// multiplicity. docs/MATH.md §3.9 drops such roots as non-events, which is right for the certificate's own
// sign but not always for the hull: when three hull cells become collinear at now, every top simplex
// on them is flat at now, and one that only touches flatness can hide a hull facet turning over and
// folding onto its neighbour at once, two sign changes that cancel in each certificate (hull-box seed
// 18304: cell 14 crossed the hull edge [4 11] of its own hull facet [4 11 14] at u = 1/2, where cells
// 4, 5, 11 and 14 were also coplanar; every certificate touched zero and held, and 12 lay outside the
// hull just after). A hull facet can only turn over where it degenerates, its three cells collinear
// (in the plane a hull edge would need two cells to collide), so at a hull touch with such a hull
// facet at one of the certificate's cells the batch repairs (BatchAgenda::request_repair), which builds
// Del(now+) whatever happened. Any other touch (a cell touching the plane of a sound hull facet and
// going back) is no event. The certificate is installed again for its next root either way.
template <class K> void Engine<K>::resolve_hull_touches() {
  std::vector<BatchAgenda::Entry> touches;
  agenda.take_hull_touches(touches);
  for (auto [id, version] : touches) {
    if (!certificates.current(id, version))
      continue;
    const Certificate& c = certificates[id];
    const Simplex key = c.key;
    install(id);
    if (!agenda.repair_due() && degenerate_hull_facet_at(key)) {
      ++stats.hull_touches_repaired;
      agenda.request_repair();
    }
  }
}

// Whether a hull facet at one of the cells of s (the infinite vertex aside) has its three cells
// collinear at now. Never in the plane, where a hull facet is an edge.
template <class K> bool Engine<K>::degenerate_hull_facet_at(const Simplex& s) {
  if constexpr (dim != 3)
    return false;
  for (VertexId v : s) {
    if (v == infinite_vertex)
      continue;
    bool degenerate = false;
    for_each_top_containing(Simplex{infinite_vertex, v}, [&](const Simplex& t) {
      degenerate = degenerate || collinear_at_now(t.facet(0));
    });
    if (degenerate)
      return true;
  }
  return false;
}

template <class K> bool Engine<K>::collinear_at_now(const Simplex& f) {
  return sign_at_now([&](auto tag) {
           using NT = decltype(tag);
           const certificate::Vec<NT> n = certificate::cross(certificate::difference<NT>(pt(f[0]), pt(f[1])),
                                                             certificate::difference<NT>(pt(f[0]), pt(f[2])));
           return certificate::dot(n, n);
         }) == 0;
}

// Whether R(s) = rho exactly at now = 0 (a frame): the constant coefficient of its radius polynomial.
template <class K> bool Engine<K>::radius_vanishes_now(const Simplex& s) {
  {
    CGAL::Protect_FPU_rounding<true> guard;
    IntervalPoly f;
    if (radius_enclosure(s, f) && (f[0].inf() > 0 || f[0].sup() < 0))
      return false;
  }
  return radius_poly<mpz_class>(s, P, Q)[0] == 0;
}

// Radius events: toggle shortness of the failed certificates, then one settle step.
template <class K> void Engine<K>::resolve_radius(Step& settle, OldMembership& old_k) {
  // Taken into a kept buffer: certificates failing meanwhile stay on the agenda, and neither vector is
  // reallocated per event.
  std::vector<BatchAgenda::Entry>& failed = radius_scratch;
  agenda.take_radius(failed);
  for (auto [id, version] : failed) {
    if (!certificates.current(id, version))
      continue;
    const Certificate& c = certificates[id];
    Simplex s = c.key;
    at_own_time(id);
    for_each_face(s, [&](const Simplex& f) { old_k.emplace(f, in_k(f)); });
    // Faces' membership depends on cofaces: also record the cofaces' faces through the closure.
    Face& f = faces.at(s);
    count_in_facets(s, f.is_short ? -1 : +1, 0);
    f.is_short = !f.is_short;
    install_radius(s);
    ++stats.radius_events;
    // Frontier update rules of docs/MATH.md §4.4: facets may leave or enter, cofaces may enter or leave.
    if (s.size() > 2)
      for (std::size_t i = 0; i < s.size(); ++i)
        update_frontier(s.facet(i));
    finite_cofaces(s, f, coface_scratch);
    for (const Simplex& c : coface_scratch)
      update_frontier(c);
  }
  (void)settle;
}

} // namespace medusa::kinetic::detail
