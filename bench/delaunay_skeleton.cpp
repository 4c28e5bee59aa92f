#include "delaunay_skeleton.h"

#include "medusa/kinetic/certificate_enclosure.h"
#include "medusa/kinetic/certificate_polynomials.h"
#include "medusa/kinetic/interval_filter.h"
#include "medusa/kinetic/moving_point.h"
#include "medusa/kinetic/root_isolation.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

namespace medusa::bench {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Clock = std::chrono::steady_clock;
using kinetic::IntervalPoly;
using kinetic::MovingPoint;
using Exact = CGAL::Simple_cartesian<CGAL::Gmpq>;

// What the skeleton does not handle (it stops there): it is a lower bound for input in general
// position, not an engine.
struct Degenerate {
  const char* what;
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

template <class Tds = void>
struct StampedFace : CGAL::Triangulation_face_base_2<K, CGAL::Triangulation_ds_face_base_2<Tds>> {
  using Base = CGAL::Triangulation_face_base_2<K, CGAL::Triangulation_ds_face_base_2<Tds>>;
  template <class Tds2> struct Rebind_TDS { using Other = StampedFace<Tds2>; };
  using Base::Base;
  std::uint32_t stamp = 0;
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
  // of the reflex edge, which three cells surround in general position (MATH.md 4.5). Writes the
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

  struct Entry {
    double lo, hi; // the failure time lies in (lo, hi)
    Cell cell;
    std::uint32_t stamp, neighbour_stamp;
    int facet;
  };
  struct LaterFirst {
    bool operator()(const Entry& a, const Entry& b) const { return a.lo > b.lo; }
  };

public:
  explicit Skeleton(const kinetic::Trajectories& t) : t_(t), n_(static_cast<int>(t.cells.size())) {
    std::int64_t lo = 0, hi = 0;
    for (const auto& c : t.cells)
      for (const auto& p : c.positions)
        for (int d = 0; d < Space::dim; ++d) {
          lo = std::min(lo, p[static_cast<std::size_t>(d)]);
          hi = std::max(hi, p[static_cast<std::size_t>(d)]);
        }
    corners_ = Space::corners(lo, hi);
    motion_.resize(static_cast<std::size_t>(n_) + corners_.size());
    for (std::size_t i = 0; i < corners_.size(); ++i)
      motion_[static_cast<std::size_t>(n_) + i].a = corners_[i];
  }

  SkeletonRun run() {
    SkeletonRun& r = run_;
    try {
      slabs(r);
    } catch (const Degenerate& d) {
      r.verdict = std::string("stopped: ") + d.what + " (the skeleton handles general position only)";
      return r;
    }
    r.completed = true;
    r.verified = Space::cells(dt_) == Space::cells(triangulate(t_.frames() - 1));
    if (!r.verified)
      r.verdict = "its final triangulation differs from CGAL's static one";
    return r;
  }

private:
  void slabs(SkeletonRun& r) {
    dt_ = triangulate(0);
    set_motion(0);
    valid_sign_ = valid_sign();
    for (auto c = Space::cells_begin(dt_); c != Space::cells_end(dt_); ++c)
      c->stamp = ++next_stamp_;
    for (std::size_t k = 0; k + 1 < t_.frames(); ++k) {
      const auto start = Clock::now();
      set_motion(k);
      heap_.clear();
      Space::for_each_facet(dt_, [&](Cell c, int i) { install(c, i, 0.0); });
      const auto rebuilt = Clock::now();
      run_slab();
      r.rebuild_seconds += std::chrono::duration<double>(rebuilt - start).count();
      r.slab_seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
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

  // The certificate of facet i of c, valid at `start`: settled when it keeps its sign on [start, 1],
  // or its first failure isolated and queued. `known`: its polynomial, when the caller has it.
  void install(Cell c, int i, double start, const IntervalPoly* known = nullptr) {
    const Cell d = c->neighbor(i);
    if (dt_.is_infinite(c) || dt_.is_infinite(d))
      return; // a facet of the far simplex's hull: it never fails
    CGAL::Protect_FPU_rounding<true> guard;
    ++run_.certificates;
    IntervalPoly f = known ? *known : certificate(c, i, false);
    kinetic::FirstSignChange next = kinetic::first_sign_change(f, start, 12);
    if (next.status == kinetic::FirstSignChange::Status::undecided && !known) {
      ++run_.tight;
      f = certificate(c, i, true);
      next = kinetic::first_sign_change(f, start, 12);
    }
    if (next.status == kinetic::FirstSignChange::Status::undecided)
      throw Degenerate{"a certificate doubles cannot settle (vanishing at its start, or a multiple root)"};
    if (next.sign < 0) {
      push({start, start, c, c->stamp, d->stamp, i});
    } else if (next.status == kinetic::FirstSignChange::Status::root) {
      // Narrowed to 2^-24 when scheduled, as the engine does: most pairs of queued times then
      // separate without refinement. (Narrowing lazily, when an entry reaches the top, saves nothing:
      // a time reaches the top by the left end of its isolating piece, long before it would fire.)
      ++run_.isolated;
      double lo = next.lo, hi = next.hi;
      kinetic::narrow_root(f, lo, hi, next.sign, 0x1p-24);
      push({lo, hi, c, c->stamp, d->stamp, i});
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
      bool two_three = true;
      const int count = Space::flip(
          dt_, e.cell, e.facet, [&](Vertex v) { return Space::at(pt(v), u); },
          [&](Vertex v) { return exact_at(pt(v), u); }, made, two_three);
      ++(two_three ? run_.flips23 : run_.flips32);
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
    }
  }

  const kinetic::Trajectories& t_;
  const int n_;
  std::vector<kinetic::GridPoint> corners_;
  std::vector<MovingPoint> motion_;
  Dt dt_;
  int valid_sign_ = 1;
  std::vector<Entry> heap_;
  std::uint32_t next_stamp_ = 0;
  SkeletonRun run_; // counted as the run goes
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

SkeletonRun run_delaunay_skeleton(const kinetic::Trajectories& t) {
  return t.dimension == 2 ? Skeleton<Space2>(t).run() : Skeleton<Space3>(t).run();
}

} // namespace medusa::bench
