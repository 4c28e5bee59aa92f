// Certificates: their polynomials' orientation, creation and retirement, and installation (the
// interval filter, root isolation in doubles, the exact path with the per-slab root cache), docs/MATH.md §3.
#pragma once

#include "engine.h"

#include "certificate_polynomials.h"
#include "interval_filter.h"
#include "medusa/core/error.h"
#include "root_isolation.h"

#include <CGAL/FPU.h>

#include <algorithm>
#include <array>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

namespace {

// Parity of the permutation that sorts `seq` (+1 even, -1 odd).
int permutation_sign(const VertexId* seq, std::size_t n) {
  int sign = 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (seq[i] > seq[j])
        sign = -sign;
  return sign;
}

} // namespace

// The oriented sign of the sequence seq of n = dim + 1 vertices: a finite top simplex of Del, the
// facet whose record is ap plus its apex `apex`.
template <class K>
int Engine<K>::orientation_of(const VertexId* seq, std::size_t n, const Apices& ap, VertexId apex) const {
  const int sign = ap.orientation_with(apex);
  if (sign == 0) {
    std::ostringstream os;
    os << "no orientation for top simplex " << Simplex::from_range(seq, seq + n);
    throw InternalError(os.str());
  }
  return sign * permutation_sign(seq, n);
}

// The orientation of a finite top simplex on the points at now's enclosure: a sign when it excludes
// zero, which it does unless t is (nearly) flat at now.
template <class K> int Engine<K>::orientation_enclosure_sign(const Simplex& t) {
  CGAL::Protect_FPU_rounding<true> guard;
  const auto at = points_at_now();
  const Interval o = K::template orientation<Interval>(K::join(t), at);
  if (o.inf() > 0 || o.sup() < 0) {
    ++stats.sign_evaluations;
    return o.inf() > 0 ? 1 : -1;
  }
  return 0;
}

// The enclosure first: the top simplices of a flip are far from flat at now but in degenerate batches.
template <class K> bool Engine<K>::flat_at_now(const Simplex& t) {
  if (orientation_enclosure_sign(t) != 0)
    return false;
  ++stats.sign_evaluations_exact;
  return orientation_at_now(t) == 0;
}

template <class K> GeometryError Engine<K>::flat_top_simplex_error(const Simplex& t) const {
  std::ostringstream os;
  os << "cells " << t
     << (dim == 2 ? " stay collinear but form a Delaunay triangle"
                  : " stay coplanar but form a Delaunay tetrahedron");
  return GeometryError(os.str());
}

template <class K> GeometryError Engine<K>::too_many_tops_error(const Simplex& f) const {
  std::ostringstream os;
  os << "cells " << f << " lie in more than " << max_face_tops
     << " Delaunay top simplices (cells on one circle round them), more than the kinetic engine counts";
  return GeometryError(os.str());
}

template <class K> int Engine<K>::orientation_sign_plus(const Simplex& t) {
  if (t.size() == top_size() && is_finite(t)) {
    // The value at now first: a new top simplex of a flip is far from flat at now, and a sign there
    // is the sign just after now.
    if (const int s = orientation_enclosure_sign(t); s != 0)
      return s;
  }
  if (t.size() == top_size() && is_finite(t))
    if (const int s = sign_after_own_orientation_root(t); s != 0) {
      ++stats.sign_evaluations;
      return s;
    }
  return sign_plus_now([&](auto tag) { return orientation_poly<decltype(tag)>(t); });
}

// A hull flip at a root of this very orientation (the failed certificate of four finite points,
// three in 2D, docs/MATH.md §3.2 case B) creates the top simplex that is flat at now; the root is then an
// event, a sign change, and the sign just after it is known without exact arithmetic. 0 otherwise.
template <class K> int Engine<K>::sign_after_own_orientation_root(const Simplex& t) const {
  if (now.isolated() == nullptr)
    return 0;
  CacheKey key;
  key.v.fill(-2);
  key.v[0] = 1;
  std::copy(t.begin(), t.end(), key.v.begin() + 1);
  CGAL::Protect_FPU_rounding<true> guard;
  return sign_after_own_root(orientation_poly<Interval>(t), key);
}

