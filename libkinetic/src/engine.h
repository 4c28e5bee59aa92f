// The kinetic engine behind KineticAlphaComplex: its state (motion, triangulation, alpha-complex
// flags, certificates, event queue, root cache) and its operations, declared by the source file that
// defines them (engine_*.cpp). The certificate polynomials and the sign^+ evaluations at now are
// templates over the number type, so they are defined here.
#pragma once

#include "batch_agenda.h"
#include "cell_triangulation.h"
#include "certificate.h"
#include "certificate_pool.h"
#include "face.h"
#include "face_states.h"
#include "medusa/kinetic/flat_simplex_map.h"
#include "root_cache.h"
#include "static_delaunay.h"
#include "touched_faces.h"

#include "algebraic_time.h"
#include "certificate_enclosure.h"
#include "certificate_polynomials.h"
#include "interval_filter.h"
#include "kinetic_traits.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/kinetic/observer.h"
#include "medusa/kinetic/simplex.h"
#include "medusa/kinetic/trajectories.h"
#include "moving_point.h"

#include <CGAL/FPU.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace medusa::kinetic::detail {

// The membership in K, before the current step, of every simplex the step touched.
using OldMembership = FlatSimplexMap<bool>;

// Scratch vectors are kept from one event to the next, which saves an allocation per event, but not
// at the size of a whole static rebuild (the initial triangulation, insertions and deletions at a
// frame): that would hold about a gigabyte for the rest of a million-cell run.
template <class T> void release_if_large(std::vector<T>& scratch) {
  if (scratch.capacity() > 4096)
    std::vector<T>().swap(scratch);
}

