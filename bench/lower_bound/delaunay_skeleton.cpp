#include "delaunay_skeleton.h"

#include "certificate_enclosure.h"
#include "certificate_polynomials.h"
#include "collision.h"
#include "interval_filter.h"
#include "moving_point.h"
#include "root_isolation.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace medusa::bench {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Clock = std::chrono::steady_clock;
using kinetic::Interval;
using kinetic::IntervalPoly;
using kinetic::MovingPoint;
using Exact = CGAL::Simple_cartesian<CGAL::Gmpq>;

// What the skeleton does not handle (it stops there): it is a lower bound for input in general
// position, not an engine.
struct Degenerate {
  const char* what;
};
// A check against CGAL's static structures that failed (SkeletonOptions::check_frames).
struct Mismatch {
  std::string what;
};

// Cells and faces with a stamp: a queue entry is current while the cell and its neighbour across the
// entry's facet carry the stamps they had when it was made (a flip restamps every cell it rewrites).
template <class Tds = void>
struct StampedCell : CGAL::Delaunay_triangulation_cell_base_3<
                         K, CGAL::Triangulation_cell_base_3<K, CGAL::Triangulation_ds_cell_base_3<Tds>>> {
  using Base = CGAL::Delaunay_triangulation_cell_base_3<
      K, CGAL::Triangulation_cell_base_3<K, CGAL::Triangulation_ds_cell_base_3<Tds>>>;
  template <class Tds2> struct Rebind_TDS { using Other = StampedCell<Tds2>; };
  using Base::Base;
  std::uint32_t stamp = 0;
};

// The planar alpha layer's state of an edge (docs/MATH.md §4.1, §4.4): short, in the alpha complex, and its
// radius certificate's serial (0, or one of an earlier slab: none, the edge is not on the
// frontier). Both faces of an edge hold
// the same copy.
struct EdgeState {
  std::uint32_t serial = 0;
  bool is_short = false, in_k = false;
};

template <class Tds = void>
struct StampedFace : CGAL::Triangulation_face_base_2<K, CGAL::Triangulation_ds_face_base_2<Tds>> {
  using Base = CGAL::Triangulation_face_base_2<K, CGAL::Triangulation_ds_face_base_2<Tds>>;
  template <class Tds2> struct Rebind_TDS { using Other = StampedFace<Tds2>; };
  using Base::Base;
  std::uint32_t stamp = 0;
  // The alpha layer: the triangle's radius certificate (0: none) and shortness (a triangle is in the
  // alpha complex iff it is short, docs/MATH.md §4.1), and its edges', edge i opposite vertex i.
  std::uint32_t serial = 0;
  bool is_short = false;
  std::array<EdgeState, 3> edge{};
};

// The dimension-specific parts: CGAL's types, the certificate of a facet, the flip of a failed facet
// and the list of top simplices. A top simplex of CGAL is positively oriented in both dimensions, so
// the certificate of facet i of c, taken on c's vertices in order and c's mirror vertex, has one sign
// on every valid facet (Skeleton::valid_sign).
struct Space3 {
  static constexpr int dim = 3;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, StampedCell<>>;
  using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;
  using Cell = Dt::Cell_handle;
  using Point = K::Point_3;

  static Point point(const kinetic::GridPoint& p) { return {double(p[0]), double(p[1]), double(p[2])}; }
  static Point at(const MovingPoint& m, double u) {
    return {double(m.a[0]) + u * double(m.b[0]), double(m.a[1]) + u * double(m.b[1]),
            double(m.a[2]) + u * double(m.b[2])};
  }
  // Four far points whose tetrahedron holds [lo, hi]^3 in its interior.
  static std::vector<kinetic::GridPoint> corners(std::int64_t lo, std::int64_t hi) {
    const std::int64_t span = std::max<std::int64_t>(hi - lo, 1), a = lo - span, b = hi + 5 * span;
    return {{a, a, a}, {b, a, a}, {a, b, a}, {a, a, b}};
  }
  template <class F> static void for_each_facet(Dt& dt, F&& f) {
    for (auto it = dt.tds().facets_begin(); it != dt.tds().facets_end(); ++it)
      f(it->first, it->second);
  }
  // From one pass in plain doubles, or (tight) in interval arithmetic, as the engine's two paths.
  template <class Pt> static IntervalPoly certificate(const Dt& dt, Cell c, int i, Pt&& pt, bool tight) {
    const auto q = dt.tds().mirror_vertex(c, i);
    if (tight)
      return kinetic::certificate::in_sphere<kinetic::Interval>(pt(c->vertex(0)), pt(c->vertex(1)),
                                                                pt(c->vertex(2)), pt(c->vertex(3)), pt(q));
    return kinetic::in_sphere_enclosure(pt(c->vertex(0)), pt(c->vertex(1)), pt(c->vertex(2)),
                                        pt(c->vertex(3)), pt(q));
  }