// A finite top simplex flat at now whose orientation only touches zero there (one sign just before and
// just after now). A hull flip that adds it can leave the top simplices wrapped once more round one of
// its edges than they should be, with every certificate holding, so such a flip is refused and the
// batch repairs (docs/MATH.md §5.10). At a frame the sign before now is read along the previous slab
// (Engine::orientation_sign_before_frame); a simplex with no sign before (flat through the previous
// slab, or with a cell born at the frame) is not refused.
template <class K> bool Engine<K>::flat_without_turning_at_now(const Simplex& t) {
  const bool at_frame = now.is_rational() && now.rational() == 0;
  if (at_frame && slab == 0)
    return false; // the structure was built just after t_0: no earlier flip to undo
  // At the simplex's own isolated root now is a sign change (no exact arithmetic needed to say so).
  if (sign_after_own_orientation_root(t) != 0 || !flat_at_now(t))
    return false;
  const auto orientation = [&](auto tag) { return orientation_poly<decltype(tag)>(t); };
  const int before = at_frame ? orientation_sign_before_frame(t) : sign_minus_now(orientation);
  if (before != sign_plus_now(orientation))
    return false;
  ++stats.hull_flips_refused_touching;
  return true;
}

// The sign of a finite top simplex's orientation just before the current frame t_k, under the motion
// of slab k-1; 0 when it vanishes identically there or a cell of t was not present at t_{k-1}. Read
// backwards from the frame, p(s) = x_k + s (x_{k-1} - x_k): the same points, so the same orientation,
// and its sign just before t_k is its sign just after s = 0 (sign_plus at u = 0, exact integers).
template <class K> int Engine<K>::orientation_sign_before_frame(const Simplex& t) {
  for (const VertexId v : t) {
    const Trajectory& c = traj.cells[static_cast<std::size_t>(v)];
    if (slab == 0 || !c.present(slab - 1) || !c.present(slab))
      return 0;
  }
  const auto backwards = [&](VertexId v) {
    const Trajectory& c = traj.cells[static_cast<std::size_t>(v)];
    const GridPoint &x = c.at(slab), &w = c.at(slab - 1);
    return MovingPoint{{x[0], x[1], x[2]}, {w[0] - x[0], w[1] - x[1], w[2] - x[2]}};
  };
  ++stats.sign_evaluations_exact;
  return sign_plus(to_exact_poly(orientation_poly<mpz_class>(t, backwards)), SlabTime());
}

// For f whose polynomial (key) is, up to a factor c, the one whose isolated simple root is now: the
// sign of f just after now, -c * sign_lo; 0 when f is not that polynomial or c is undecided.
template <class K> int Engine<K>::sign_after_own_root(const IntervalPoly& f, const CacheKey& key) const {
  const IsolatedRoot* current = now.isolated();
  double lo, hi;
  now.enclosure(lo, hi);
  if (current == nullptr || !(lo < hi) || current->slab != slab || current->key != key.v)
    return 0;
  return -proportionality_sign(f, current->enclosure, current->shift) * current->sign_lo;
}

// A hull certificate (docs/MATH.md §3.2): a ridge's (case B, the key holds the infinite vertex) or a hull
// facet's (case A, the infinite vertex is an apex), each the orientation of four (three) cells.
template <class K> bool Engine<K>::is_hull_orientation(const Certificate& c) const {
  if (c.kind != CertKind::delaunay || c.substitute != Substitute::none)
    return false;
  return !is_finite(c.key) || cells.apices(c.cell, c.facet_index).has(infinite_vertex);
}

template <class K> int Engine<K>::new_cert(CertKind kind, const Simplex& key) {
  return certificates.create(kind, key);
}

template <class K> void Engine<K>::kill_cert(int id) {
  if (id < 0)
    return;
  if (const Certificate& c = certificates[id]; c.kind == CertKind::delaunay)
    agenda.withdraw_delaunay(c.key, id);
  certificates.retire(id);
}

// Every certificate dies at once (a frame rebuilds them all, docs/MATH.md §2.3). The callers must drop
// their ids (the records keep -1 until they get a new one). Nothing catches an exception between this
// and the end of the frame's reinstall (Engine::reinstall_all): one aborts the run, so records not
// yet visited never hand their old ids to anyone.
template <class K> void Engine<K>::retire_all_certs() {
  certificates.retire_all();
  agenda.withdraw_all_delaunay(); // it only ever holds live Delaunay certificates
}

// Counts a certificate built by its formula; `enclosed` says cert_enclosure took it, which it does for
// every certificate but the hull orientations.
template <class K> void Engine<K>::count_built(const Certificate& c, bool enclosed) {
  if (c.kind == CertKind::delaunay)
    ++(enclosed ? stats.built_in_sphere : stats.built_hull);
  else
    ++stats.built_radius.at(c.key.size() - 2);
}