// The kinetic engine of one run (docs/MATH.md §2-§5). Outside it, only a run and its results are seen
// (KineticAlphaComplex); its state and its steps are private, and its member functions are defined in
// engine/, one header per concern (docs/ARCHITECTURE.md).
template <class K> class Engine {
public:
  Engine(const Trajectories& t, KineticOptions o); // engine/run.h
  void run(Observer& observer);                    // engine/run.h
  const KineticStatistics& statistics() const { return stats; }
  // The alpha complex just after now; after run, K(t_end-), just before the last frame (docs/MATH.md §0).
  std::vector<Simplex> current_complex() const; // engine/membership.h

private:
  // The input and the outputs of the run.
  const Trajectories& traj;
  KineticOptions options;
  KineticStatistics stats;

  // rho^2 = P/Q exactly and as intervals (the root cache's key polynomials take it from SlabMotion).
  mpz_class P, Q;
  Interval Pi, Qi;

  // The dimension of the run (docs/MATH.md §5.7): 3, or 2 for a planar run whose z is constant. Top
  // simplices have dim + 1 vertices, facets dim; the dimension-specific rules are K's
  // (kinetic_traits.h) and the static structures' (static_delaunay.h). Everything else is shared.
  static constexpr int dim = K::dimension;
  static constexpr std::size_t top_size() { return K::top_size; }

  // The current slab, time u inside it, the cells' motion in it and who is alive.
  std::size_t slab = 0;
  SlabTime now;
  std::shared_ptr<SlabMotion> motion; // shared with the roots isolated in this slab (root_cache.h)
  std::vector<char> alive;

  // Del(now+), held as cells (cell_triangulation.h), and the alpha-complex state of its finite
  // simplices. Each Delaunay certificate names the cell and facet index of its facet
  // (Certificate::cell): the cell of the facet's first apex, the one whose top simplex was there
  // first, or the first of two made by one change (Engine::install_touched_facets).
  CellTriangulation<dim> cells;
  using Apices = typename CellTriangulation<dim>::Apices;
  FaceStates faces;                       // finite simplices of dimension 1..dim in Del (face_states.h)
  std::vector<int> dropped_certs_scratch; // certificates of facets that left Del
  // The cells the last change of the triangulation made, in the order of its added top simplices:
  // its facets' certificates are theirs, and every face it touched that stays in Del is a face of
  // one of them. created_position[c] is c's position there during a large change, -1 otherwise.
  std::vector<CellIndex> created_cells;
  std::vector<int> created_position;
  std::vector<int> orientation_scratch;                                     // apply_top_change's
  std::vector<std::pair<Simplex, std::pair<CellIndex, int>>> facet_scratch; // install_touched_facets'
  std::vector<Simplex> coface_scratch;                                      // resolve_radius's

  // Certificates and their failure times (certificate_pool.h).
  CertificatePool certificates;

  // Certificates found invalid at the current time, waiting in the current batch.
  BatchAgenda agenda; // what the batch at now still has to resolve (batch_agenda.h)

  // Event batches emitted so far, and since the last audit.
  std::size_t batch_index = 0;
  std::size_t batches_since_audit = 0;

  // Certificates built on the same points share their polynomial up to sign, hence its roots: the
  // in-sphere of a 5-point set (the facet of a flip and the new interior facets), the orientation of
  // a 4-point set, the radius of a face (docs/MATH.md §3.8, caching; cleared at every frame).
  RootCache root_cache;

  // Scratch space of process_batch and change_tops, kept to avoid allocations per event.
  OldMembership batch_scratch;
  std::vector<BatchAgenda::Entry> radius_scratch; // resolve_radius's failed certificates
  TouchedFaces touched_scratch;
  std::vector<VertexId> link_scratch;                                  // gabriel_now's link vertices
  std::array<std::vector<std::pair<Simplex, bool>>, 4> settle_scratch; // settle_membership's buckets by size

  // ------------------------------------ geometry of certificates (templates over the number type)

  const MovingPoint& pt(VertexId v) const { return motion->points[static_cast<std::size_t>(v)]; }

  // The cells at now's enclosure, as a function of the vertex: a certificate given these points is
  // its value at now (certificate::PointAtTime), a few interval operations where the polynomial
  // costs many. The caller holds a CGAL::Protect_FPU_rounding guard.
  auto points_at_now() const {
    double lo, hi;
    now.enclosure(lo, hi);
    return [this, u = Interval(lo, hi)](VertexId v) { return certificate::PointAtTime{&pt(v), u}; };
  }

  // rho^2 = P/Q as the number type of a certificate computation.
  static const Interval& pick(const mpz_class&, const Interval& approx, const Interval&) { return approx; }
  static const mpz_class& pick(const mpz_class& exact, const Interval&, const mpz_class&) { return exact; }

  // The moving points of this slab, as an accessor for the certificate formulas (kinetic_traits.h).
  auto moving() const {
    return [this](VertexId v) -> const MovingPoint& { return pt(v); };
  }

  // Delaunay certificate of a facet, positive while valid (docs/MATH.md §3.1, §3.2; in the plane a facet
  // is an edge between two triangles): c's i-th facet, c the cell of its first apex.
  template <class NT> Poly<NT> delaunay_poly(const Simplex& facet, CellIndex c, int i) const {
    const Apices ap = cells.apices(c, i);
    const VertexId p = ap.v[0], q = ap.v[1];
    if (is_finite(facet)) {
      if (p == infinite_vertex || q == infinite_vertex) {
        // Case A: the orientation of the finite top simplex on the hull facet; it fails when the
        // apex reaches the hull facet's plane (line).
        const VertexId z = p == infinite_vertex ? q : p;
        const auto seq = K::join(facet, z);
        const Poly<NT> o = K::template orientation<NT>(seq, moving());
        return orientation_of(seq.data(), K::top_size, ap, z) > 0 ? o : -o;
      }
      // In-sphere (in-circle), positive while q is strictly outside the circumsphere of facet + p.
      const auto seq = K::join(facet, p);
      const Poly<NT> s = K::template in_sphere<NT>(seq, q, moving());
      return orientation_of(seq.data(), K::top_size, ap, p) * K::outside_sign > 0 ? s : -s;
    }
    // Case B: the infinite facet [-1 r] over the hull ridge r, between [-1 r p] and [-1 r q]: hull
    // facet r + p (c's facet without the infinite vertex), apex z of the finite top simplex below
    // it; the certificate O(r, p, q) oriented so that O(r, p, z) > 0 (the hull is convex at r while
    // q is on z's side of r + p).
    const Simplex ridge = facet.facet(0);
    const Apices hull = cells.apices(c, cells.index_of(c, infinite_vertex));
    const VertexId z = hull.v[1];
    const auto seq = K::join(ridge, p, z);
    const Poly<NT> o = K::template orientation<NT>(K::join(ridge, p, q), moving());
    return orientation_of(seq.data(), K::top_size, hull, z) > 0 ? o : -o;
  }

  // The in-sphere (in-circle) certificate of c's i-th facet with two finite apices, enclosed from
  // one pass in plain doubles (certificate_enclosure.h); false for the orientation certificates at
  // the hull.
  bool delaunay_enclosure(const Simplex& facet, CellIndex c, int i, IntervalPoly& f) const {
    const Apices ap = cells.apices(c, i);
    const VertexId p = ap.v[0], q = ap.v[1];
    if (!is_finite(facet) || p == infinite_vertex || q == infinite_vertex)
      return false;
    const auto seq = K::join(facet, p);
    f = K::in_sphere_enclosure(seq, q, moving());
    if (orientation_of(seq.data(), K::top_size, ap, p) * K::outside_sign < 0)
      f = -f;
    return true;
  }

  // At a hull ridge (c's i-th facet) whose certificate vanishes at now: whether its facets are folded
  // onto each other at now around a top simplex that is not flat then, so that the triangulation is
  // not embedded just after now (engine/certificates.h).
  bool hull_ridge_folded_at_now(const Simplex& facet, CellIndex c, int i);

  // Whether the hull facets ridge + p and ridge + q are folded onto each other (KineticTraits::fold).
  // `at` gives the points: moving (pt) for the polynomial, at now's enclosure (points_at_now) for its
  // value at now.
  template <class NT, class At>
  auto fold_poly(const Simplex& ridge, VertexId p, VertexId q, const At& at) const {
    return K::template fold<NT>(ridge, p, q, at);
  }
  template <class NT> Poly<NT> fold_poly(const Simplex& ridge, VertexId p, VertexId q) const {
    return fold_poly<NT>(ridge, p, q, moving());
  }
  // The hull facets at the ridge of the infinite facet [-1 a b] ([-1 a]), c's i-th.
  template <class NT> Poly<NT> hull_fold_poly(const Simplex& facet, CellIndex c, int i) const {
    const Apices ap = cells.apices(c, i);
    return fold_poly<NT>(facet.facet(0), ap.v[0], ap.v[1]);
  }

  // The orientation polynomial of a finite top simplex (a tetrahedron, a triangle in 2D); `at` gives
  // the moving points (pt: this slab's motion).
  template <class NT, class At> auto orientation_poly(const Simplex& t, const At& at) const {
    return K::template orientation<NT>(K::join(t), at);
  }
  template <class NT> Poly<NT> orientation_poly(const Simplex& t) const {
    return orientation_poly<NT>(t, moving());
  }

  // For a finite facet with two finite apices: the product of its two top simplices' orientations,
  // each signed by its recorded orientation, positive while both keep it (Substitute::cell_orientations).
  template <class NT> Poly<NT> cell_orientations_poly(const Simplex& facet, CellIndex c, int i) const {
    const Apices ap = cells.apices(c, i);
    Poly<NT> f(NT(1));
    for (int k = 0; k < 2; ++k) {
      std::array<VertexId, 4> w{};
      w[0] = ap.v[static_cast<std::size_t>(k)];
      std::copy(facet.begin(), facet.end(), w.begin() + 1);
      const Simplex t = Simplex::from_range(w.begin(), w.begin() + 1 + facet.size());
      const Poly<NT> o = orientation_poly<NT>(t);
      f = f * (ap.orientation[static_cast<std::size_t>(k)] > 0 ? o : -o);
    }
    return f;
  }

  // The radius polynomial f of a finite simplex: f <= 0 iff short (docs/MATH.md §3.3).
  template <class NT> Poly<NT> radius_poly(const Simplex& s, const NT& p, const NT& q) const {
    switch (s.size()) {
    case 2: return certificate::edge_radius<NT>(pt(s[0]), pt(s[1]), p, q);
    case 3: return certificate::triangle_radius<NT>(pt(s[0]), pt(s[1]), pt(s[2]), p, q);
    default: return certificate::tetrahedron_radius<NT>(pt(s[0]), pt(s[1]), pt(s[2]), pt(s[3]), p, q);
    }
  }

  template <class NT> Poly<NT> cert_poly(const Certificate& c) const;

  // cert_poly<Interval> enclosed from one pass in plain doubles (certificate_enclosure.h): cheaper,
  // wider. False for the orientation certificates at the hull.
  bool cert_enclosure(const Certificate& c, IntervalPoly& f) const {
    if (c.kind == CertKind::delaunay)
      return c.substitute == Substitute::none && delaunay_enclosure(c.key, c.cell, c.facet_index, f);
    if (!radius_enclosure(c.key, f))
      return false;
    if (faces.at(c.key).is_short)
      f = -f;
    return true;
  }

  // radius_poly<Interval>(s) enclosed from one pass in plain doubles; false for a vertex.
  bool radius_enclosure(const Simplex& s, IntervalPoly& f) const {
    if (s.size() == 2)
      f = edge_radius_enclosure(pt(s[0]), pt(s[1]), Pi, Qi);
    else if (s.size() == 3)
      f = triangle_radius_enclosure(pt(s[0]), pt(s[1]), pt(s[2]), Pi, Qi);
    else if (s.size() == 4)
      f = tetrahedron_radius_enclosure(pt(s[0]), pt(s[1]), pt(s[2]), pt(s[3]), Pi, Qi);
    else
      return false;
    return true;
  }

  // The sign of a polynomial given by a builder (called with an NT tag) on now's enclosure, or 0 when
  // the enclosure does not decide it; a sign there is the sign at, just after and just before now.
  template <class Build> int sign_on_enclosure_of_now(Build&& build) const {
    CGAL::Protect_FPU_rounding<true> guard;
    const IntervalPoly f = build(Interval());
    double lo, hi;
    now.enclosure(lo, hi);
    return interval_sign(f, lo, hi);
  }

  // sign^+ (just after now) and sign^- (just before now, in this slab's motion), filter first.
  template <class Build> int sign_plus_now(Build&& build) { return sign_beside_now(build, true); }
  template <class Build> int sign_minus_now(Build&& build) { return sign_beside_now(build, false); }
  template <class Build> int sign_beside_now(Build&& build, bool after) {
    ++stats.sign_evaluations;
    if (const int s = sign_on_enclosure_of_now(build); s != 0)
      return s;
    ++stats.sign_evaluations_exact;
    const ExactPoly f = to_exact_poly(build(mpz_class()));
    return after ? sign_plus(f, now) : sign_minus(f, now);
  }

  template <class Build> int sign_at_now(Build&& build) {
    if (const int s = sign_on_enclosure_of_now(build); s != 0)
      return s;
    return sign_at(to_exact_poly(build(mpz_class())), now);
  }

  // ------------------------------------ certificates and their scheduling (engine/certificates.h)

  int orientation_of(const VertexId* seq, std::size_t n, const Apices& ap, VertexId apex) const;
  int orientation_sign_plus(const Simplex& t);
  bool flat_without_turning_at_now(const Simplex& t);  // engine/certificates.h
  int orientation_sign_before_frame(const Simplex& t); // 0: none at the previous frame
  int sign_after_own_orientation_root(const Simplex& t) const;
  bool top_simplex_turns_at_frame();  // engine/frames.h
  bool flat_at_now(const Simplex& t); // a finite top simplex whose orientation vanishes at now
  bool is_hull_orientation(const Certificate& c) const;         // engine/certificates.h
  bool degenerate_hull_facet_at(const Simplex& s);              // engine/flips.h
  bool collinear_at_now(const Simplex& f);                      // three cells, on one line at now
  int orientation_enclosure_sign(const Simplex& t);             // 0: the enclosure at now does not decide
  GeometryError flat_top_simplex_error(const Simplex& t) const; // t stays flat just after now
  GeometryError too_many_tops_error(const Simplex& f) const;    // f would exceed max_face_tops
  int sign_after_own_root(const IntervalPoly& f, const CacheKey& key) const;
  int new_cert(CertKind kind, const Simplex& key);
  void kill_cert(int id);
  // at_now, when given and now is a slab start (a frame), receives the enclosure of the certificate's
  // value there from the first enclosure built, the one from plain doubles; it stays as it was when
  // that enclosure was not built (hull orientations) or now is inside the slab.
  void install(int id, Interval* at_now = nullptr);
  void settle_certificate(int id, bool counted = true, Interval* at_now = nullptr);
  void count_built(const Certificate& c, bool enclosed);
  // wide: f is the enclosure from plain doubles (certificate_enclosure.h), replaced by the interval
  // one before its root is reported (Engine::run_slab).
  bool install_in_doubles(int id, const IntervalPoly& f, bool wide = false);
  bool schedule_first_change(int id, const IntervalPoly& f, int sign, double start, const CacheKey& key,
                             int shift = 0, bool wide = false);
  bool install_vanishing_at_start(int id, const IntervalPoly& f);
  bool install_from_exact_coefficients(int id, const Poly<mpz_class>& f);
  KeyPolynomial key_polynomial(const CacheKey& key) const;
  CacheKey cache_key(const Certificate& c) const;
  void mark_invalid(int id);
  void retire_all_certs();
  // The Delaunay certificate of c's i-th facet, built anew (c: the cell of its first apex); of a
  // facet by its vertices (nothing when it is not in Del).
  void install_facet(CellIndex c, int i);
  void install_facet_at(const Simplex& facet);
  void install_radius(const Simplex& s) { install_radius(s, faces.at(s)); }
  void install_radius(const Simplex& s, Face& f, Interval* at_now = nullptr); // f: s's state
  bool compute_short(const Simplex& s);

  // ------------------------------------ Del changes, frontier, membership (engine/membership.h)

  bool in_k(const Simplex& s) const { return faces.in_k(s, alive); }
  // Replaces top simplices (removed_cells: their cells, in the same order) and records the old
  // membership of every touched simplex in old_k, when given.
  void change_tops(const std::vector<Simplex>& removed, const std::vector<CellIndex>& removed_cells,
                   const std::vector<Simplex>& added, OldMembership* old_k,
                   const int* added_orientations = nullptr);
  // A flip, when the change is one (Engine::flip): the cell holding the flipped facet, named by the
  // facet's certificate (Certificate::cell), the facet's index there, and the change.
  struct HeldFlip {
    CellIndex cell = no_cell;
    int index = 0;
    const FlipChange* change = nullptr;
  };
  // change_tops in phases, for a flip: every touched face is looked up in `faces` once, and its
  // entry is held in touched_scratch throughout (the flags, counts and frontier rules read only
  // touched faces and their facets, which are touched too). apply_top_change keeps the faces that
  // leave Del, with no top simplex, until finish_top_change erases them (erasing moves entries);
  // settle_touched re-evaluates membership in between. held_flip, for a flip, makes it on the held
  // cell (removed_cells is then not read). The Delaunay certificates of the new cells' facets are
  // installed by install_touched_facets, which reads only the triangulation: a flip calls it before
  // settle_touched, change_tops after finish_top_change, once the touched faces are let go.
  void apply_top_change(const std::vector<Simplex>& removed, const std::vector<CellIndex>& removed_cells,
                        const std::vector<Simplex>& added, const int* added_orientations,
                        const HeldFlip* held_flip = nullptr);
  // The flip of a held change on the cells, its new cells in created_cells in the order of `added`.
  void flip_cells(const HeldFlip& held_flip, const std::vector<Simplex>& added,
                  const std::vector<int>& orientations, std::vector<int>& dropped);
  void install_touched_facets();
  void settle_touched(Step& step);
  void finish_top_change();

  // ------------------------------------ look-ups in the triangulation by vertices (engine/cells.h)

  // A cell holding the simplex s, no_cell when s is not in Del: among the cells of the last change
  // first (the faces a change touches are theirs), then by a walk round a vertex of s.
  CellIndex cell_holding(const Simplex& s) const;
  // The same for a face of Del with its state: the cell the state names when it still holds s (set
  // by the change that made it, apply_top_change), otherwise found as above and kept there.
  CellIndex cell_holding(const Simplex& s, Face& state) const;
  // The cell and index naming the facet (c, i) in its certificate: the cell of its first apex.
  std::pair<CellIndex, int> facet_owner(CellIndex c, int i) const;
  bool has_top(const Simplex& t) const { return cells.find(t) != no_cell; }
  // The apex across the facet f from its apex `apex` (f + apex must be a top simplex).
  VertexId other_apex(const Simplex& f, VertexId apex) const;
  // Calls f(c) for every cell c containing s; f must not walk the triangulation itself.
  template <class F> void for_each_cell_containing(const Simplex& s, F&& f) const {
    if (const CellIndex start = cell_holding(s); start != no_cell)
      cells.for_each_cell_containing_from(start, s, f);
  }
  // Calls f(t) for every top simplex t containing s; f must not walk the triangulation itself.
  template <class F> void for_each_top_containing(const Simplex& s, F&& f) const {
    for_each_cell_containing(s, [&](CellIndex c) { f(cells.top(c)); });
  }
  std::vector<Simplex> tops_containing(const Simplex& s) const {
    std::vector<Simplex> result;
    for_each_top_containing(s, [&](const Simplex& t) { result.push_back(t); });
    return result;
  }
  // The finite (k+1)-cofaces of a finite k-simplex s of Del with its state, sorted, each once.
  void finite_cofaces(const Simplex& s, Face& state, std::vector<Simplex>& out) const;
  // The top simplices of `held`, sorted (the canonical order a change is applied in), with `held`
  // put in the same order.
  std::vector<Simplex> sort_by_top(std::vector<CellIndex>& held) const;
  // The top simplices of Del, in cell order.
  std::vector<Simplex> all_tops() const {
    std::vector<Simplex> tops;
    tops.reserve(cells.size());
    cells.for_each_cell([&](CellIndex c) { tops.push_back(cells.top(c)); });
    return tops;
  }
  bool is_short(const Simplex& s) const { return faces.is_short(s); }
  // The state of a face of Del, or nullptr: from the table, or from the faces touched by the change
  // being applied.
  Face* state_in_table(const Simplex& s) { return faces.find(s); }
  // A flip's faces are found by their bit mask; a larger change (a static rebuild, the first
  // triangulation: about a million faces for 30,000 cells) looks in the table instead of a binary
  // search of the touched list, one cache miss instead of twenty. The facets of a touched face are
  // touched too, and in the table until finish_top_change erases the faces that left.
  Face* state_in_touched(const Simplex& s) {
    if (touched_scratch.local_count == 0)
      return s.size() < 2 ? nullptr : faces.find(s);
    TouchedFace* t = touched_scratch.find(s);
    return t == nullptr ? nullptr : t->state;
  }
  bool in_frontier(const Simplex& s) const { return in_frontier(s, faces.at(s)); }
  bool in_frontier(const Simplex& s, const Face& f) const {
    return FaceStates::in_frontier(s, f, [&](const Simplex& x) { return is_short(x); });
  }
  void update_frontier(const Simplex& s) { update_frontier(s, faces.at(s)); }
  void update_frontier(const Simplex& s, Face& f) { set_frontier(s, f, in_frontier(s, f)); } // f: s's state
  void set_frontier(const Simplex& s, Face& f, bool want);
  bool gabriel_now(const Simplex& s, Face& f); // f: s's state
  void count_in_facets(const Simplex& c, int short_delta, int k_delta) {
    FaceStates::count_in_facets(c, short_delta, k_delta, [&](const Simplex& x) { return state_in_table(x); });
  }
  void settle_membership(const OldMembership& old_k, Step& step);
  // The membership of s just after now, given its state; updates the coface counts of its facets.
  template <class StateOf> bool settle(const Simplex& s, Face& f, StateOf&& state_of);

  // ------------------------------------ flips (docs/MATH.md §4.5) and radius events (engine/flips.h)

  void flip(int cert, const FlipChange& change, std::vector<Step>& steps); // cert: the failed facet's
  void repair(std::vector<Step>& steps);
  bool flippable(int cert, FlipChange& change); // cert: the failed facet's
  void resolve_delaunay(std::vector<Step>& steps);
  void resolve_radius(Step& settle, OldMembership& old_k);
  void resolve_touches(OldMembership& old_k);
  void resolve_hull_touches();
  bool radius_vanishes_now(const Simplex& s);

  // ------------------------------------ the event loop and batches (engine/event_loop.h)

  EventTime event_time(bool at_frame) const;
  void emit_batch(Observer& observer, std::vector<Step>& steps, bool at_frame);
  void process_batch(std::vector<Step>& steps);
  void fire(const QueueEntry& e);
  void at_own_time(int cert); // now = the time cert fired at, if it fired in this batch
  void run_slab(Observer& observer);

  // ------------------------------------ static rebuilds with CGAL (engine/static_rebuild.h)

  detail::StaticInput static_input(const std::vector<VertexId>& ids) const;
  std::vector<VertexId> alive_ids() const;
  // old_k, when given, receives the membership before the change of every simplex it touched.
  void rebuild_static(OldMembership* old_k);
  void reorient_kept(const std::vector<CellIndex>& kept); // the cells the rebuild kept
  // After a change: the added top simplices are created_cells'.
  void reinstall_hull_ridges_over(const std::vector<Simplex>& added, const std::vector<Simplex>& removed);
  // Calls f on the infinite facets over the ridges of c's i-th facet when it is a hull facet: the hull
  // ridges whose certificates are oriented by the top simplex below it (docs/MATH.md §3.2 case B).
  template <class F> void for_each_hull_ridge_over(CellIndex c, int i, F&& f) const {
    if (!cells.apices(c, i).has(infinite_vertex))
      return;
    const Simplex f_hull = cells.facet(c, i);
    for (std::size_t j = 0; j < f_hull.size(); ++j)
      f(f_hull.facet(j).with(infinite_vertex));
  }
  Rational rational_before_next_event() const;
  std::vector<Simplex> delaunay_after_algebraic_now(const std::vector<VertexId>& ids, int& dimension);

  // ------------------------------------ collisions (engine/collisions.h)

  void check_collisions_at_frame(std::size_t k) const;
  // A collision foretold (docs/MATH.md §2.5): the time u in (now, 1) at which the cells of an edge
  // meet, and the edge.
  using Collision = std::pair<mpq_class, Simplex>;
  // Keeps in `earliest` the earlier of it and e's collision, if e's cells meet after now (exact;
  // among equal times the edge first in trajectory order), so that of the collisions foretold
  // together the earliest is reported, whatever order the edges come in.
  void note_collision(const Simplex& e, std::optional<Collision>& earliest) const;
  [[noreturn]] void throw_collision(const Collision& c) const;
  void check_collisions_in_slab() const;

  // ------------------------------------ frames, insertions, deletions (engine/frames.h)

  void set_slab_motion(std::size_t k);
  void reinstall_all();
  void frame(Observer& observer, std::size_t k);
  void insert_or_delete(VertexId v, bool insert, std::vector<Step>& steps);
  void record_top_changes(Step& step, OldMembership& old_k);
  // The finite top simplices of a change, as the step reports them.
  static void record_delaunay_change(Step& step, const std::vector<Simplex>& removed,
                                     const std::vector<Simplex>& added) {
    for (const Simplex& t : removed)
      if (is_finite(t))
        step.delaunay_removed.push_back(t);
    for (const Simplex& t : added)
      if (is_finite(t))
        step.delaunay_created.push_back(t);
  }

  // ------------------------------------ local insertions and deletions (engine/local_updates.h)

  // The top simplices to remove and add (with the orientations sign^+ of the added ones, 0 for
  // infinite ones) for inserting or deleting v at now; false, with nothing changed, where a predicate
  // vanishes for the whole slab or a check fails, and the caller rebuilds statically.
  bool insert_locally(VertexId v, std::vector<CellIndex>& removed, std::vector<Simplex>& added,
                      std::vector<int>& orientations);
  bool delete_locally(VertexId v, std::vector<CellIndex>& removed, std::vector<Simplex>& added,
                      std::vector<int>& orientations);
  bool record_local_change(Step& step, OldMembership& old_k, VertexId v, bool insert);
  int in_conflict_just_after(CellIndex c, VertexId v);
  int facet_side_just_after(const Simplex& f, VertexId x);
  bool find_conflict(VertexId v, CellIndex& seed);

  // ------------------------------------ the run (engine/run.h)

  void check_planar() const;
  void initialise(Observer& observer);

  // ------------------------------------ degenerate groups of static repairs (engine/degenerate_groups.h)

  int orientation_at_now(const Simplex& t);
  bool cospherical_at_now(const Simplex& t, VertexId y);
  bool concyclic_at_now(const Simplex& t);
  bool face_group_within_rho(const std::vector<VertexId>& p, const std::vector<VertexId>& apices,
                             const std::vector<Simplex>& cofaces);
  std::vector<DegenerateGroup> degenerate_groups(const std::vector<Simplex>& removed,
                                                 const std::vector<Simplex>& added);

  // ------------------------------------ audit (engine/audit.h)

  [[noreturn]] void audit_failure(const std::string& what) const;
  void audit();
  void audit_embedded(const Rational& q, const std::vector<Simplex>& cgal_tops);
  void audit_supporting(const Rational& q, const Simplex& hull_facet);
};

template <class K> template <class NT> Poly<NT> Engine<K>::cert_poly(const Certificate& c) const {
  if (c.kind == CertKind::delaunay) {
    switch (c.substitute) {
    case Substitute::hull_fold: return -hull_fold_poly<NT>(c.key, c.cell, c.facet_index);
    case Substitute::cell_orientations: return cell_orientations_poly<NT>(c.key, c.cell, c.facet_index);
    case Substitute::none: break;
    }
    return delaunay_poly<NT>(c.key, c.cell, c.facet_index);
  }
  Poly<NT> f = radius_poly<NT>(c.key, pick(P, Pi, NT()), pick(Q, Qi, NT()));
  // Positive while valid: -f while short, +f while long (docs/MATH.md §3.1).
  return faces.at(c.key).is_short ? -f : f;
}

// Instantiated once per dimension, in engine_2.cpp and engine_3.cpp.
extern template class Engine<KineticTraits2>;
extern template class Engine<KineticTraits3>;

} // namespace medusa::kinetic::detail