  // The failed facet i of c at u: a 2-3 flip when the union of its two cells is convex, else a 3-2 flip
  // of the reflex edge, which three cells surround in general position (docs/MATH.md §4.5). Writes the
  // rewritten cells to `made` and returns how many; a cell the flip deletes gets stamp 0.
  template <class At, class ExactAt>
  static int flip(Dt& dt, Cell c, int i, At&& at, ExactAt&& exact_at, std::array<Cell, 3>& made,
                  bool& two_three) {
    const auto q = dt.tds().mirror_vertex(c, i);
    std::array<Point, 4> p{at(c->vertex(0)), at(c->vertex(1)), at(c->vertex(2)), at(c->vertex(3))};
    int reflex = -1, negatives = 0;
    for (int j = 0; j < 4; ++j) {
      if (j == i)
        continue;
      std::array<Point, 4> r = p;
      r[static_cast<std::size_t>(j)] = at(q);
      CGAL::Orientation o = CGAL::orientation(r[0], r[1], r[2], r[3]);
      if (o == CGAL::COPLANAR) {
        // The points at u rounded to doubles are coplanar: decide on the exact points at u.
        std::array<Exact::Point_3, 4> x;
        for (int m = 0; m < 4; ++m)
          x[static_cast<std::size_t>(m)] = exact_at(m == j ? q : c->vertex(m));
        o = CGAL::orientation(x[0], x[1], x[2], x[3]);
        if (o == CGAL::COPLANAR)
          throw Degenerate{"four points coplanar at an event"};
      }
      if (o == CGAL::NEGATIVE) {
        reflex = j;
        ++negatives;
      }
    }
    if (negatives == 0) {
      const Cell d = c->neighbor(i);
      const int i2 = (i + 2) & 3;
      dt.tds().flip_flippable(c, i);
      made = {c, d, c->neighbor(i2)}; // flip_really: c and d rewritten, the new cell at c's i2
      two_three = true;
      return 3;
    }
    if (negatives != 1)
      throw Degenerate{"a failed facet with two reflex edges"};
    // The edge of the facet opposite the reflex vertex: the two indices other than i and reflex.
    int k = -1, l = -1;
    for (int j = 0; j < 4; ++j)
      if (j != i && j != reflex)
        (k < 0 ? k : l) = j;
    // The cells around the edge, checked as we go: index() on a cell without the vertex is undefined.
    const auto indices = [&](Cell x, int& a, int& b) {
      if (!x->has_vertex(c->vertex(k), a) || !x->has_vertex(c->vertex(l), b))
        throw Degenerate{"a triangulation no longer consistent around a reflex edge"};
    };
    const Cell c1 = c->neighbor(Tds::next_around_edge(k, l));
    int k1 = -1, l1 = -1, k2 = -1, l2 = -1;
    indices(c1, k1, l1);
    const Cell c2 = c1->neighbor(Tds::next_around_edge(k1, l1));
    indices(c2, k2, l2);
    if (c2->neighbor(Tds::next_around_edge(k2, l2)) != c)
      throw Degenerate{"a failed facet whose reflex edge has more than three cells"};
    c->stamp = 0;
    dt.tds().flip_flippable(c, k, l);
    made = {c1, c2, Cell()};
    two_three = false;
    return 2;
  }

  static std::vector<std::array<int, 4>> cells(const Dt& dt) {
    std::vector<std::array<int, 4>> out;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
      std::array<int, 4> v{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
                           c->vertex(3)->info()};
      std::sort(v.begin(), v.end());
      out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  static auto cells_begin(Dt& dt) { return dt.tds().cells_begin(); }
  static auto cells_end(Dt& dt) { return dt.tds().cells_end(); }
};

struct Space2 {
  static constexpr int dim = 2;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, StampedFace<>>;
  using Dt = CGAL::Delaunay_triangulation_2<K, Tds>;
  using Cell = Dt::Face_handle;
  using Point = K::Point_2;