// A hull ridge whose certificate vanishes at now has its two facets in one plane (line) then. Folded
// onto each other, a valid sign just after now reads a knife edge, which an embedded triangulation
// has only if every top simplex round the ridge is flat at now and folded too; otherwise they wrap
// round the ridge though every certificate may hold, and the ridge fails (docs/MATH.md §5.9). Where a
// vertex lies on the ridge's line at now the angle is undefined, and nothing is concluded.
template <class K> bool Engine<K>::hull_ridge_folded_at_now(const Simplex& facet, CellIndex c, int i) {
  const Simplex ridge = facet.facet(0);
  {
    // At now's enclosure first: most hull ridges are far from flat at now, and the new ridges of a
    // hull flip, whose certificates vanish at now with the flip's own, have their facets side by
    // side. Only the rest is decided exactly.
    CGAL::Protect_FPU_rounding<true> guard;
    const auto at = points_at_now();
    const Apices ap = cells.apices(c, i);
    const VertexId p = ap.v[0], q = ap.v[1];
    const Interval o = K::template orientation<Interval>(K::join(ridge, p, q), at);
    if (o.inf() > 0 || o.sup() < 0 || fold_poly<Interval>(ridge, p, q, at).sup() < 0)
      return false;
  }
  if (sign_at_now([&](auto tag) { return delaunay_poly<decltype(tag)>(facet, c, i); }) != 0)
    return false;
  if (sign_at_now([&](auto tag) { return hull_fold_poly<decltype(tag)>(facet, c, i); }) <= 0)
    return false;
  bool knife = true;
  for_each_top_containing(ridge, [&](const Simplex& t) {
    if (!knife || !is_finite(t))
      return;
    std::array<VertexId, 2> off{};
    std::size_t n = 0;
    for (VertexId v : t)
      if (!ridge.contains(v))
        off[n++] = v;
    knife = flat_at_now(t) &&
            sign_at_now([&](auto tag) { return fold_poly<decltype(tag)>(ridge, off[0], off[1]); }) >= 0;
  });
  return !knife;
}

// Evaluates a fresh certificate at `now`: schedules its next failure in (now, 1), or queues it in
// the current batch when it is already invalid just after now (docs/MATH.md §3.7, §3.9).
template <class K> void Engine<K>::install(int id, Interval* at_now) {
  ++stats.certificates_built;
  settle_certificate(id, true, at_now);
}

