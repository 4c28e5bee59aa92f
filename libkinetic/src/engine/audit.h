// The audit: the structure checked exactly against static CGAL computations at a rational time.
#pragma once

#include "engine.h"

#include "certificate_polynomials.h"
#include "medusa/core/error.h"
#include "static_delaunay.h"

#include <CGAL/FPU.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

namespace medusa::kinetic::detail {

template <class K> void Engine<K>::audit_failure(const std::string& what) const {
  throw InternalError("audit failed in slab " + std::to_string(slab) + " after u ~ " +
                      std::to_string(now.approx()) + ": " + what);
}

template <class K> void Engine<K>::audit() {
  ++stats.audits;
  // Each part's own invariants (certificate_pool.h, batch_agenda.h, cell_triangulation.h,
  // face_states.h), then those between the parts, first: they need no time q, and the checks at q
  // read the triangulation. The audit runs between batches.
  if (std::string v = certificates.first_violation(); !v.empty())
    audit_failure(v);
  if (std::string v = agenda.first_violation(certificates, true); !v.empty())
    audit_failure(v);
  if (std::string v = cells.first_violation(); !v.empty())
    audit_failure("cell triangulation: " + v);
  if (std::string v = faces.first_violation(cells, alive); !v.empty())
    audit_failure(v);
  for (std::size_t i = 0; i < alive.size(); ++i)
    if ((cells.cell_of(static_cast<VertexId>(i)) == no_cell) == bool(alive[i]))
      audit_failure("cell " + std::to_string(i) +
                    (alive[i] ? " is alive but not in" : " is dead but still in") + " the triangulation");
  // Every Delaunay certificate names a living cell holding its facet, which holds its id.
  for (int id = 0; id < static_cast<int>(certificates.size()); ++id) {
    const Certificate& cert = certificates[id];
    if (!cert.alive || cert.kind != CertKind::delaunay)
      continue;
    const CellIndex c = cert.cell;
    if (!cells.alive(c) || cert.facet_index < 0 || cert.facet_index > dim ||
        cells.cert(c, cert.facet_index) != id || cells.facet(c, cert.facet_index) != cert.key) {
      std::ostringstream os;
      os << "certificate " << id << " of facet " << cert.key << " names a cell that does not hold it";
      audit_failure(os.str());
    }
  }
  // A rational time strictly between now and the next event (or the slab end).
  const SlabTime upper = certificates.earliest_time(SlabTime(Rational(1)));
  if (!(now < upper))
    return; // the slab has no room left (event at u = 1)
  // The audit compares open conditions (valid on (now, next event)) with closed ones at q, so q must
  // avoid the isolated zeros of every certificate polynomial, such as a radius touching rho without
  // crossing it (a tangential root, docs/MATH.md §3.9): move q towards now until none vanishes there. The
  // signs at q (0 only for identically-zero polynomials) serve the checks below.
  std::vector<std::pair<Simplex, ExactPoly>> delaunay_polys, radius_polys;
  std::vector<std::pair<CellIndex, int>> facet_cells; // of delaunay_polys, each the cell of its first apex
  mpz_class p = P, qq = Q;
  cells.for_each_cell([&](CellIndex c) {
    for (int i = 0; i <= dim; ++i)
      if (c < cells.neighbor(c, i)) {
        const auto [owner, j] = facet_owner(c, i);
        const Simplex facet = cells.facet(owner, j);
        facet_cells.emplace_back(owner, j);
        delaunay_polys.emplace_back(facet, to_exact_poly(delaunay_poly<mpz_class>(facet, owner, j)));
      }
  });
  faces.for_each([&](const Simplex& s, const Face&) {
    radius_polys.emplace_back(s, to_exact_poly(radius_poly<mpz_class>(s, p, qq)));
  });
  std::vector<int> delaunay_sign, radius_sign;
  Rational q = rational_between(now, upper);
  for (int attempt = 0;; ++attempt) {
    const SlabTime at(q);
    auto signs_at_q = [&](const std::vector<std::pair<Simplex, ExactPoly>>& polys, std::vector<int>& signs) {
      signs.clear();
      for (const auto& sf : polys) {
        const bool zero = CGAL::is_zero(sf.second);
        const int sg = zero ? 0 : sign_at(sf.second, at);
        if (sg == 0 && !zero)
          return false;
        signs.push_back(sg);
      }
      return true;
    };
    if (signs_at_q(delaunay_polys, delaunay_sign) && signs_at_q(radius_polys, radius_sign))
      break;
    if (attempt == 20)
      return; // no rational found quickly: skip this audit rather than report a false failure
    q = rational_between(now, at);
  }

  // Local Delaunay, exactly, at q (identically-zero certificates are valid, docs/MATH.md §3.9).
  for (std::size_t i = 0; i < delaunay_polys.size(); ++i) {
    const Simplex& facet = delaunay_polys[i].first;
    if (delaunay_sign[i] < 0) {
      std::ostringstream os;
      os << "facet " << facet << " is not locally Delaunay";
      audit_failure(os.str());
    }
    const int id = cells.cert(facet_cells[i].first, facet_cells[i].second);
    if (id < 0 || !certificates[id].alive || certificates[id].key != facet ||
        certificates[id].cell != facet_cells[i].first ||
        certificates[id].facet_index != facet_cells[i].second)
      audit_failure("a facet has no certificate");
  }
  // Exactly those: a certificate left alive without its simplex would still fire.
  const std::size_t alive_delaunay = certificates.alive_count(CertKind::delaunay);
  const std::size_t alive_radius = certificates.alive_count(CertKind::radius);
  std::size_t certified_radius = 0;
  if (alive_delaunay != delaunay_polys.size())
    audit_failure("a Delaunay certificate outlived its facet");
  // Radius flags, exactly at q, and the certificates the frontier holds (docs/MATH.md §4.4).
  for (std::size_t i = 0; i < radius_polys.size(); ++i) {
    const Simplex& s = radius_polys[i].first;
    const Face& f = faces.at(s);
    if ((radius_sign[i] <= 0) != f.is_short) {
      std::ostringstream os;
      os << "simplex " << s << " has a wrong shortness flag";
      audit_failure(os.str());
    }
    if (f.cert < 0)
      continue;
    const Certificate& c = certificates[f.cert];
    if (!c.alive || c.kind != CertKind::radius || c.key != s) {
      std::ostringstream os;
      os << "simplex " << s << " names a radius certificate that is not its own";
      audit_failure(os.str());
    }
    ++certified_radius;
  }
  if (alive_radius != certified_radius)
    audit_failure("a radius certificate outlived its simplex");
  // The alpha complex against CGAL's static Fixed_alpha_shape_3 (Alpha_shape_2 in 2D) at q.
  std::vector<Simplex> cgal_tops;
  Rational rho2(CGAL::Gmpz(P.get_mpz_t()), CGAL::Gmpz(Q.get_mpz_t()));
  std::vector<Simplex> expected =
      detail::static_alpha_complex(dim, static_input(alive_ids()), q, rho2, cgal_tops);
  std::unordered_set<Simplex, SimplexHash> cgal_set(cgal_tops.begin(), cgal_tops.end());
  bool same_triangulation = cgal_set.size() == cells.size();
  for (const Simplex& t : all_tops())
    same_triangulation = same_triangulation && cgal_set.count(t);
  if (!same_triangulation) {
    // A degenerate (identically cospherical) group triangulated differently (docs/MATH.md §5.3): the
    // complexes are not compared, but ours must still triangulate the points at q.
    audit_embedded(q, cgal_tops);
    return;
  }
  ++stats.audits_compared_with_cgal;
  std::sort(expected.begin(), expected.end());
  std::vector<Simplex> ours = current_complex();
  if (expected != ours) {
    std::ostringstream os;
    std::vector<Simplex> extra, missing;
    std::set_difference(ours.begin(), ours.end(), expected.begin(), expected.end(),
                        std::back_inserter(extra));
    std::set_difference(expected.begin(), expected.end(), ours.begin(), ours.end(),
                        std::back_inserter(missing));
    os << "alpha complex differs from CGAL's: " << extra.size() << " extra";
    if (!extra.empty())
      os << " (e.g. " << extra.front() << ")";
    os << ", " << missing.size() << " missing";
    if (!missing.empty())
      os << " (e.g. " << missing.front() << ")";
    audit_failure(os.str());
  }
}

// Every local test passes on a fan that wraps twice around a centre, so local Delaunay at q does
// not make a triangulation. With every finite top simplex positively oriented at q as recorded, the
// structure maps onto the plane or space with a local degree that is its number of layers; with
// CGAL's hull facets as its boundary, that number is one over the whole hull: it is embedded. Where
// the hull facets differ (coplanar hull points triangulated differently), every hull facet of ours
// must support the points at q (none strictly outside its plane, or line). The boundary then lies
// on the boundary of the convex hull, so the number of layers is the same over every interior
// point, and equal volumes make it one.
template <class K> void Engine<K>::audit_embedded(const Rational& q, const std::vector<Simplex>& cgal_tops) {
  const auto volume = [&](const Simplex& t) { return value_at(orientation_poly<mpz_class>(t), q); };
  Rational ours(0), theirs(0);
  std::set<Simplex> our_hull, their_hull;
  std::vector<std::pair<Simplex, int>> tops;
  cells.for_each_cell([&](CellIndex c) { tops.emplace_back(cells.top(c), cells.orientation(c)); });
  for (const auto& [t, orientation] : tops) {
    if (!is_finite(t)) {
      our_hull.insert(t.facet(0));
      continue;
    }
    // Zero too is a failure: Del(q) has no flat top simplex, not even one flat for the whole slab
    // (the frame where one appears repairs it, Engine::top_simplex_turns_at_frame).
    const Rational v = volume(t);
    if (CGAL::sign(v) != orientation) {
      std::ostringstream os;
      os << "top simplex " << t << " is inside out or flat at the audit time";
      audit_failure(os.str());
    }
    ours += CGAL::abs(v);
  }
  for (const Simplex& t : cgal_tops)
    if (!is_finite(t))
      their_hull.insert(t.facet(0));
  if (our_hull == their_hull)
    return;
  for (const Simplex& f : our_hull)
    audit_supporting(q, f);
  for (const Simplex& t : cgal_tops)
    if (is_finite(t))
      theirs += CGAL::abs(volume(t));
  if (ours != theirs)
    audit_failure("the triangulation covers the hull more or less than once (volumes differ from CGAL's)");
}

// No cell lies strictly on the far side of the hull facet f's plane (line) at q from the apex of the
// finite top simplex under f. Interval arithmetic at q first; exactly only where it cannot tell.
template <class K> void Engine<K>::audit_supporting(const Rational& q, const Simplex& f) {
  const CellIndex c = cells.find(f.with(infinite_vertex));
  if (c == no_cell)
    audit_failure("a hull facet has no infinite top simplex");
  const VertexId z = cells.apex_across(c, 0); // the infinite vertex is c's first

  const auto side = [&](VertexId p) {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval u = CGAL::to_interval(q);
      const auto at = [&](VertexId v) { return certificate::PointAtTime{&pt(v), u}; };
      const Interval o = K::template orientation<Interval>(K::join(f, p), at);
      if (o.inf() > 0 || o.sup() < 0)
        return o.inf() > 0 ? 1 : -1;
    }
    const Poly<mpz_class> o = K::template orientation<mpz_class>(K::join(f, p), moving());
    return static_cast<int>(CGAL::sign(value_at(o, q)));
  };
  const int inside = side(z);
  for (std::size_t i = 0; i < alive.size(); ++i)
    if (alive[i] && side(static_cast<VertexId>(i)) == -inside) {
      std::ostringstream os;
      os << "vertex " << i << " lies outside the hull facet " << f << " at the audit time";
      audit_failure(os.str());
    }
}

} // namespace medusa::kinetic::detail