  static Point point(const kinetic::GridPoint& p) { return {double(p[0]), double(p[1])}; }
  static Point at(const MovingPoint& m, double u) {
    return {double(m.a[0]) + u * double(m.b[0]), double(m.a[1]) + u * double(m.b[1])};
  }
  // Three far points whose triangle holds [lo, hi]^2 in its interior.
  static std::vector<kinetic::GridPoint> corners(std::int64_t lo, std::int64_t hi) {
    const std::int64_t span = std::max<std::int64_t>(hi - lo, 1), a = lo - span, b = hi + 3 * span;
    return {{a, a, 0}, {b, a, 0}, {a, b, 0}};
  }
  template <class F> static void for_each_facet(Dt& dt, F&& f) {
    for (auto it = dt.tds().edges_begin(); it != dt.tds().edges_end(); ++it)
      f(it->first, it->second);
  }
  template <class Pt> static IntervalPoly certificate(const Dt& dt, Cell c, int i, Pt&& pt, bool tight) {
    const auto q = dt.tds().mirror_vertex(c, i);
    if (tight)
      return kinetic::certificate::in_circle<kinetic::Interval>(pt(c->vertex(0)), pt(c->vertex(1)),
                                                                pt(c->vertex(2)), pt(q));
    return kinetic::in_circle_enclosure(pt(c->vertex(0)), pt(c->vertex(1)), pt(c->vertex(2)), pt(q));
  }
  // A failed edge is flipped when pq crosses it (four cocircular points in convex position).
  template <class At, class ExactAt>
  static int flip(Dt& dt, Cell c, int i, At&& at, ExactAt&&, std::array<Cell, 3>& made, bool& two_three) {
    const Point p = at(c->vertex(i)), q = at(dt.tds().mirror_vertex(c, i));
    const Point a = at(c->vertex(Dt::cw(i))), b = at(c->vertex(Dt::ccw(i)));
    if (CGAL::orientation(p, q, a) == CGAL::orientation(p, q, b) ||
        CGAL::orientation(a, b, p) == CGAL::orientation(a, b, q))
      throw Degenerate{"a failed edge whose quadrilateral is not strictly convex"};
    const Cell d = c->neighbor(i);
    dt.tds().flip(c, i);
    made = {c, d, Cell()};
    two_three = true;
    return 2;
  }
  static std::vector<std::array<int, 4>> cells(const Dt& dt) {
    std::vector<std::array<int, 4>> out;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      std::array<int, 4> v{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info(), -1};
      std::sort(v.begin(), v.end());
      out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  static auto cells_begin(Dt& dt) { return dt.tds().faces_begin(); }
  static auto cells_end(Dt& dt) { return dt.tds().faces_end(); }
};

template <class Space> class Skeleton {
  using Dt = typename Space::Dt;
  using Cell = typename Space::Cell;
  using Vertex = typename Dt::Vertex_handle;

  // What a queue entry certifies: a facet's in-sphere, or (the planar alpha layer) an edge's or a
  // triangle's radius.
  enum class Kind : std::uint8_t { delaunay, edge_radius, triangle_radius };

  struct Entry {
    double lo, hi; // the failure time lies in (lo, hi)
    Cell cell;
    std::uint32_t stamp, neighbour_stamp; // a radius entry: its certificate's serial in `stamp`
    int facet;
    Kind kind = Kind::delaunay;
    Vertex a{}, b{}; // an edge radius entry: the edge's ends (a flip may move the edge to other faces)
  };
  struct LaterFirst {
    bool operator()(const Entry& a, const Entry& b) const { return a.lo > b.lo; }
  };

public:
  Skeleton(const kinetic::Trajectories& t, const SkeletonOptions& options)
      : t_(t), n_(static_cast<int>(t.cells.size())), alpha_(options.rho2 != nullptr && Space::dim == 2),
        check_frames_(options.check_frames) {
    const kinetic::SquaredRadius* rho2 = options.rho2;
    std::int64_t lo = 0, hi = 0;
    for (const auto& c : t.cells)
      for (const auto& p : c.positions)
        for (int d = 0; d < Space::dim; ++d) {
          lo = std::min(lo, p[static_cast<std::size_t>(d)]);
          hi = std::max(hi, p[static_cast<std::size_t>(d)]);
        }
    if (alpha_) {
      // The corners must stay farther than 2 rho from every cell (alpha layer, below).
      const auto pad =
          static_cast<std::int64_t>(std::ceil(2.0 * std::sqrt(rho2->num.get_d() / rho2->den.get_d()))) + 1;
      lo -= pad;
      hi += pad;
    }
    corners_ = Space::corners(lo, hi);
    motion_.resize(static_cast<std::size_t>(n_) + corners_.size());
    for (std::size_t i = 0; i < corners_.size(); ++i)
      motion_[static_cast<std::size_t>(n_) + i].a = corners_[i];
    if (alpha_) {
      rho2_ = *rho2;
      P_ = Interval(CGAL::to_interval(CGAL::Gmpz(rho2->num.get_mpz_t())));
      Q_ = Interval(CGAL::to_interval(CGAL::Gmpz(rho2->den.get_mpz_t())));
    }
    run_.alpha = alpha_;
  }

  SkeletonRun run() {
    SkeletonRun& r = run_;
    try {
      slabs(r);
    } catch (const Degenerate& d) {
      r.verdict = std::string("stopped: ") + d.what + " (the skeleton handles general position only)";
      return r;
    } catch (const Mismatch& m) {
      r.verdict = m.what;
      return r;
    }
    r.completed = true;
    try {
      check_frame(t_.frames() - 1); // the last frame: what --check-skeleton checks at every frame
      r.verified = true;
      r.alpha_verified = alpha_;
    } catch (const Mismatch& m) {
      r.verdict = m.what;
    }
    return r;
  }

private:
  void slabs(SkeletonRun& r) {
    dt_ = triangulate(0);
    set_motion(0);
    valid_sign_ = valid_sign();
    for (auto c = Space::cells_begin(dt_); c != Space::cells_end(dt_); ++c)
      c->stamp = ++next_stamp_;
    if constexpr (Space::dim == 2)
      if (alpha_)
        alpha_initialise(); // with the triangulation at frame 0: not part of any slab
    for (std::size_t k = 0; k + 1 < t_.frames(); ++k) {
      if (check_frames_ && k > 0)
        check_frame(k); // untimed
      const auto start = Clock::now();
      set_motion(k);
      heap_.clear();
      {
        CGAL::Protect_FPU_rounding<true> guard;
        Space::for_each_facet(dt_, [&](Cell c, int i) { install(c, i, 0.0); });
        if constexpr (Space::dim == 2)
          if (alpha_)
            alpha_frame();
      }
      const auto rebuilt = Clock::now();
      run_slab();
      r.rebuild_seconds += std::chrono::duration<double>(rebuilt - start).count();
      r.slab_seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
  }

  // At frame k, before its rebuild (or at the end of the run): the triangulation equals CGAL's static
  // one, and in the plane the alpha layer's state is what docs/MATH.md §4 defines there: the alpha complex
  // equals CGAL's exact Alpha_shape_2, every edge's shortness is the exact one, and exactly the frontier
  // simplices hold a certificate of the slab just ended.
  void check_frame(std::size_t k) const {
    const std::string at = " at frame " + std::to_string(k);
    if (Space::cells(dt_) != Space::cells(triangulate(k)))
      throw Mismatch{"its triangulation differs from CGAL's static one" + at};
    if constexpr (Space::dim == 2) {
      if (!alpha_)
        return;
      if (alpha_complex() != static_alpha_complex(k))
        throw Mismatch{"its alpha complex differs from CGAL's exact Alpha_shape_2" + at};
      for (auto f = dt_.tds().faces_begin(); f != dt_.tds().faces_end(); ++f)
        if (face_on_frontier(f) != certified(f->serial))
          throw Mismatch{"a triangle's certificate and its place on the frontier disagree" + at};
      for (auto e = dt_.tds().edges_begin(); e != dt_.tds().edges_end(); ++e) {
        const Cell f = e->first;
        const int i = e->second;
        if (!real_edge(f, i))
          continue;
        const auto& p = t_.cells[static_cast<std::size_t>(f->vertex(Dt::cw(i))->info())].at(k);
        const auto& q = t_.cells[static_cast<std::size_t>(f->vertex(Dt::ccw(i))->info())].at(k);
        mpz_class d2 = 0;
        for (int c = 0; c < 2; ++c) {
          const mpz_class d(std::to_string(p[static_cast<std::size_t>(c)] - q[static_cast<std::size_t>(c)]));
          d2 += d * d;
        }
        const EdgeState& st = f->edge[static_cast<std::size_t>(i)];
        if (st.is_short != (rho2_.den * d2 <= 4 * rho2_.num))
          throw Mismatch{"an edge's shortness differs from the exact one" + at};
        if (edge_on_frontier(f, i) != certified(st.serial))
          throw Mismatch{"an edge's certificate and its place on the frontier disagree" + at};
      }
    }
  }

  Dt triangulate(std::size_t k) const {
    std::vector<std::pair<typename Space::Point, int>> pts;
    for (int i = 0; i < n_; ++i)
      pts.emplace_back(Space::point(t_.cells[static_cast<std::size_t>(i)].at(k)), i);
    for (std::size_t i = 0; i < corners_.size(); ++i)
      pts.emplace_back(Space::point(corners_[i]), n_ + static_cast<int>(i));
    // CGAL's spatial sort shuffles with its default generator, so the cells' vertex order, hence
    // the rounding of every certificate, would depend on what ran before in the process: seeded here,
    // the skeleton does the same arithmetic in every run.
    const CGAL::Random saved = CGAL::get_default_random();
    CGAL::get_default_random() = CGAL::Random(20261126);
    Dt dt(pts.begin(), pts.end());
    CGAL::get_default_random() = saved;
    return dt;
  }

  void set_motion(std::size_t k) {
    for (int i = 0; i < n_; ++i) {
      const auto& c = t_.cells[static_cast<std::size_t>(i)];
      MovingPoint& m = motion_[static_cast<std::size_t>(i)];
      for (std::size_t d = 0; d < 3; ++d) {
        m.a[d] = c.at(k)[d];
        m.b[d] = c.at(k + 1)[d] - c.at(k)[d];
      }
    }
  }

  // A cell's position at u exactly (u is a dyadic rational).
  static Exact::Point_3 exact_at(const MovingPoint& m, double u) {
    const CGAL::Gmpq x(u);
    return {CGAL::Gmpq(double(m.a[0])) + x * CGAL::Gmpq(double(m.b[0])),
            CGAL::Gmpq(double(m.a[1])) + x * CGAL::Gmpq(double(m.b[1])),
            CGAL::Gmpq(double(m.a[2])) + x * CGAL::Gmpq(double(m.b[2]))};
  }

  const MovingPoint& pt(Vertex v) const { return motion_[static_cast<std::size_t>(v->info())]; }

  // The sign of the certificate on valid facets: read off the first facet whose value at t0 is
  // certified.
  int valid_sign() {
    CGAL::Protect_FPU_rounding<true> guard;
    int sign = 0;
    Space::for_each_facet(dt_, [&](Cell c, int i) {
      if (sign == 0 && !dt_.is_infinite(c) && !dt_.is_infinite(c->neighbor(i)))
        sign = kinetic::certified_sign(kinetic::value_at_point(
            Space::certificate(
                dt_, c, i, [this](Vertex v) -> const MovingPoint& { return pt(v); }, true),
            0.0));
    });
    return sign < 0 ? -1 : 1;
  }

  // The sign of f over [start, 1] or its first change there: the engine's filters in its order, the
  // dominance and depth-0 Bernstein test (bernstein_sign_subdivided) before the Bernstein-Descartes
  // search.
  static kinetic::FirstSignChange settle(const IntervalPoly& f, double start) {
    const int sign = kinetic::bernstein_sign_subdivided(f, start, 0);
    if (sign != 0) {
      kinetic::FirstSignChange none;
      none.status = kinetic::FirstSignChange::Status::none;
      none.sign = sign;
      return none;
    }
    return kinetic::first_sign_change(f, start, 12);
  }

  // settle on f, the enclosure from plain doubles; where that leaves the sign open, on the tighter
  // enclosure `tight()` returns (interval arithmetic, as the engine's second path), which replaces f.
  // Stops the skeleton when neither decides.
  template <class Tight>
  kinetic::FirstSignChange settle_or_tighten(IntervalPoly& f, double start, Tight&& tight, const char* why) {
    kinetic::FirstSignChange next = settle(f, start);
    if (next.status == kinetic::FirstSignChange::Status::undecided) {
      f = tight();
      next = settle(f, start);
    }
    if (next.status == kinetic::FirstSignChange::Status::undecided)
      throw Degenerate{why};
    return next;
  }

  // Narrowed to 2^-24 when scheduled, as the engine does: most pairs of queued times then separate
  // without refinement. (Narrowing lazily, when an entry reaches the top, saves nothing: a time
  // reaches the top by the left end of its isolating piece, long before it would fire.)
  void schedule(const IntervalPoly& f, const kinetic::FirstSignChange& next, Entry e) {
    e.lo = next.lo;
    e.hi = next.hi;
    kinetic::narrow_root(f, e.lo, e.hi, next.sign, 0x1p-24);
    push(e);
  }

  // The certificate of facet i of c, valid at `start`: settled when it keeps its sign on [start, 1],
  // or its first failure isolated and queued. `known`: its polynomial, when the caller has it. The
  // certificate arithmetic runs rounding upwards: the caller sets the mode once for a frame or an
  // event, as an engine would (CGAL's predicates in flip() need it to nearest).
  void install(Cell c, int i, double start, const IntervalPoly* known = nullptr) {
    const Cell d = c->neighbor(i);
    if (dt_.is_infinite(c) || dt_.is_infinite(d))
      return; // a facet of the far simplex's hull: it never fails
    ++run_.certificates;
    IntervalPoly f = known ? *known : certificate(c, i, false);
    const kinetic::FirstSignChange next = settle_or_tighten(
        f, start,
        [&] {
          if (known)
            return *known; // the failed certificate's own polynomial: nothing tighter to build
          ++run_.tight;
          return certificate(c, i, true);
        },
        "a certificate doubles cannot settle (vanishing at its start, or a multiple root)");
    if (next.sign < 0) {
      push({start, start, c, c->stamp, d->stamp, i});
    } else if (next.status == kinetic::FirstSignChange::Status::root) {
      ++run_.isolated;
      schedule(f, next, {0, 0, c, c->stamp, d->stamp, i});
    }
  }

  void push(const Entry& e) {
    heap_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end(), LaterFirst{});
  }

  IntervalPoly certificate(Cell c, int i, bool tight) const {
    IntervalPoly f = Space::certificate(
        dt_, c, i, [this](Vertex v) -> const MovingPoint& { return pt(v); }, tight);
    return valid_sign_ < 0 ? -f : f;
  }

  bool current(const Entry& e) const {
    return e.cell->stamp == e.stamp && e.cell->neighbor(e.facet)->stamp == e.neighbour_stamp;
  }

  Entry pop() {
    std::pop_heap(heap_.begin(), heap_.end(), LaterFirst{});
    const Entry e = heap_.back();
    heap_.pop_back();
    return e;
  }

  void run_slab() {
    std::array<Cell, 3> made{};
    while (!heap_.empty()) {
      const Entry e = pop();
      if constexpr (Space::dim == 2)
        if (e.kind != Kind::delaunay) {
          CGAL::Protect_FPU_rounding<true> guard;
          radius_event(e);
          continue;
        }
      if (!current(e)) {
        ++run_.stale;
        continue;
      }
      // The new facets between rewritten cells have the failed facet's five points: their certificate
      // is the failed one's polynomial, negated (valid after the root, where the failed one is not;
      // the engine finds this through its root cache). It has a certified sign at e.hi, where the
      // isolation of the failure left it, and the other new facets start there too.
      IntervalPoly after;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        after = -certificate(e.cell, e.facet, false);
      }
      // Orientations just after the root: at the right end of its isolating interval.
      const double u = e.hi;
      if constexpr (Space::dim == 2)
        if (alpha_)
          before_flip(e.cell, e.facet, u);
      bool two_three = true;
      const int count = Space::flip(
          dt_, e.cell, e.facet, [&](Vertex v) { return Space::at(pt(v), u); },
          [&](Vertex v) { return exact_at(pt(v), u); }, made, two_three);
      ++(two_three ? run_.flips23 : run_.flips32);
      CGAL::Protect_FPU_rounding<true> guard;
      for (int m = 0; m < count; ++m)
        made[static_cast<std::size_t>(m)]->stamp = ++next_stamp_;
      for (int m = 0; m < count; ++m)
        for (int j = 0; j <= Space::dim; ++j) {
          const Cell c = made[static_cast<std::size_t>(m)], d = c->neighbor(j);
          // A facet between two rewritten cells once, from the cell with the lower stamp.
          const bool inner = std::find(made.begin(), made.begin() + count, d) != made.begin() + count;
          if (inner && d->stamp < c->stamp)
            continue;
          install(c, j, u, inner ? &after : nullptr);
        }
      if constexpr (Space::dim == 2)
        if (alpha_)
          after_flip(made[0], made[1], u);
    }
  }

