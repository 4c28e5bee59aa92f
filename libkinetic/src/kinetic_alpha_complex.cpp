// The kinetic engine: event loop, flips, radius events, frames, insertions and deletions, audit.
// MATH.md sections are cited where each rule is applied.
#include "medusa/kinetic/kinetic_alpha_complex.h"

#include "medusa/kinetic/algebraic_time.h"
#include "medusa/kinetic/certificate_polynomials.h"
#include "medusa/kinetic/error.h"
#include "medusa/kinetic/interval_filter.h"
#include "medusa/kinetic/root_isolation.h"
#include "static_delaunay.h"
#include "triangulation.h"

#include <CGAL/FPU.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace medusa::kinetic {

using detail::infinite_vertex;
using detail::is_finite;

SquaredRadius squared_radius_from_decimal(const std::string& rho, std::int64_t scale) {
  // rho = digits[.digits]; rho_g = S rho = N / 10^d exactly, rho_g^2 = N^2 / 10^(2d).
  std::size_t dot = rho.find('.');
  std::string digits = rho.substr(0, dot);
  std::string fraction = dot == std::string::npos ? "" : rho.substr(dot + 1);
  if ((digits.empty() && fraction.empty()) || rho.find_first_not_of("0123456789.") != std::string::npos ||
      std::count(rho.begin(), rho.end(), '.') > 1)
    throw InputError("radius '" + rho + "' is not a positive decimal number");
  mpz_class n(digits.empty() ? "0" : digits);
  mpz_class den = 1;
  for (char c : fraction) {
    n = n * 10 + (c - '0');
    den *= 10;
  }
  if (n == 0)
    throw InputError("radius must be positive, got '" + rho + "'");
  n *= scale;
  mpz_class g = gcd(n, den);
  n /= g;
  den /= g;
  return {n * n, den * den};
}

namespace {

enum class CertKind : std::uint8_t { delaunay, radius };

struct Certificate {
  CertKind kind = CertKind::delaunay;
  Simplex key; // the facet (delaunay) or the finite face (radius)
  std::uint32_t version = 0;
  bool alive = false;
};

struct QueueEntry {
  SlabTime u;
  std::uint32_t cert;
  std::uint32_t version;
};
struct LaterFirst {
  bool operator()(const QueueEntry& a, const QueueEntry& b) const { return compare(b.u, a.u) < 0; }
};

// The exact polynomial behind a root-cache key, up to sign (MATH.md 3.1): the in-sphere determinant
// of five points, the orientation of four, or the radius polynomial of a simplex. It copies the
// points' motion, so it stays valid after the triangulation has moved on within the slab.
struct KeyPolynomial {
  int kind = 0; // 0 in-sphere, 1 orientation, 2 radius (as CacheKey::v[0])
  int count = 0;
  std::array<MovingPoint, 5> pts{};
  std::shared_ptr<const SquaredRadius> rho2;

  ExactPoly operator()() const {
    Poly<mpz_class> f;
    const auto& p = pts;
    if (kind == 0)
      f = certificate::in_sphere<mpz_class>(p[0], p[1], p[2], p[3], p[4]);
    else if (kind == 1)
      f = certificate::orientation<mpz_class>(p[0], p[1], p[2], p[3]);
    else if (count == 2)
      f = certificate::edge_radius<mpz_class>(p[0], p[1], rho2->num, rho2->den);
    else if (count == 3)
      f = certificate::triangle_radius<mpz_class>(p[0], p[1], p[2], rho2->num, rho2->den);
    else
      f = certificate::tetrahedron_radius<mpz_class>(p[0], p[1], p[2], p[3], rho2->num, rho2->den);
    // Divide out u^m: the same roots in (0, 1], and no root at 0, where an isolating interval
    // starting at a frame may begin (CGAL's algebraic reals need a polynomial non-zero at the ends).
    Poly<mpz_class> g;
    int m = 0;
    while (m < f.degree_bound() && f[m] == 0)
      ++m;
    for (int i = f.degree_bound(); i >= m; --i)
      g = g * Poly<mpz_class>(mpz_class(0), mpz_class(1)) + Poly<mpz_class>(f[i]);
    return to_exact_poly(g);
  }
};

struct Face {
  bool is_short = false;
  bool in_k = false;
  int cert = -1;
};

// Parity of the permutation that sorts `seq` (+1 even, -1 odd).
int permutation_sign(std::array<VertexId, 4> seq) {
  int sign = 1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (seq[i] > seq[j])
        sign = -sign;
  return sign;
}

template <class F> void for_each_face(const Simplex& t, F&& f) {
  // Every non-empty subset of the vertices of t that avoids the infinite vertex.
  const std::size_t n = t.size();
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    std::array<VertexId, 4> v{};
    std::size_t k = 0;
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i)
      if (mask & (1u << i)) {
        v[k++] = t[i];
        finite = finite && t[i] != infinite_vertex;
      }
    if (finite)
      f(Simplex::from_range(v.begin(), v.begin() + k));
  }
}

} // namespace

struct KineticAlphaComplex::Impl {
  const Trajectories& traj;
  KineticOptions options;
  KineticStatistics stats;

  mpz_class P, Q;
  Interval Pi, Qi;
  std::shared_ptr<const SquaredRadius> rho2_shared;

  std::size_t slab = 0;
  SlabTime now;
  std::vector<MovingPoint> motion;
  std::vector<char> alive;

  detail::Triangulation tri;
  std::unordered_map<Simplex, int, SimplexHash> orient; // sign of O(sorted vertices), finite tets
  std::unordered_map<Simplex, Face, SimplexHash> faces; // finite simplices of dimension 1..3 in Del
  std::unordered_map<Simplex, int, SimplexHash> facet_cert;