// install's work. A certificate replaced by its substitute is settled again, and is still one
// certificate, counted (by formula and by how it was settled) as the one it replaced: `counted` is
// false for the second pass.
template <class K> void Engine<K>::settle_certificate(int id, bool counted, Interval* at_now) {
  const Certificate& c = certificates[id];
  const auto tally = [counted](std::size_t& counter) { counter += counted ? 1 : 0; };
  {
    CGAL::Protect_FPU_rounding<true> guard;
    double lo, hi;
    now.enclosure(lo, hi);
    IntervalPoly f;
    // Most certificates hold through the slab, and most others have a simple root in it: the
    // enclosure from doubles settles both at a fraction of the cost of interval arithmetic (it is
    // an enclosure like any other, only wider). What it cannot settle is recomputed tightly.
    const bool enclosed = cert_enclosure(c, f);
    if (counted)
      count_built(c, enclosed);
    if (enclosed && at_now != nullptr && lo == 0.0 && hi == 0.0)
      *at_now = f[0]; // the value at a slab start is the constant term
    if (enclosed) {
      if (bernstein_sign_subdivided(f, lo, 4) > 0) {
        tally(stats.filter_settled);
        tally(stats.double_filter_settled);
        return;
      }
      if (install_in_doubles(id, f, true)) {
        tally(stats.interval_settled);
        tally(stats.double_isolation_settled);
        return;
      }
    }
    f = cert_poly<Interval>(c);
    if (bernstein_sign_subdivided(f, lo, 4) > 0) {
      tally(stats.filter_settled);
      return;
    }
    if (install_in_doubles(id, f)) {
      tally(stats.interval_settled);
      return;
    }
    if (install_vanishing_at_start(id, f)) {
      tally(stats.start_zero_settled);
      return;
    }
  }
  tally(stats.exact_settled);
  tally(c.kind == CertKind::delaunay ? stats.exact_delaunay : stats.exact_radius);
  Poly<mpz_class> exact = cert_poly<mpz_class>(c);
  if (install_from_exact_coefficients(id, exact)) {
    tally(stats.exact_filter_settled);
    return;
  }
  ExactPoly f = to_exact_poly(exact);
  if (CGAL::is_zero(f)) {
    // Identically zero: valid, never scheduled (docs/MATH.md §3.9), with the exceptions of docs/MATH.md
    // §5.8. A radius polynomial f == 0 means R = rho throughout, short, so a face still flagged long
    // fails now. An identically-zero hull ridge (an infinite facet) is convex only while its two hull
    // facets lie side by side, so it carries the fold test instead (Substitute::hull_fold). A case-A
    // certificate vanishing for the whole slab needs nothing here: the frame repairs it first
    // (Engine::top_simplex_turns_at_frame, docs/MATH.md §5.11).
    if (c.kind == CertKind::delaunay && !is_finite(c.key) && c.substitute == Substitute::none) {
      certificates.set_substitute(id, Substitute::hull_fold);
      settle_certificate(id, false);
      return;
    }
    // Likewise a finite facet whose five (four) points stay cospherical (cocircular): every
    // triangulation of them is Delaunay, but a top simplex among them can flatten and turn inside out
    // with no in-sphere event, so it carries the product of its two top simplices' orientations
    // (Substitute::cell_orientations, docs/MATH.md §5.8; tests "five cospherical cells reaching one
    // circle ..." in test_kinetic_engine.cpp and "planar: an isosceles trapezoid ..." in
    // test_kinetic_engine_2d.cpp).
    if (c.kind == CertKind::delaunay && is_finite(c.key) && c.substitute == Substitute::none) {
      if (!cells.apices(c.cell, c.facet_index).has(infinite_vertex)) {
        certificates.set_substitute(id, Substitute::cell_orientations);
        settle_certificate(id, false);
        return;
      }
    }
    if (c.kind == CertKind::radius && !faces.at(c.key).is_short) {
      ++stats.invalid_at_creation;
      mark_invalid(id);
    }
    return;
  }
  auto [slot, fresh] = root_cache.try_emplace(cache_key(c));
  if (fresh)
    slot->second = real_roots(f);
  else
    ++stats.root_cache_hits;
  std::vector<AlgebraicReal> roots;
  int s = sign_plus_from_roots(f, slot->second, now, &roots);
  if (s < 0) {
    ++stats.invalid_at_creation;
    mark_invalid(id);
    return;
  }
  if (c.kind == CertKind::radius || is_hull_orientation(c)) {
    // A root of even multiplicity before the first failure is a touch (Engine::resolve_touches,
    // Engine::resolve_hull_touches). In doubles such a root is never isolated nor excluded, so it
    // always comes this way.
    const AlgebraicReal one(1);
    for (const auto& [x, multiplicity] : slot->second.roots)
      if (multiplicity % 2 == 0 && x < one && compare(now, SlabTime(x)) < 0) {
        if (roots.empty() || x < roots.front()) {
          ++stats.exact_scheduled;
          certificates.schedule(id, SlabTime(x), true);
          return;
        }
        break;
      }
  }
  if (!roots.empty()) {
    ++stats.exact_scheduled;
    certificates.schedule(id, SlabTime(roots.front()));
  }
}

// The fast path of install (docs/MATH.md §3.8): the sign just after now and the next failure time,
// isolated in double interval arithmetic. False when doubles cannot decide; nothing is changed then.
template <class K> bool Engine<K>::install_in_doubles(int id, const IntervalPoly& f, bool wide) {
  const Certificate& c = certificates[id];
  const CacheKey key = cache_key(c);
  double lo, hi;
  now.enclosure(lo, hi);
  int sign;
  const IsolatedRoot* current = now.isolated();
  const bool same_polynomial =
      current != nullptr && lo < hi && current->key == key.v && current->slab == slab;
  if (same_polynomial && current->clear_hi > hi) {
    // f's next root lies beyond clear_hi, so its sign just after now settles it: no exact arithmetic
    // even though f is tiny near now.
    if (const int s = sign_after_own_root(f, key); s != 0)
      return schedule_first_change(id, f, s, current->clear_hi, key, 0, wide);
  }
  if (same_polynomial) {
    // f is +-(the polynomial whose root is now): its only root in (lo, hi) is now itself, so its
    // sign just after now is its sign at hi (the flipped facet, the toggled radius certificate).
    sign = interval_sign(f, hi, hi);
  } else {
    // f keeps one sign on the enclosure of now: it does not vanish at now.
    sign = interval_sign(f, lo, hi);
  }
  return sign != 0 && schedule_first_change(id, f, sign, hi, key, 0, wide);
}