  // ---- The planar alpha layer (docs/MATH.md §4): the fixed-radius alpha complex on the frontier rule of
  // 4.4, its radius certificates in the faces, membership through flips (Proposition 4.5 in the
  // plane: the new simplices of a 2-2 flip are in K iff its triangles are short) and radius events
  // (Lemma 4.1, Gabriel status tested at the event, never tracked: Lemma 4.3). General position
  // only, as the rest of the skeleton: a radius certificate that vanishes at an event or a frame
  // stops it. Simplices with a far corner are left out: the corners are farther than 2 rho from
  // every cell, so they change no simplex of the cells' alpha complex. All of it runs rounding
  // upwards (the callers' guards).

  bool real(Vertex v) const { return !dt_.is_infinite(v) && v->info() < n_; }
  bool real_face(Cell f) const { return real(f->vertex(0)) && real(f->vertex(1)) && real(f->vertex(2)); }
  bool real_edge(Cell f, int i) const { return real(f->vertex(Dt::cw(i))) && real(f->vertex(Dt::ccw(i))); }
  bool short_face(Cell f) const { return f->is_short; } // false on faces that are not real

  void set_edge(Cell f, int i, const EdgeState& s) {
    f->edge[static_cast<std::size_t>(i)] = s;
    const Cell g = f->neighbor(i);
    g->edge[static_cast<std::size_t>(dt_.tds().mirror_index(f, i))] = s;
  }