  std::vector<Certificate> certs;
  std::vector<int> free_certs;
  std::priority_queue<QueueEntry, std::vector<QueueEntry>, LaterFirst> queue;

  // Certificates found invalid at the current time, waiting in the current batch.
  std::set<std::pair<Simplex, int>> pending_delaunay;
  std::vector<std::pair<int, std::uint32_t>> pending_radius; // (certificate, version)

  std::size_t batch_index = 0;
  std::size_t batches_since_audit = 0;

  Impl(const Trajectories& t, KineticOptions o) : traj(t), options(std::move(o)) {
    P = options.rho2.num;
    Q = options.rho2.den;
    Pi = Interval(CGAL::to_interval(CGAL::Gmpz(P.get_mpz_t())));
    Qi = Interval(CGAL::to_interval(CGAL::Gmpz(Q.get_mpz_t())));
    rho2_shared = std::make_shared<const SquaredRadius>(options.rho2);
    motion.resize(traj.cells.size());
    alive.assign(traj.cells.size(), 0);
  }

  // ---------------------------------------------------------------- geometry of certificates

  const MovingPoint& pt(VertexId v) const { return motion[static_cast<std::size_t>(v)]; }

  // rho^2 = P/Q as the number type of a certificate computation.
  static const Interval& pick(const mpz_class&, const Interval& approx, const Interval&) { return approx; }
  static const mpz_class& pick(const mpz_class& exact, const Interval&, const mpz_class&) { return exact; }

  // The oriented sign of the 4-sequence seq (finite tetrahedron of Del).
  int orientation_of(const std::array<VertexId, 4>& seq) const {
    Simplex sorted = Simplex::from_range(seq.begin(), seq.end());
    auto it = orient.find(sorted);
    if (it == orient.end()) {
      std::ostringstream os;
      os << "no orientation for tetrahedron " << sorted;
      throw InternalError(os.str());
    }
    return it->second * permutation_sign(seq);
  }

  // Delaunay certificate of a facet, positive while valid (MATH.md 3.1, 3.2).
  template <class NT> Poly<NT> delaunay_poly(const Simplex& facet) const {
    const detail::Triangulation::Apices* ap = tri.apices(facet);
    VertexId p = ap->v[0], q = ap->v[1];
    if (is_finite(facet)) {
      if (p == infinite_vertex || q == infinite_vertex) {
        // Case A: the orientation of the finite cell below the hull facet.
        VertexId z = p == infinite_vertex ? q : p;
        std::array<VertexId, 4> seq{facet[0], facet[1], facet[2], z};
        Poly<NT> o = certificate::orientation<NT>(pt(seq[0]), pt(seq[1]), pt(seq[2]), pt(seq[3]));
        return orientation_of(seq) > 0 ? o : -o;
      }
      std::array<VertexId, 4> seq{facet[0], facet[1], facet[2], p};
      Poly<NT> s = certificate::in_sphere<NT>(pt(seq[0]), pt(seq[1]), pt(seq[2]), pt(seq[3]), pt(q));
      return orientation_of(seq) > 0 ? s : -s;
    }
    // Case B: facet (inf, a, b) between (inf, a, b, c) and (inf, a, b, d): hull facet abc, apex z of
    // the finite cell below it; the certificate O(a, b, c, d) oriented so that O(a, b, c, z) > 0.
    VertexId a = facet[1], b = facet[2], c = p, d = q;
    Simplex hull{a, b, c};
    VertexId z = tri.other_apex(hull, infinite_vertex);
    std::array<VertexId, 4> seq{a, b, c, z};
    Poly<NT> o = certificate::orientation<NT>(pt(a), pt(b), pt(c), pt(d));
    return orientation_of(seq) > 0 ? o : -o;
  }

  // The radius polynomial f of a finite simplex: f <= 0 iff short (MATH.md 3.3).
  template <class NT> Poly<NT> radius_poly(const Simplex& s, const NT& p, const NT& q) const {
    switch (s.size()) {
    case 2: return certificate::edge_radius<NT>(pt(s[0]), pt(s[1]), p, q);
    case 3: return certificate::triangle_radius<NT>(pt(s[0]), pt(s[1]), pt(s[2]), p, q);
    default: return certificate::tetrahedron_radius<NT>(pt(s[0]), pt(s[1]), pt(s[2]), pt(s[3]), p, q);
    }
  }

  template <class NT> Poly<NT> cert_poly(const Certificate& c) const;