// With the sign of f just after now known and no other root of f in (now, start]: isolates the
// first sign change of f after start, then marks the certificate invalid or schedules its failure.
// f is the certificate's polynomial divided by u^shift.
// False when doubles cannot decide; nothing is changed then.
template <class K>
bool Engine<K>::schedule_first_change(int id, const IntervalPoly& f, int sign, double start,
                                      const CacheKey& key, int shift, bool wide) {
  FirstSignChange next;
  if (start < 1.0) {
    next = first_sign_change(f, start, 12);
    if (next.status == FirstSignChange::Status::undecided || next.sign != sign)
      return false;
  } else {
    next.status = FirstSignChange::Status::none; // nothing is left of the slab after start
  }
  if (sign < 0) {
    ++stats.invalid_at_creation;
    mark_invalid(id);
    return true;
  }
  if (next.status == FirstSignChange::Status::root) {
    ++stats.interval_scheduled;
    auto root = make_isolated_root(key_polynomial(key));
    root->enclosure = f;
    root->shift = shift;
    root->wide = wide;
    root->lo = next.lo;
    root->hi = next.hi;
    root->sign_lo = sign;
    root->clear_hi = next.hi;
    // Events of a slab are about 1/(events per slab) apart, and the isolating pieces are far wider:
    // narrowed once here, most pairs of queued times separate on their enclosures without refinement.
    narrow_root(root->enclosure, root->lo, root->hi, sign, 0x1p-24);
    root->key = key.v;
    root->slab = slab;
    certificates.schedule(id, SlabTime(std::move(root)));
  }
  return true;
}

// At a slab start (u = 0: t_0 and frames) an enclosure that straddles zero often belongs to a
// certificate that vanishes there exactly: CC3D's initial lattice is full of cospherical and coplanar
// sets (docs/MATH.md §5.5). One exact static determinant proves f(0) = 0; then f = u h, h is enclosed by
// f's enclosure shifted down, and the sign just after 0 is h(0)'s. False when this does not decide;
// nothing is changed then.
template <class K> bool Engine<K>::install_vanishing_at_start(int id, const IntervalPoly& f) {
  const int n = f.degree_bound();
  if (n < 1 || !now.is_rational() || now.rational() != 0)
    return false;
  const IntervalPoly h = f.shifted_down(1);
  const int sign = interval_sign(h, 0.0, 0.0);
  if (sign == 0)
    return false;
  const CacheKey key = cache_key(certificates[id]);
  ++stats.start_zero_tests;
  if (!key_polynomial(key).vanishes_at_start())
    return false;
  return schedule_first_change(id, h, sign, 0.0, key, 1);
}

// The second path, on the exact coefficients rounded outward to doubles (tight enclosures): at a
// rational slab start (u = 0: t_0 and frames) the root at 0 of multiplicity m is divided out first,
// which settles the lattice-degenerate certificates of CC3D's initial layout (docs/MATH.md §5.5) without
// CGAL. False when doubles cannot decide; nothing is changed then.
template <class K> bool Engine<K>::install_from_exact_coefficients(int id, const Poly<mpz_class>& f) {
  const bool at_zero = now.is_rational() && now.rational() == 0;
  const int n = f.degree_bound();
  int m = 0;
  if (at_zero)
    while (m <= n && f[m] == 0)
      ++m;
  if (m > n || n < 0)
    return false; // identically zero: handled by the caller
  CGAL::Protect_FPU_rounding<true> guard;
  IntervalPoly g;
  for (int i = n; i >= m; --i) {
    IntervalPoly term{Interval(CGAL::to_interval(CGAL::Gmpz(f[i].get_mpz_t())))};
    g = g * IntervalPoly(Interval(0), Interval(1)) + term;
  }
  if (!at_zero)
    return install_in_doubles(id, g);
  // f = u^m g and g(0) = f_m != 0: the sign just after 0 is the sign of f_m.
  return schedule_first_change(id, g, sgn(f[m]) > 0 ? 1 : -1, 0.0, cache_key(certificates[id]), m);
}

template <class K> KeyPolynomial Engine<K>::key_polynomial(const CacheKey& key) const {
  KeyPolynomial k;
  k.kind = key.v[0];
  k.motion = motion;
  for (std::size_t i = 1; i < key.v.size() && key.v[i] != -2; ++i)
    k.ids[static_cast<std::size_t>(k.count++)] = key.v[i];
  return k;
}