  // The radius polynomial of edge i of f, or of f's triangle (i < 0): negative iff short.
  IntervalPoly radius_poly(Cell f, int i, bool tight) const {
    if (i >= 0) {
      const MovingPoint &p = pt(f->vertex(Dt::cw(i))), &q = pt(f->vertex(Dt::ccw(i)));
      return tight ? kinetic::certificate::edge_radius<Interval>(p, q, P_, Q_)
                   : kinetic::edge_radius_enclosure(p, q, P_, Q_);
    }
    const MovingPoint &a = pt(f->vertex(0)), &b = pt(f->vertex(1)), &c = pt(f->vertex(2));
    return tight ? kinetic::certificate::triangle_radius<Interval>(a, b, c, P_, Q_)
                 : kinetic::triangle_radius_enclosure(a, b, c, P_, Q_);
  }

  // Shortness just after u (the event's right end): the sign of the radius polynomial there.
  bool short_at(Cell f, int i, double u, IntervalPoly& poly) const {
    poly = radius_poly(f, i, false);
    int s = kinetic::certified_sign(kinetic::value_at_point(poly, u));
    if (s == 0) {
      poly = radius_poly(f, i, true);
      s = kinetic::certified_sign(kinetic::value_at_point(poly, u));
    }
    if (s == 0)
      throw Degenerate{"a radius certificate vanishing at an event"};
    return s < 0;
  }