  // sign^+ at `now` of a polynomial given by a builder (called with an NT tag), filter first.
  template <class Build> int sign_plus_now(Build&& build) {
    ++stats.sign_evaluations;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      IntervalPoly f = build(Interval());
      double lo, hi;
      now.enclosure(lo, hi);
      int s = interval_sign(f, lo, hi);
      if (s != 0)
        return s;
    }
    ++stats.sign_evaluations_exact;
    return sign_plus(to_exact_poly(build(mpz_class())), now);
  }

  template <class Build> int sign_at_now(Build&& build) {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      IntervalPoly f = build(Interval());
      double lo, hi;
      now.enclosure(lo, hi);
      int s = interval_sign(f, lo, hi);
      if (s != 0)
        return s;
    }
    return sign_at(to_exact_poly(build(mpz_class())), now);
  }

  // ---------------------------------------------------------------- certificates

  struct CacheKey {
    std::array<VertexId, 6> v;
    bool operator==(const CacheKey& o) const { return v == o.v; }
  };
  struct CacheKeyHash {
    std::size_t operator()(const CacheKey& k) const {
      std::size_t h = 0;
      for (VertexId x : k.v)
        h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::size_t>(x + 3);
      return h;
    }
  };

  int new_cert(CertKind kind, const Simplex& key) {
    int id;
    if (!free_certs.empty()) {
      id = free_certs.back();
      free_certs.pop_back();
    } else {
      id = static_cast<int>(certs.size());
      certs.emplace_back();
    }
    Certificate& c = certs[static_cast<std::size_t>(id)];
    c.kind = kind;
    c.key = key;
    c.alive = true;
    ++c.version;
    return id;
  }

  void kill_cert(int id) {
    if (id < 0)
      return;
    Certificate& c = certs[static_cast<std::size_t>(id)];
    if (c.kind == CertKind::delaunay)
      pending_delaunay.erase({c.key, id});
    c.alive = false;
    ++c.version;
    free_certs.push_back(id);
  }

  // Evaluates a fresh certificate at `now`: schedules its next failure in (now, 1), or queues it in
  // the current batch when it is already invalid just after now (MATH.md 3.7, 3.9).
  void install(int id) {
    ++stats.certificates_built;
    Certificate& c = certs[static_cast<std::size_t>(id)];
    {
      CGAL::Protect_FPU_rounding<true> guard;
      IntervalPoly f = cert_poly<Interval>(c);
      double lo, hi;
      now.enclosure(lo, hi);
      if (bernstein_sign_subdivided(f, lo, 4) > 0) {
        ++stats.filter_settled;
        return;
      }
      if (install_in_doubles(id, f))
        return;
    }
    ++stats.exact_settled;
    ++(c.kind == CertKind::delaunay ? stats.exact_delaunay : stats.exact_radius);
    Poly<mpz_class> exact = cert_poly<mpz_class>(c);
    if (install_from_exact_coefficients(id, exact)) {
      ++stats.exact_filter_settled;
      return;
    }
    ExactPoly f = to_exact_poly(exact);
    if (CGAL::is_zero(f))
      return; // identically zero: valid, never scheduled (MATH.md 3.9)
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
    if (!roots.empty()) {
      ++stats.exact_scheduled;
      queue.push({SlabTime(roots.front()), static_cast<std::uint32_t>(id), c.version});
    }
  }

  // The fast path of install (MATH.md 3.8): the sign just after now and the next failure time,
  // isolated in double interval arithmetic. False when doubles cannot decide; nothing is changed then.
  bool install_in_doubles(int id, const IntervalPoly& f) {
    const Certificate& c = certs[static_cast<std::size_t>(id)];
    const CacheKey key = cache_key(c);
    double lo, hi;
    now.enclosure(lo, hi);
    int sign;
    const IsolatedRoot* current = now.isolated();
    if (current != nullptr && lo < hi && current->key == key.v) {
      // f is +-(the polynomial whose root is now): its only root in (lo, hi) is now itself, so its
      // sign just after now is its sign at hi (the flipped facet, the toggled radius certificate).
      sign = interval_sign(f, hi, hi);
    } else {
      // f keeps one sign on the enclosure of now: it does not vanish at now.
      sign = interval_sign(f, lo, hi);
    }
    if (sign == 0 || !schedule_first_change(id, f, sign, hi, key))
      return false;
    ++stats.interval_settled;
    return true;
  }

  // With the sign of f just after now known and no other root of f in (now, start]: isolates the
  // first sign change of f after start, then marks the certificate invalid or schedules its failure.
  // False when doubles cannot decide; nothing is changed then.
  bool schedule_first_change(int id, const IntervalPoly& f, int sign, double start, const CacheKey& key) {
    const Certificate& c = certs[static_cast<std::size_t>(id)];
    FirstSignChange next = first_sign_change(f, start, 12);
    if (next.status == FirstSignChange::Status::undecided || next.sign != sign)
      return false;
    if (sign < 0) {
      ++stats.invalid_at_creation;
      mark_invalid(id);
      return true;
    }
    if (next.status == FirstSignChange::Status::root) {
      ++stats.interval_scheduled;
      auto root = std::make_shared<IsolatedRoot>();
      root->enclosure = f;
      root->lo = next.lo;
      root->hi = next.hi;
      root->sign_lo = sign;
      root->key = key.v;
      root->slab = slab;
      root->exact = key_polynomial(key);
      queue.push({SlabTime(std::move(root)), static_cast<std::uint32_t>(id), c.version});
    }
    return true;
  }

  // The second path, on the exact coefficients rounded outward to doubles (tight enclosures): at a
  // rational slab start (u = 0: t_0 and frames) the root at 0 of multiplicity m is divided out first,
  // which settles the lattice-degenerate certificates of CC3D's initial layout (MATH.md 5.5) without
  // CGAL. False when doubles cannot decide; nothing is changed then.
  bool install_from_exact_coefficients(int id, const Poly<mpz_class>& f) {
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
    return schedule_first_change(id, g, sgn(f[m]) > 0 ? 1 : -1, 0.0,
                                 cache_key(certs[static_cast<std::size_t>(id)]));
  }

  KeyPolynomial key_polynomial(const CacheKey& key) const {
    KeyPolynomial k;
    k.kind = key.v[0];
    k.rho2 = rho2_shared;
    for (std::size_t i = 1; i < key.v.size() && key.v[i] != -2; ++i)
      k.pts[static_cast<std::size_t>(k.count++)] = pt(key.v[i]);
    return k;
  }

  // Certificates built on the same points share their polynomial up to sign, hence its roots: the
  // in-sphere of a 5-point set (the facet of a flip and the new interior facets), the orientation of
  // a 4-point set, the radius of a face (MATH.md 3.8, caching; cleared at every frame).
  std::unordered_map<CacheKey, RealRoots, CacheKeyHash> root_cache;

  CacheKey cache_key(const Certificate& c) const {
    CacheKey k;
    k.v.fill(-2);
    std::vector<VertexId> pts;
    if (c.kind == CertKind::radius) {
      k.v[0] = 2;
      pts.assign(c.key.begin(), c.key.end());
    } else {
      const detail::Triangulation::Apices* ap = tri.apices(c.key);
      pts.assign(c.key.begin(), c.key.end());
      pts.push_back(ap->v[0]);
      pts.push_back(ap->v[1]);
      bool infinite = std::find(pts.begin(), pts.end(), infinite_vertex) != pts.end();
      k.v[0] = infinite ? 1 : 0;
      if (infinite) {
        // Case A: the finite tetrahedron; case B: the four finite points (MATH.md 3.2).
        pts.erase(std::remove(pts.begin(), pts.end(), infinite_vertex), pts.end());
      }
      std::sort(pts.begin(), pts.end());
    }
    for (std::size_t i = 0; i < pts.size(); ++i)
      k.v[i + 1] = pts[i];
    return k;
  }

  void mark_invalid(int id) {
    const Certificate& c = certs[static_cast<std::size_t>(id)];
    if (c.kind == CertKind::delaunay)
      pending_delaunay.insert({c.key, id});
    else
      pending_radius.emplace_back(id, c.version);
  }

  void install_facet(const Simplex& facet) {
    auto it = facet_cert.find(facet);
    if (it != facet_cert.end()) {
      kill_cert(it->second);
      facet_cert.erase(it);
    }
    const detail::Triangulation::Apices* ap = tri.apices(facet);
    if (ap == nullptr)
      return;
    if (ap->count != 2) {
      std::ostringstream os;
      os << "facet " << facet << " has " << ap->count << " tetrahedra";
      throw InternalError(os.str());
    }
    int id = new_cert(CertKind::delaunay, facet);
    facet_cert[facet] = id;
    install(id);
  }

  void install_radius(const Simplex& s) {
    Face& f = faces[s];
    kill_cert(f.cert);
    f.cert = new_cert(CertKind::radius, s);
    install(f.cert);
  }

  bool compute_short(const Simplex& s) {
    int sp = sign_plus_now(
        [&](auto tag) { return radius_poly<decltype(tag)>(s, pick(P, Pi, tag), pick(Q, Qi, tag)); });
    return sp <= 0; // f == 0 identically means R = rho: short (MATH.md 3.9)
  }

  // ---------------------------------------------------------------- triangulation changes

  bool in_k(const Simplex& s) const {
    if (s.size() == 1)
      return alive[static_cast<std::size_t>(s[0])] != 0;
    auto it = faces.find(s);
    return it != faces.end() && it->second.in_k;
  }

  // Replaces tetrahedra; records the old membership of every touched finite simplex.
  void change_tets(const std::vector<Simplex>& removed, const std::vector<Simplex>& added,
                   std::unordered_map<Simplex, bool, SimplexHash>& old_k) {
    std::unordered_set<Simplex, SimplexHash> touched_faces, touched_facets;
    for (const auto* list : {&removed, &added})
      for (const Simplex& t : *list) {
        for_each_face(t, [&](const Simplex& f) {
          touched_faces.insert(f);
          old_k.emplace(f, in_k(f));
        });
        for (std::size_t i = 0; i < 4; ++i)
          touched_facets.insert(t.facet(i));
      }
    for (const Simplex& t : removed) {
      tri.remove_tet(t);
      orient.erase(t);
    }
    for (const Simplex& t : added) {
      tri.add_tet(t);
      if (is_finite(t)) {
        int s = orientation_sign_plus(t);
        if (s == 0) {
          std::ostringstream os;
          os << "cells " << t << " stay coplanar but form a Delaunay tetrahedron";
          throw GeometryError(os.str());
        }
        orient[t] = s;
      }
    }
    for (const Simplex& f : touched_faces) {
      if (f.size() == 1)
        continue;
      bool present = !tri.tets_containing(f).empty();
      auto it = faces.find(f);
      if (!present && it != faces.end()) {
        kill_cert(it->second.cert);
        faces.erase(it);
      } else if (present && it == faces.end()) {
        if (f.size() == 2 && slab + 1 < traj.frames())
          check_collision(f);
        Face& face = faces[f];
        face.is_short = compute_short(f);
      }
    }
    // Frontier membership of every surviving touched simplex: their cofaces changed (MATH.md 4.4,
    // "after any change of Del"). Cofaces of new simplices are new, hence touched as well.
    for (const Simplex& f : touched_faces)
      if (f.size() > 1 && faces.count(f))
        update_frontier(f);
    for (const Simplex& f : touched_facets)
      install_facet(f);
  }

  bool is_short(const Simplex& s) const {
    if (s.size() == 1)
      return true;
    auto it = faces.find(s);
    return it != faces.end() && it->second.is_short;
  }

  // The (k+1)-cofaces of a finite simplex in Del (finite ones only).
  std::vector<Simplex> cofaces(const Simplex& s) const {
    std::set<Simplex> result;
    for (const Simplex& t : tri.tets_containing(s)) {
      if (!is_finite(t))
        continue;
      if (s.size() == 3) {
        result.insert(t);
        continue;
      }
      for (VertexId v : t)
        if (!s.contains(v)) {
          std::array<VertexId, 4> w{};
          std::size_t k = 0;
          for (VertexId x : s)
            w[k++] = x;
          w[k++] = v;
          result.insert(Simplex::from_range(w.begin(), w.begin() + k));
        }
    }
    return {result.begin(), result.end()};
  }

  // The frontier (MATH.md 4.4): maximal short simplices and minimal long ones.
  bool in_frontier(const Simplex& s) const {
    if (is_short(s)) {
      for (const Simplex& c : cofaces(s))
        if (is_short(c))
          return false;
      return true;
    }
    if (s.size() == 2)
      return true;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (!is_short(s.facet(i)))
        return false;
    return true;
  }

  // Creates or drops the radius certificate of s so that exactly the frontier carries one.
  void update_frontier(const Simplex& s) {
    Face& f = faces.at(s);
    bool want = in_frontier(s);
    if (want && f.cert < 0)
      install_radius(s);
    else if (!want && f.cert >= 0) {
      kill_cert(f.cert);
      f.cert = -1;
    }
  }

  int orientation_sign_plus(const Simplex& t) {
    return sign_plus_now([&](auto tag) {
      using NT = decltype(tag);
      return certificate::orientation<NT>(pt(t[0]), pt(t[1]), pt(t[2]), pt(t[3]));
    });
  }

  bool gabriel_now(const Simplex& s) {
    // Not strictly inside the smallest circumball: sign^+ of G1/G2 >= 0 (MATH.md 3.4, 4.1 Lemma 4.2).
    std::set<VertexId> link;
    for (const Simplex& t : tri.tets_containing(s))
      for (VertexId v : t)
        if (v != infinite_vertex && !s.contains(v))
          link.insert(v);
    for (VertexId x : link) {
      int g = sign_plus_now([&](auto tag) {
        using NT = decltype(tag);
        return s.size() == 2 ? certificate::gabriel_edge<NT>(pt(s[0]), pt(s[1]), pt(x))
                             : certificate::gabriel_triangle<NT>(pt(s[0]), pt(s[1]), pt(s[2]), pt(x));
      });
      if (g < 0)
        return false;
    }
    return true;
  }

  bool has_coface_in_k(const Simplex& s) {
    for (const Simplex& t : tri.tets_containing(s)) {
      if (!is_finite(t))
        continue;
      if (s.size() == 3) {
        if (in_k(t))
          return true;
        continue;
      }
      for (VertexId v : t)
        if (!s.contains(v)) {
          std::array<VertexId, 3> tv{s[0], s[1], v};
          if (in_k(Simplex::from_range(tv.begin(), tv.end())))
            return true;
        }
    }
    return false;
  }

  // Re-evaluates membership (MATH.md 4.5 "re-eval") on the touched simplices, in decreasing
  // dimension, and fills the step's entered/left lists.
  void settle_membership(const std::unordered_map<Simplex, bool, SimplexHash>& old_k, Step& step) {
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
      if (s.size() == 4)
        f.in_k = f.is_short;
      else
        f.in_k = (f.is_short && !has_coface_in_k(s) && gabriel_now(s)) || has_coface_in_k(s);
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      bool before = old_k.at(*it), after = in_k(*it);
      if (before && !after)
        step.left.push_back(*it);
      else if (!before && after)
        step.entered.push_back(*it);
    }
  }

  // ---------------------------------------------------------------- flips (MATH.md 4.5)

  void flip(const Simplex& facet, std::vector<Step>& steps) {
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
        rebuild_static(old_k);
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

  void resolve_delaunay(std::vector<Step>& steps) {
    std::size_t guard = 0;
    const std::size_t limit = 20 * traj.cells.size() + 1000;
    while (!pending_delaunay.empty()) {
      auto [facet, id] = *pending_delaunay.begin();
      pending_delaunay.erase(pending_delaunay.begin());
      if (!certs[static_cast<std::size_t>(id)].alive || certs[static_cast<std::size_t>(id)].key != facet)
        continue;
      if (++guard > limit) {
        std::ostringstream os;
        os << "no progress resolving degenerate Delaunay events in slab " << slab << " at u ~ "
           << now.approx();
        throw InternalError(os.str());
      }
      flip(facet, steps);
    }
  }

  // Radius events: toggle shortness of the failed certificates, then one settle step.
  void resolve_radius(Step& settle, std::unordered_map<Simplex, bool, SimplexHash>& old_k) {
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

  // ---------------------------------------------------------------- frames, insertions, deletions

  void set_slab_motion(std::size_t k) {
    slab = k;
    for (std::size_t i = 0; i < traj.cells.size(); ++i) {
      const Trajectory& c = traj.cells[i];
      if (!c.present(k))
        continue;
      MovingPoint& m = motion[i];
      const GridPoint& x = c.at(k);
      m.a = {x[0], x[1], x[2]};
      if (k + 1 < traj.frames() && c.present(k + 1)) {
        const GridPoint& y = c.at(k + 1);
        m.b = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
      } else {
        m.b = {0, 0, 0}; // ending at this frame: velocity 0 for this instant (MATH.md 5.6)
      }
    }
  }

  detail::StaticInput static_input(const std::vector<VertexId>& ids) const {
    detail::StaticInput in;
    for (VertexId v : ids) {
      in.ids.push_back(v);
      in.motion.push_back(pt(v));
    }
    return in;
  }

  std::vector<VertexId> alive_ids() const {
    std::vector<VertexId> ids;
    for (std::size_t i = 0; i < alive.size(); ++i)
      if (alive[i])
        ids.push_back(static_cast<VertexId>(i));
    return ids;
  }

  void check_collisions_at_frame(std::size_t k) const {
    std::vector<std::pair<GridPoint, std::size_t>> pos;
    for (std::size_t i = 0; i < traj.cells.size(); ++i)
      if (traj.cells[i].present(k))
        pos.emplace_back(traj.cells[i].at(k), i);
    std::sort(pos.begin(), pos.end());
    for (std::size_t i = 1; i < pos.size(); ++i)
      if (pos[i].first == pos[i - 1].first)
        throw GeometryError("cells " + std::to_string(traj.cells[pos[i - 1].second].cell_id) + " and " +
                            std::to_string(traj.cells[pos[i].second].cell_id) +
                            " are at the same position at frame " + std::to_string(k) + " (time " +
                            std::to_string(traj.frame_times[k]) + ")");
  }

  // Collision inside the slab (MATH.md 2.5): p_i(u) = p_j(u) for some u in (now, 1). Tested on the
  // Delaunay edges at the slab start and on every edge when it is created: colliding cells are
  // joined by a Delaunay edge just before they meet.
  void check_collision(const Simplex& e) const {
    const MovingPoint &p = pt(e[0]), &q = pt(e[1]);
    bool has = true, fixed = false;
    mpq_class root(-1);
    for (int i = 0; i < 3 && has; ++i) {
      std::int64_t da = p.a[i] - q.a[i], db = p.b[i] - q.b[i];
      if (db == 0) {
        has = da == 0;
        continue;
      }
      mpq_class r(mpz_class(-da), mpz_class(db));
      r.canonicalize();
      if (!fixed) {
        root = r;
        fixed = true;
      } else if (root != r) {
        has = false;
      }
    }
    if (!has || !fixed || root <= 0 || root >= 1 || !(now < SlabTime(Rational(root.get_mpq_t()))))
      return;
    double t = double(traj.frame_times[slab]) +
               root.get_d() * double(traj.frame_times[slab + 1] - traj.frame_times[slab]);
    throw GeometryError("cells " + std::to_string(traj.cells[static_cast<std::size_t>(e[0])].cell_id) +
                        " and " + std::to_string(traj.cells[static_cast<std::size_t>(e[1])].cell_id) +
                        " collide at time " + std::to_string(t));
  }

  void check_collisions_in_slab() const {
    for (const auto& kv : faces)
      if (kv.first.size() == 2)
        check_collision(kv.first);
  }

  // Rebuilds Del of the current vertex set at now+ with CGAL and replaces the differing tetrahedra.
  void rebuild_static(std::unordered_map<Simplex, bool, SimplexHash>& old_k) {
    ++stats.static_rebuilds;
    std::vector<VertexId> ids = alive_ids();
    int dimension = 0;
    std::vector<Simplex> tets =
        now.is_rational() ? detail::delaunay_just_after(static_input(ids), now.rational(), dimension)
                          : detail::delaunay_at(static_input(ids), rational_before_next_event(), dimension);
    if (dimension < 3) {
      if (ids.size() < 4)
        throw GeometryError("fewer than 4 cells are present at frame " + std::to_string(slab) +
                            ": the 3D alpha complex needs at least 4");
      throw GeometryError("all cells lie in one plane at frame " + std::to_string(slab) +
                          " (a 2D run given as 3D data?): the 3D method needs cells spanning space");
    }
    std::unordered_set<Simplex, SimplexHash> target(tets.begin(), tets.end());
    std::vector<Simplex> removed, added;
    for (const Simplex& t : tri.tets())
      if (!target.count(t))
        removed.push_back(t);
    for (const Simplex& t : tets)
      if (!tri.has_tet(t))
        added.push_back(t);
    change_tets(removed, added, old_k);
  }

  // A rational q in (now, next event) (or (now, 1) without one): Del at q is Del(now+) except where a
  // certificate fails in (now, q], and those failures are found at now+ and flipped by the caller
  // (static repair at an algebraic time, MATH.md 5.4).
  Rational rational_before_next_event() const {
    SlabTime upper(Rational(1));
    for (auto copy = queue; !copy.empty(); copy.pop()) {
      const QueueEntry& e = copy.top();
      const Certificate& c = certs[e.cert];
      if (c.alive && c.version == e.version && now < e.u) {
        upper = e.u;
        break;
      }
    }
    return rational_between(now, upper);
  }

  // ---------------------------------------------------------------- the run

  EventTime event_time(bool at_frame) const {
    EventTime e;
    e.batch = batch_index;
    e.slab = slab;
    e.u = now.approx();
    double t0 = double(traj.frame_times[slab]);
    double t1 = slab + 1 < traj.frames() ? double(traj.frame_times[slab + 1]) : t0;
    e.time = t0 + e.u * (t1 - t0);
    e.at_frame = at_frame;
    return e;
  }

  void reinstall_all() {
    while (!queue.empty())
      queue.pop();
    root_cache.clear();
    std::vector<Simplex> fs;
    for (const auto& kv : tri.facets())
      fs.push_back(kv.first);
    for (const Simplex& f : fs)
      install_facet(f);
    std::vector<Simplex> rs;
    for (const auto& kv : faces)
      if (kv.second.cert >= 0)
        rs.push_back(kv.first);
    for (const Simplex& s : rs)
      install_radius(s);
  }

  std::vector<Simplex> current_complex() const {
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

  void initialise(Observer& observer) {
    check_collisions_at_frame(0);
    set_slab_motion(0);
    now = SlabTime();
    for (std::size_t i = 0; i < traj.cells.size(); ++i)
      alive[i] = traj.cells[i].present(0) && traj.cells[i].first_frame == 0;
    std::unordered_map<Simplex, bool, SimplexHash> old_k;
    rebuild_static(old_k);
    std::vector<Step> ignored;
    resolve_delaunay(ignored); // Del(t0+) (MATH.md 5.5): fix what the frozen delta left
    pending_radius.clear();
    // Membership of every simplex, in decreasing dimension (MATH.md 4.6).
    std::unordered_map<Simplex, bool, SimplexHash> all;
    for (const auto& kv : faces)
      all.emplace(kv.first, false);
    Step step;
    settle_membership(all, step);
    check_collisions_in_slab();
    observer.initial(event_time(true), current_complex());
    if (options.audit)
      audit();
  }

  void emit_batch(Observer& observer, std::vector<Step>& steps, bool at_frame) {
    std::vector<Step> kept;
    for (Step& s : steps)
      if (s.kind != StepKind::settle || !s.entered.empty() || !s.left.empty())
        kept.push_back(std::move(s));
    if (kept.empty())
      return;
    ++batch_index;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      kept[i].rank = i + 1;
      auto by_dim = [](const Simplex& a, const Simplex& b) { return a < b; };
      std::sort(kept[i].entered.begin(), kept[i].entered.end(), by_dim);
      std::sort(kept[i].left.begin(), kept[i].left.end(), by_dim);
    }
    ++stats.batches;
    if (at_frame)
      ++stats.frame_batches;
    observer.batch(event_time(at_frame), kept);
  }

  // Processes the batch at `now`: Delaunay failures first (canonical order), then radius events,
  // then the final re-evaluation (MATH.md 5.2).
  void process_batch(std::vector<Step>& steps) {
    resolve_delaunay(steps);
    std::unordered_map<Simplex, bool, SimplexHash> old_k;
    Step settle;
    settle.kind = StepKind::settle;
    while (!pending_radius.empty()) {
      resolve_radius(settle, old_k);
      resolve_delaunay(steps);
    }
    // The closure: faces of cofaces matter only through the faces themselves, which old_k holds.
    settle_membership(old_k, settle);
    steps.push_back(std::move(settle));
  }

  void run_slab(Observer& observer) {
    while (!queue.empty()) {
      QueueEntry top = queue.top();
      queue.pop();
      const Certificate& c = certs[top.cert];
      if (!c.alive || c.version != top.version)
        continue;
      now = top.u;
      now.tighten();
      mark_invalid(static_cast<int>(top.cert));
      while (!queue.empty() && compare(queue.top().u, now) == 0) {
        QueueEntry e = queue.top();
        queue.pop();
        const Certificate& ce = certs[e.cert];
        if (ce.alive && ce.version == e.version)
          mark_invalid(static_cast<int>(e.cert));
      }
      std::vector<Step> steps;
      process_batch(steps);
      emit_batch(observer, steps, false);
      if (options.audit && ++batches_since_audit >= options.audit_stride) {
        batches_since_audit = 0;
        audit();
      }
    }
  }

  void frame(Observer& observer, std::size_t k) {
    // Slab k-1 ended at t_k; switch to slab k and rebuild every certificate (MATH.md 2.3, 5.6).
    // At t_0 the structure was just built (initialise); only cells present at t_0 alone are deleted.
    std::vector<Step> steps;
    if (k > 0) {
      check_collisions_at_frame(k);
      set_slab_motion(k);
      now = SlabTime();
      reinstall_all();
      resolve_delaunay(steps);
    }
    // Insertions, then deletions, one rank each in increasing cell id (MATH.md 5.6).
    std::vector<std::pair<std::int64_t, VertexId>> born, dying;
    for (std::size_t i = 0; i < traj.cells.size(); ++i) {
      const Trajectory& c = traj.cells[i];
      if (c.first_frame == k && k > 0)
        born.emplace_back(c.cell_id, static_cast<VertexId>(i));
      if (c.last_frame() == k && k + 1 < traj.frames() && alive[i])
        dying.emplace_back(c.cell_id, static_cast<VertexId>(i));
    }
    std::sort(born.begin(), born.end());
    std::sort(dying.begin(), dying.end());
    for (const auto& cell_vertex : born)
      insert_or_delete(cell_vertex.second, true, steps);
    for (const auto& cell_vertex : dying)
      insert_or_delete(cell_vertex.second, false, steps);
    process_batch(steps); // radius events at the frame, then the final re-evaluation (MATH.md 5.6 step 5)
    check_collisions_in_slab();
    emit_batch(observer, steps, true);
    if (k > 0)
      observer.frame(k, event_time(true));
    if (options.audit)
      audit();
  }

  // One insertion or deletion of vertex v at the current frame, as its own rank (MATH.md 5.6), with
  // the Delaunay changes made by a static rebuild and the membership re-evaluated around them.
  void insert_or_delete(VertexId v, bool insert, std::vector<Step>& steps) {
    Step step;
    step.kind = insert ? StepKind::insertion : StepKind::deletion;
    step.vertex = v;
    std::unordered_map<Simplex, bool, SimplexHash> old_k;
    old_k.emplace(Simplex{v}, !insert);
    alive[static_cast<std::size_t>(v)] = insert ? 1 : 0;
    record_tet_changes(step, old_k);
    settle_membership(old_k, step);
    step.rank = steps.size() + 1;
    steps.push_back(std::move(step));
    ++(insert ? stats.insertions : stats.deletions);
    resolve_delaunay(steps);
  }

  void record_tet_changes(Step& step, std::unordered_map<Simplex, bool, SimplexHash>& old_k) {
    std::unordered_set<Simplex, SimplexHash> before(tri.tets().begin(), tri.tets().end());
    rebuild_static(old_k);
    for (const Simplex& t : before)
      if (is_finite(t) && !tri.has_tet(t))
        step.delaunay_removed.push_back(t);
    for (const Simplex& t : tri.tets())
      if (is_finite(t) && !before.count(t))
        step.delaunay_created.push_back(t);
  }

  void run(Observer& observer) {
    traj.validate();
    if (traj.dimension != 3)
      throw GeometryError("the run is two-dimensional: the 3D kinetic alpha complex needs a 3D run");
    auto clock = std::chrono::steady_clock::now();
    initialise(observer);
    for (std::size_t k = 0; k + 1 < traj.frames(); ++k) {
      frame(observer, k);
      run_slab(observer);
      auto t = std::chrono::steady_clock::now();
      stats.seconds_per_frame.push_back(std::chrono::duration<double>(t - clock).count());
      clock = t;
    }
    // t_end: the reported state is K(t_end-) (MATH.md conventions).
    slab = traj.frames() - 1;
    now = SlabTime();
    ++batch_index; // t_end is later than every batch: cells alive at the end die there
    observer.finish(event_time(true));
  }

  // ---------------------------------------------------------------- audit

  [[noreturn]] void audit_failure(const std::string& what) const {
    throw InternalError("audit failed in slab " + std::to_string(slab) + " after u ~ " +
                        std::to_string(now.approx()) + ": " + what);
  }

  void audit() {
    ++stats.audits;
    // A rational time strictly between now and the next event (or the slab end).
    SlabTime upper(Rational(1));
    for (auto copy = queue; !copy.empty(); copy.pop()) {
      const QueueEntry& e = copy.top();
      const Certificate& c = certs[e.cert];
      if (c.alive && c.version == e.version) {
        upper = e.u;
        break;
      }
    }
    if (!(now < upper))
      return; // the slab has no room left (event at u = 1)
    Rational q = rational_between(now, upper);
    SlabTime at(q);
    auto sign_q = [&](const ExactPoly& f) { return sign_at(f, at); };

    // Combinatorial validity: every facet has two tetrahedra; Euler characteristic of S^3 is 0.
    std::size_t nv = 1, ne = 0, nf = 0, nt = tri.tets().size();
    std::unordered_set<Simplex, SimplexHash> edges;
    for (const auto& kv : tri.facets()) {
      if (kv.second.count != 2)
        audit_failure("a facet does not have two tetrahedra");
      ++nf;
    }
    for (const Simplex& t : tri.tets())
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
          edges.insert(Simplex{t[i], t[j]});
    ne = edges.size();
    for (char a : alive)
      nv += a ? 1 : 0;
    if (nv + nf != ne + nt)
      audit_failure("the Euler characteristic of the augmented triangulation is not 0");
    // Local Delaunay, exactly, at q.
    for (const auto& kv : tri.facets()) {
      ExactPoly f = to_exact_poly(delaunay_poly<mpz_class>(kv.first));
      if (!CGAL::is_zero(f) && sign_q(f) <= 0) {
        std::ostringstream os;
        os << "facet " << kv.first << " is not locally Delaunay";
        audit_failure(os.str());
      }
      auto it = facet_cert.find(kv.first);
      if (it == facet_cert.end() || !certs[static_cast<std::size_t>(it->second)].alive)
        audit_failure("a facet has no certificate");
    }
    // Radius flags and certificates.
    mpz_class p = P, qq = Q;
    for (const auto& kv : faces) {
      ExactPoly f = to_exact_poly(radius_poly<mpz_class>(kv.first, p, qq));
      bool is_short = sign_q(f) <= 0;
      if (is_short != kv.second.is_short) {
        std::ostringstream os;
        os << "simplex " << kv.first << " has a wrong shortness flag";
        audit_failure(os.str());
      }
      // Certificates exactly on the frontier (MATH.md 4.4).
      bool certified = kv.second.cert >= 0 && certs[static_cast<std::size_t>(kv.second.cert)].alive;
      if (certified != in_frontier(kv.first)) {
        std::ostringstream os;
        os << "simplex " << kv.first
           << (certified ? " has a radius certificate outside the frontier"
                         : " is on the frontier without a radius certificate");
        audit_failure(os.str());
      }
    }
    // The alpha complex against CGAL's static Fixed_alpha_shape_3 at q.
    std::vector<Simplex> cgal_tets;
    Rational rho2(CGAL::Gmpz(P.get_mpz_t()), CGAL::Gmpz(Q.get_mpz_t()));
    std::vector<Simplex> expected =
        detail::static_alpha_complex(static_input(alive_ids()), q, rho2, cgal_tets);
    std::unordered_set<Simplex, SimplexHash> cgal_set(cgal_tets.begin(), cgal_tets.end());
    bool same_triangulation = cgal_set.size() == tri.tets().size();
    for (const Simplex& t : tri.tets())
      same_triangulation = same_triangulation && cgal_set.count(t);
    if (!same_triangulation)
      return; // a degenerate (identically cospherical) group triangulated differently (MATH.md 5.3)
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
};

template <class NT> Poly<NT> KineticAlphaComplex::Impl::cert_poly(const Certificate& c) const {
  if (c.kind == CertKind::delaunay)
    return delaunay_poly<NT>(c.key);
  Poly<NT> f = radius_poly<NT>(c.key, pick(P, Pi, NT()), pick(Q, Qi, NT()));
  // Positive while valid: -f while short, +f while long (MATH.md 3.1).
  return faces.at(c.key).is_short ? -f : f;
}

KineticAlphaComplex::KineticAlphaComplex(const Trajectories& trajectories, KineticOptions options)
    : impl_(std::make_unique<Impl>(trajectories, std::move(options))) {}

KineticAlphaComplex::~KineticAlphaComplex() = default;

void KineticAlphaComplex::run(Observer& observer) { impl_->run(observer); }

const KineticStatistics& KineticAlphaComplex::statistics() const { return impl_->stats; }

std::vector<Simplex> KineticAlphaComplex::current_complex() const { return impl_->current_complex(); }

} // namespace medusa::kinetic