template <class K> CacheKey Engine<K>::cache_key(const Certificate& c) const {
  CacheKey k;
  k.v.fill(-2);
  // At most d + 2 = 5 points, kept on the stack: this runs for every certificate isolated in doubles.
  std::array<VertexId, 5> pts{};
  std::size_t n = 0;
  for (VertexId v : c.key)
    pts[n++] = v;
  if (c.kind == CertKind::radius) {
    k.v[0] = 2;
  } else if (c.substitute == Substitute::cell_orientations) {
    // The facet's points, then its two apices (Engine::cell_orientations_poly).
    const Apices ap = cells.apices(c.cell, c.facet_index);
    k.v[0] = 4;
    pts[n++] = std::min(ap.v[0], ap.v[1]);
    pts[n++] = std::max(ap.v[0], ap.v[1]);
  } else if (c.substitute == Substitute::hull_fold) {
    // The ridge's points, then the two apices (Engine::fold_poly).
    const Apices ap = cells.apices(c.cell, c.facet_index);
    k.v[0] = 3;
    n = 0;
    for (VertexId v : c.key.facet(0))
      pts[n++] = v;
    pts[n++] = std::min(ap.v[0], ap.v[1]);
    pts[n++] = std::max(ap.v[0], ap.v[1]);
  } else {
    const Apices ap = cells.apices(c.cell, c.facet_index);
    pts[n++] = ap.v[0];
    pts[n++] = ap.v[1];
    auto* end = pts.begin() + static_cast<std::ptrdiff_t>(n);
    bool infinite = std::find(pts.begin(), end, infinite_vertex) != end;
    k.v[0] = infinite ? 1 : 0;
    if (infinite) {
      // Case A: the finite top simplex; case B: its d + 1 finite points (docs/MATH.md §3.2).
      end = std::remove(pts.begin(), end, infinite_vertex);
      n = static_cast<std::size_t>(end - pts.begin());
    }
    // Insertion sort of at most five (std::sort here trips GCC 12's -Warray-bounds).
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t j = i; j > 0 && pts[j - 1] > pts[j]; --j)
        std::swap(pts[j - 1], pts[j]);
  }
  for (std::size_t i = 0; i < n; ++i)
    k.v[i + 1] = pts[i];
  return k;
}

template <class K> void Engine<K>::mark_invalid(int id) {
  const Certificate& c = certificates[id];
  if (c.kind == CertKind::delaunay)
    agenda.fail_delaunay(c.key, id);
  else
    agenda.fail_radius(id, c.version);
}

// A facet that left Del has no cell any more: its certificate went with it.
template <class K> void Engine<K>::install_facet_at(const Simplex& facet) {
  if (const CellIndex c = cell_holding(facet); c != no_cell) {
    const auto [owner, i] = facet_owner(c, cells.facet_index(c, facet));
    install_facet(owner, i);
  }
}

template <class K> void Engine<K>::install_facet(CellIndex c, int i) {
  kill_cert(cells.cert(c, i));
  const Simplex facet = cells.facet(c, i);
  const int id = new_cert(CertKind::delaunay, facet);
  cells.set_cert(c, i, id);
  certificates.set_cell(id, c, i);
  install(id);
  if (!is_finite(facet) && !agenda.delaunay_failed(facet, id) && hull_ridge_folded_at_now(facet, c, i)) {
    ++stats.invalid_at_creation;
    ++stats.hull_ridges_folded_at_now;
    mark_invalid(id);
    agenda.request_repair();
  }
}

template <class K> void Engine<K>::install_radius(const Simplex& s, Face& f, Interval* at_now) {
  kill_cert(f.cert);
  f.cert = new_cert(CertKind::radius, s);
  install(f.cert, at_now);
}

template <class K> bool Engine<K>::compute_short(const Simplex& s) {
  {
    // Every face a flip creates asks this: the enclosure from doubles decides it away from R = rho.
    CGAL::Protect_FPU_rounding<true> guard;
    IntervalPoly f;
    double lo, hi;
    now.enclosure(lo, hi);
    if (radius_enclosure(s, f))
      if (const int sp = interval_sign(f, lo, hi); sp != 0) {
        ++stats.sign_evaluations;
        return sp < 0;
      }
  }
  int sp = sign_plus_now(
      [&](auto tag) { return radius_poly<decltype(tag)>(s, pick(P, Pi, tag), pick(Q, Qi, tag)); });
  return sp <= 0; // f == 0 identically means R = rho: short (docs/MATH.md §3.9)
}

} // namespace medusa::kinetic::detail