  // Puts a frontier simplex's radius certificate in place from `start`, with a new serial (any queued
  // entry of an earlier certificate of it goes stale). `known`: its polynomial, when the caller has it.
  void install_radius(Cell f, int i, double start, const IntervalPoly* known = nullptr) {
    ++run_.radius_certificates;
    IntervalPoly poly = known ? *known : radius_poly(f, i, false);
    const kinetic::FirstSignChange next = settle_or_tighten(
        poly, start, [&] { return radius_poly(f, i, true); }, "a radius certificate doubles cannot settle");
    const std::uint32_t serial = ++next_serial_;
    bool held_short = false;
    if (i >= 0) {
      EdgeState s = f->edge[static_cast<std::size_t>(i)];
      held_short = s.is_short;
      s.serial = serial;
      set_edge(f, i, s);
    } else {
      held_short = f->is_short;
      f->serial = serial;
    }
    Entry e{start, start, f, serial, 0, i, i >= 0 ? Kind::edge_radius : Kind::triangle_radius};
    if (i >= 0) {
      e.a = f->vertex(Dt::cw(i));
      e.b = f->vertex(Dt::ccw(i));
    }
    if ((next.sign < 0) != held_short) {
      // It has changed since the state was set: a crossing within the isolating interval of the
      // event that made it a frontier simplex (the skeleton evaluates at that interval's right end).
      // Taken now, as the engine takes a certificate invalid at its creation.
      push(e);
    } else if (next.status == kinetic::FirstSignChange::Status::root) {
      ++run_.radius_isolated;
      schedule(poly, next, e);
    }
  }

  // Serials up to epoch_ are of earlier slabs: their certificates ended at the frame, so a frame
  // need not clear them.
  bool certified(std::uint32_t serial) const { return serial > epoch_; }

  void drop_edge_certificate(Cell f, int i) {
    EdgeState s = f->edge[static_cast<std::size_t>(i)];
    if (!certified(s.serial))
      return;
    s.serial = 0;
    set_edge(f, i, s);
  }

  // docs/MATH.md §4.4: an edge is on the frontier when long, or short with no short triangle; a triangle
  // when short, or long with three short edges.
  bool edge_on_frontier(Cell f, int i) const {
    return real_edge(f, i) && (!f->edge[static_cast<std::size_t>(i)].is_short ||
                               (!short_face(f) && !short_face(f->neighbor(i))));
  }
  bool face_on_frontier(Cell f) const {
    return real_face(f) &&
           (f->is_short || (f->edge[0].is_short && f->edge[1].is_short && f->edge[2].is_short));
  }

  // Gabriel at u (Lemma 4.2): neither apex of edge i of f strictly inside the edge's diametral disc.
  bool gabriel_at(Cell f, int i, double u) const {
    const kinetic::certificate::PointAtTime p{&pt(f->vertex(Dt::cw(i))), Interval(u)},
        q{&pt(f->vertex(Dt::ccw(i))), Interval(u)};
    for (const Vertex x : {f->vertex(i), dt_.tds().mirror_vertex(f, i)}) {
      if (dt_.is_infinite(x))
        continue;
      const int s = kinetic::certified_sign(kinetic::certificate::gabriel_edge<Interval>(
          p, q, kinetic::certificate::PointAtTime{&pt(x), Interval(u)}));
      if (s == 0)
        throw Degenerate{"a point on an edge's diametral circle at an event"};
      if (s < 0)
        return false;
    }
    return true;
  }

  // The stream a medusa builder reads (docs/MATH.md §6), as an engine hands it to its observer: one record
  // per flip (its four cells) and per simplex entering or leaving K (its cells), with the event's
  // time, kept for the slab.
  void emit(Kind kind, Cell f, double u, int i = -1) {
    Record r{u, kind, {-1, -1, -1, -1}};
    if (kind == Kind::triangle_radius)
      r.v = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info(), -1};
    else if (kind == Kind::edge_radius)
      r.v = {f->vertex(Dt::cw(i))->info(), f->vertex(Dt::ccw(i))->info(), -1, -1};
    else
      r.v = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info(),
             dt_.tds().mirror_vertex(f, i)->info()};
    stream_.push_back(r);
    run_.alpha_changes += kind != Kind::delaunay;
  }

  // docs/MATH.md §2.5: the ends of edge i of f meeting inside the slab, decided in integers as libkinetic
  // decides it (meeting_in_slab). Colliding cells are joined by a Delaunay edge just before they
  // meet, so the edges at a frame and those a flip creates are all that need it.
  void check_collision(Cell f, int i) const {
    if (kinetic::meeting_in_slab(pt(f->vertex(Dt::cw(i))), pt(f->vertex(Dt::ccw(i)))))
      throw Degenerate{"two cells meet inside a slab"};
  }

  // Shortness and membership at frame 0, from the cells' positions there.
  void alpha_initialise() {
    CGAL::Protect_FPU_rounding<true> guard;
    IntervalPoly poly;
    for (auto f = dt_.tds().faces_begin(); f != dt_.tds().faces_end(); ++f) {
      f->serial = 0;
      f->is_short = real_face(f) && short_at(f, -1, 0.0, poly);
    }
    for (auto e = dt_.tds().edges_begin(); e != dt_.tds().edges_end(); ++e) {
      const Cell f = e->first;
      const int i = e->second;
      EdgeState s;
      if (real_edge(f, i)) {
        s.is_short = short_at(f, i, 0.0, poly);
        s.in_k = short_face(f) || short_face(f->neighbor(i)) || (s.is_short && gabriel_at(f, i, 0.0));
      }
      set_edge(f, i, s);
    }
  }

  // Every frontier simplex's radius certificate, at a frame (docs/MATH.md §2.3).
  void alpha_frame() {
    epoch_ = next_serial_;
    stream_.clear(); // the last slab's records, read by the observer by now
    for (auto f = dt_.tds().faces_begin(); f != dt_.tds().faces_end(); ++f)
      if (face_on_frontier(f))
        install_radius(f, -1, 0.0);
    for (auto e = dt_.tds().edges_begin(); e != dt_.tds().edges_end(); ++e) {
      if (!real_edge(e->first, e->second))
        continue;
      check_collision(e->first, e->second);
      if (edge_on_frontier(e->first, e->second))
        install_radius(e->first, e->second, 0.0);
    }
  }

  // A frontier simplex changes shortness at the entry's time (docs/MATH.md §4.4 update rules, 4.1).
  void radius_event(const Entry& e) {
    const double u = e.hi;
    if (e.kind == Kind::triangle_radius) {
      const Cell f = e.cell;
      if (f->serial != e.stamp) {
        ++run_.stale;
        return;
      }
      ++run_.radius_events;
      emit(Kind::triangle_radius, f, u); // the triangle enters or leaves K
      f->is_short = !f->is_short;
      for (int j = 0; j < 3; ++j) {
        EdgeState s = f->edge[static_cast<std::size_t>(j)];
        if (f->is_short) { // its edges have a short coface now: off the frontier, in K
          s.serial = 0;
          if (!s.in_k)
            emit(Kind::edge_radius, f, u, j);
          s.in_k = true;
          set_edge(f, j, s);
        } else { // its edges, all short, may be maximal short again, and may leave K
          const bool other = short_face(f->neighbor(j));
          const bool in_k = other || gabriel_at(f, j, u);
          if (in_k != s.in_k)
            emit(Kind::edge_radius, f, u, j);
          s.in_k = in_k;
          set_edge(f, j, s);
          if (!other)
            install_radius(f, j, u);
        }
      }
      install_radius(f, -1, u); // it stays on the frontier
      return;
    }
    Cell f;
    int i = 0;
    if (!dt_.is_edge(e.a, e.b, f, i) || f->edge[static_cast<std::size_t>(i)].serial != e.stamp) {
      ++run_.stale;
      return;
    }
    ++run_.radius_events;
    EdgeState s = f->edge[static_cast<std::size_t>(i)];
    s.is_short = !s.is_short;
    // Long before, so no short triangle: in K now iff Gabriel; leaving K when it turns long.
    const bool in_k = s.is_short && gabriel_at(f, i, u);
    if (in_k != s.in_k)
      emit(Kind::edge_radius, f, u, i);
    s.in_k = in_k;
    set_edge(f, i, s);
    for (const Cell h : {f, f->neighbor(i)}) {
      if (s.is_short && !certified(h->serial) && face_on_frontier(h))
        install_radius(h, -1, u); // three short edges: the long triangle joins the frontier
      else if (!s.is_short)
        h->serial = 0; // a long edge: its triangles have a long face, off the frontier
    }
    install_radius(f, i, u); // it stays on the frontier
  }

  // The flip of edge i of c: the simplices it removes leave K; the state of the four edges of the
  // quadrilateral is kept, to be put back in the rewritten faces.
  void before_flip(Cell c, int i, double u) {
    const Cell d = c->neighbor(i);
    emit(Kind::delaunay, c, u, i); // the flip: its quadrilateral's vertices
    if (c->edge[static_cast<std::size_t>(i)].in_k)
      emit(Kind::edge_radius, c, u, i);
    for (const Cell h : {c, d})
      if (short_face(h))
        emit(Kind::triangle_radius, h, u);
    const int di = dt_.tds().mirror_index(c, i);
    int m = 0;
    for (const auto& [f, j] : {std::pair{c, Dt::cw(i)}, std::pair{c, Dt::ccw(i)}, std::pair{d, Dt::cw(di)},
                               std::pair{d, Dt::ccw(di)}})
      quad_[static_cast<std::size_t>(m++)] = {f->vertex(Dt::cw(j)), f->vertex(Dt::ccw(j)),
                                              f->edge[static_cast<std::size_t>(j)]};
  }

  void after_flip(Cell c, Cell d, double u) {
    int new_edge = -1;
    for (int j = 0; j < 3; ++j) {
      const Vertex a = c->vertex(Dt::cw(j)), b = c->vertex(Dt::ccw(j));
      bool kept = false;
      for (const auto& q : quad_)
        if ((q.a == a && q.b == b) || (q.a == b && q.b == a)) {
          c->edge[static_cast<std::size_t>(j)] = q.state;
          kept = true;
        }
      if (!kept)
        new_edge = j;
    }
    for (int j = 0; j < 3; ++j) {
      const Vertex a = d->vertex(Dt::cw(j)), b = d->vertex(Dt::ccw(j));
      for (const auto& q : quad_)
        if ((q.a == a && q.b == b) || (q.a == b && q.b == a))
          d->edge[static_cast<std::size_t>(j)] = q.state;
    }
    // The new edge and the new triangles: shortness just after the flip; in K iff the triangles are
    // short (Proposition 4.5 in the plane). A triangle with a long edge is long (R is monotone,
    // docs/MATH.md §4.1), and off the frontier: only one with three short edges needs its radius.
    std::array<IntervalPoly, 3> poly;
    EdgeState s;
    const bool real = real_edge(c, new_edge);
    if (real) {
      s.is_short = short_at(c, new_edge, u, poly[2]);
      check_collision(c, new_edge);
    }
    set_edge(c, new_edge, s);
    for (const Cell h : {c, d}) {
      h->serial = 0;
      h->is_short = h->edge[0].is_short && h->edge[1].is_short && h->edge[2].is_short && real_face(h) &&
                    short_at(h, -1, u, poly[h == c ? 0 : 1]);
      if (h->is_short)
        emit(Kind::triangle_radius, h, u);
    }
    if (real && (short_face(c) || short_face(d))) {
      s.in_k = true;
      emit(Kind::edge_radius, c, u, new_edge);
      set_edge(c, new_edge, s);
    }
    // The frontier over the new simplices and the quadrilateral's edges (docs/MATH.md §4.4, after a change
    // of Del).
    for (const Cell h : {c, d})
      if (face_on_frontier(h))
        install_radius(h, -1, u, &poly[h == c ? 0 : 1]);
    if (edge_on_frontier(c, new_edge))
      install_radius(c, new_edge, u, &poly[2]);
    for (const Cell h : {c, d})
      for (int j = 0; j < 3; ++j) {
        if (h == c && j == new_edge)
          continue;
        if (h == d && h->neighbor(j) == c)
          continue;
        const bool on = edge_on_frontier(h, j), has = certified(h->edge[static_cast<std::size_t>(j)].serial);
        if (on && !has)
          install_radius(h, j, u);
        else if (!on && has)
          drop_edge_certificate(h, j);
      }
  }

  using Simplices = std::pair<std::vector<std::array<int, 3>>, std::vector<std::array<int, 2>>>;

  // A face's cells, or those of its edge i, as sorted indices: in the skeleton's triangulation and
  // in the oracle's alike.
  template <class Face> static std::array<int, 3> triangle_of(const Face& f) {
    std::array<int, 3> v{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(v.begin(), v.end());
    return v;
  }
  template <class Face> static std::array<int, 2> edge_of(const Face& f, int i) {
    std::array<int, 2> v{f->vertex(Dt::cw(i))->info(), f->vertex(Dt::ccw(i))->info()};
    std::sort(v.begin(), v.end());
    return v;
  }
  static Simplices sorted(Simplices s) {
    std::sort(s.first.begin(), s.first.end());
    std::sort(s.second.begin(), s.second.end());
    return s;
  }

  // The alpha complex held: its triangles and edges.
  Simplices alpha_complex() const {
    Simplices out;
    for (auto f = dt_.finite_faces_begin(); f != dt_.finite_faces_end(); ++f)
      if (f->is_short)
        out.first.push_back(triangle_of(f));
    for (auto e = dt_.finite_edges_begin(); e != dt_.finite_edges_end(); ++e)
      if (e->first->edge[static_cast<std::size_t>(e->second)].in_k)
        out.second.push_back(edge_of(e->first, e->second));
    return sorted(std::move(out));
  }

  // The oracle: CGAL's Alpha_shape_2 on the exact kernel, of the cells' positions at frame k.
  Simplices static_alpha_complex(std::size_t k) const {
    using EK = CGAL::Exact_predicates_exact_constructions_kernel;
    using Vb = CGAL::Alpha_shape_vertex_base_2<EK, CGAL::Triangulation_vertex_base_with_info_2<int, EK>>;
    using Fb = CGAL::Alpha_shape_face_base_2<EK>;
    using Edt = CGAL::Delaunay_triangulation_2<EK, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
    using Shape = CGAL::Alpha_shape_2<Edt>;
    std::vector<std::pair<EK::Point_2, int>> pts;
    for (int i = 0; i < n_; ++i) {
      const auto& p = t_.cells[static_cast<std::size_t>(i)].at(k);
      pts.emplace_back(EK::Point_2(double(p[0]), double(p[1])), i);
    }
    Edt dt(pts.begin(), pts.end());
    const EK::FT alpha(mpq_class(rho2_.num, rho2_.den)); // exact: Epeck's FT is over mpq_class
    Shape shape(dt, alpha, Shape::GENERAL);
    Simplices out;
    for (auto f = shape.finite_faces_begin(); f != shape.finite_faces_end(); ++f)
      if (shape.classify(f) != Shape::EXTERIOR)
        out.first.push_back(triangle_of(f));
    for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e)
      if (shape.classify(*e) != Shape::EXTERIOR)
        out.second.push_back(edge_of(e->first, e->second));
    return sorted(std::move(out));
  }

  struct QuadEdge {
    Vertex a, b;
    EdgeState state;
  };
  struct Record {
    double u;
    Kind kind;
    std::array<int, 4> v;
  };

  const kinetic::Trajectories& t_;
  const int n_;
  const bool alpha_;        // the planar alpha layer runs
  const bool check_frames_; // check_frame at every frame
  kinetic::SquaredRadius rho2_;
  Interval P_, Q_;
  std::vector<kinetic::GridPoint> corners_;
  std::vector<MovingPoint> motion_;
  Dt dt_;
  int valid_sign_ = 1;
  std::vector<Entry> heap_;
  std::uint32_t next_stamp_ = 0, next_serial_ = 0, epoch_ = 0;
  std::array<QuadEdge, 4> quad_{}; // the edges of the quadrilateral of the flip in progress
  std::vector<Record> stream_;     // the slab's output (emit)
  SkeletonRun run_;                // counted as the run goes
};

} // namespace

bool skeleton_applies(const kinetic::Trajectories& t, std::string& why) {
  if (t.frames() < 2) {
    why = "a single frame";
    return false;
  }
  for (const auto& c : t.cells)
    if (c.first_frame != 0 || c.positions.size() != t.frames()) {
      why = "cells are born or die";
      return false;
    }
  return true;
}

SkeletonRun run_delaunay_skeleton(const kinetic::Trajectories& t, const SkeletonOptions& options) {
  return t.dimension == 2 ? Skeleton<Space2>(t, options).run() : Skeleton<Space3>(t, options).run();
}

} // namespace medusa::bench
