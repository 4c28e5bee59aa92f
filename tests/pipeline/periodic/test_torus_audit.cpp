// The periodic audit (docs/MATH.md §8.7): its two static constructions of the alpha complex on the
// torus checked against each other and against complexes derived on paper, and random periodic walks
// run through the engine and the canonical filter with the audit after every batch.
#include "medusa/core/error.h"
#include "medusa/kinetic/kinetic_alpha_complex.h"
#include "medusa/periodic/canonical_filter.h"
#include "medusa/periodic/periodic_cover.h"
#include "medusa/periodic/torus_alpha_complex.h"
#include "medusa/periodic/torus_audit.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

using namespace medusa;
using namespace medusa::periodic;
using kinetic::Simplex;

namespace {

io::PeriodicDomain domain(std::array<bool, 3> periodic, std::array<std::int64_t, 3> period) {
  io::PeriodicDomain d;
  d.periodic = periodic;
  for (std::size_t a = 0; a < 3; ++a)
    if (periodic[a]) {
      d.period[a] = period[a];
      d.lattice[a] = period[a];
    }
  return d;
}

kinetic::SquaredRadius squared(std::int64_t num, std::int64_t den = 1) {
  kinetic::SquaredRadius r;
  r.num = num;
  r.den = den;
  return r;
}

std::vector<TorusPoint> points(const std::vector<std::array<std::int64_t, 3>>& xs) {
  std::vector<TorusPoint> out;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    TorusPoint p;
    p.id = static_cast<kinetic::VertexId>(i);
    for (std::size_t a = 0; a < 3; ++a)
      p.position[a] = xs[i][a];
    out.push_back(p);
  }
  return out;
}

std::vector<TorusPoint> random_points(std::mt19937_64& rng, int n, int dim, std::int64_t box) {
  std::uniform_int_distribution<std::int64_t> x(-box, 2 * box); // some lifts outside the domain
  std::set<std::array<std::int64_t, 3>> used;
  std::vector<std::array<std::int64_t, 3>> xs;
  while (static_cast<int>(xs.size()) < n) {
    std::array<std::int64_t, 3> p{x(rng), x(rng), dim == 3 ? x(rng) : 0};
    std::array<std::int64_t, 3> wrapped{};
    for (std::size_t a = 0; a < 3; ++a)
      wrapped[a] = ((p[a] % box) + box) % box;
    if (used.insert(wrapped).second)
      xs.push_back(p);
  }
  return points(xs);
}

// Cells 7 at (1,5) and 9 at (9,6), still over one slab: on a band of period 10 along x they are
// sqrt 5 apart across the seam.
kinetic::Trajectories two_still_cells_on_a_band() {
  kinetic::Trajectories t;
  t.dimension = 2;
  t.scale = 1;
  t.frame_times = {0, 100};
  kinetic::Trajectory a, b;
  a.cell_id = 7;
  a.positions = {{1, 5, 0}, {1, 5, 0}};
  b.cell_id = 9;
  b.positions = {{9, 6, 0}, {9, 6, 0}};
  t.cells = {a, b};
  return t;
}

} // namespace

TEST_CASE("A ring that closes across the seam is three edges and one loop on the torus",
          "[periodic][audit]") {
  // On paper: cells at (0,0), (4,1), (8,0) on a 12 x 12 torus, rho = 2.5. The edges to the next cell
  // have lengths sqrt(17) and sqrt(17), and (8,0) to the copy (12,0) of the first has length 4: all
  // three have half-lengths below 2.5 and nothing inside their diametral circles. The triangle's
  // circumradius is far above 2.5 (its lifts are nearly collinear). So K = 3 vertices and 3 edges,
  // with b0 = b1 = 1.
  const std::vector<Simplex> expected = {Simplex{0},    Simplex{1},    Simplex{2},
                                         Simplex{0, 1}, Simplex{0, 2}, Simplex{1, 2}};
  std::vector<Simplex> sorted = expected;
  std::sort(sorted.begin(), sorted.end());
  const auto pts = points({{0, 0, 0}, {4, 1, 0}, {8, 0, 0}});
  const auto square = domain({true, true, false}, {12, 12, 0});
  const auto periodic = torus_alpha_complex(2, square, pts, squared(25, 4));
  CHECK(periodic.oracle == TorusOracle::periodic_triangulation);
  CHECK(periodic.complex == sorted);
  const auto tiled = torus_alpha_complex(2, square, pts, squared(25, 4), true);
  CHECK(tiled.oracle == TorusOracle::tiled_copies);
  CHECK(tiled.complex == sorted);
  // Periodic along x alone (a band): the same ring.
  CHECK(torus_alpha_complex(2, domain({true, false, false}, {12, 0, 0}), pts, squared(25, 4)).complex ==
        sorted);
  CHECK(betti_numbers_z2(sorted) == std::vector<std::size_t>{1, 1});
  // At rho = 1.9 every edge is too long (half-lengths sqrt(17)/2 ~ 2.06 and 2).
  CHECK(torus_alpha_complex(2, square, pts, squared(361, 100)).complex ==
        std::vector<Simplex>{Simplex{0}, Simplex{1}, Simplex{2}});
}

TEST_CASE("A tetrahedron across the corner of the cube is in the complex on the 3-torus",
          "[periodic][audit]") {
  // On paper: cells at (0,0,0), (9,0,0), (0,9,0), (0,0,9) on a 10^3 torus; their lifts (0,0,0),
  // (-1,0,0), (0,-1,0), (0,0,-1) form a tetrahedron with circumcentre (-1/2,-1/2,-1/2) and squared
  // circumradius 3/4; rho^2 = 1 takes it and all its faces. No other lift
  // is within 2 rho of it.
  const auto pts = points({{0, 0, 0}, {9, 0, 0}, {0, 9, 0}, {0, 0, 9}});
  const auto cube = domain({true, true, true}, {10, 10, 10});
  std::vector<Simplex> expected;
  const std::vector<kinetic::VertexId> all = {0, 1, 2, 3};
  for (unsigned mask = 1; mask < 16; ++mask) {
    std::vector<kinetic::VertexId> s;
    for (unsigned i = 0; i < 4; ++i)
      if (mask & (1u << i))
        s.push_back(all[i]);
    expected.push_back(Simplex::from_range(s.begin(), s.end()));
  }
  std::sort(expected.begin(), expected.end());
  CHECK(torus_alpha_complex(3, cube, pts, squared(1)).complex == expected);
  CHECK(torus_alpha_complex(3, cube, pts, squared(1), true).complex == expected);
  // rho^2 = 0.7 < 3/4: the tetrahedron is out, and so is its far triangle {1, 2, 3} (equilateral,
  // side sqrt 2, squared radius 2/3, but the corner cell lies inside its smallest sphere at squared
  // distance 1/3: attached, it enters with the tetrahedron). The three right triangles through the
  // corner cell (squared radius 1/2, the fourth cell at squared distance 3/2 from their centre) and
  // all edges stay.
  const auto smaller = torus_alpha_complex(3, cube, pts, squared(7, 10)).complex;
  CHECK(smaller.size() == expected.size() - 2);
  CHECK(std::find(smaller.begin(), smaller.end(), Simplex{0, 1, 2, 3}) == smaller.end());
  CHECK(std::find(smaller.begin(), smaller.end(), Simplex{1, 2, 3}) == smaller.end());
  CHECK(torus_alpha_complex(3, cube, pts, squared(7, 10), true).complex == smaller);
}

TEST_CASE("CGAL's periodic triangulation and the tiled copies give the same complex on the torus",
          "[periodic][audit]") {
  // Few points (CGAL keeps 27, or 9, sheets) to many (one sheet), at radii up to just below L/4.
  std::size_t above_vertices = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    std::mt19937_64 rng(seed);
    const int dim = seed % 3 == 0 ? 2 : 3;
    const int n = 2 + static_cast<int>(rng() % (dim == 3 ? 60 : 80));
    const std::int64_t box = 1000;
    const std::int64_t rho = 50 + static_cast<std::int64_t>(rng() % 199); // 4 rho < 1000
    INFO("seed " << seed << ", dimension " << dim << ", " << n << " points, rho " << rho);
    const auto pts = random_points(rng, n, dim, box);
    const auto cube = domain({true, true, dim == 3}, {box, box, dim == 3 ? box : 0});
    const auto a = torus_alpha_complex(dim, cube, pts, squared(rho * rho));
    const auto b = torus_alpha_complex(dim, cube, pts, squared(rho * rho), true);
    REQUIRE(a.oracle == TorusOracle::periodic_triangulation);
    REQUIRE(b.full_dimensional);
    CHECK(a.complex == b.complex);
    above_vertices += a.complex.size() - static_cast<std::size_t>(n);
  }
  CHECK(above_vertices > 100);
}

namespace {

// n cells walking on a torus (periodic axes of `d`; open axes clamped into [0, box]), unwrapped,
// grid units with scale 1: starts anywhere in the domain, steps up to `step` per coordinate (below
// L/2). About a tenth of the cells are born at a later frame and a tenth die early.
kinetic::Trajectories periodic_walk(std::uint64_t seed, int n, int frames, int dim, std::int64_t box,
                                    std::int64_t step) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> start(0, box - 1), d(-step, step);
  kinetic::Trajectories t;
  t.dimension = dim;
  t.scale = 1;
  for (int k = 0; k < frames; ++k)
    t.frame_times.push_back(100 * k);
  for (int i = 0; i < n; ++i) {
    kinetic::Trajectory c;
    c.cell_id = i + 1;
    c.type = 1 + i % 2;
    int first = 0, last = frames - 1;
    const auto fate = rng() % 10;
    if (fate == 0)
      first = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(frames - 2));
    else if (fate == 1)
      last = 1 + static_cast<int>(rng() % static_cast<std::uint64_t>(frames - 2));
    c.first_frame = static_cast<std::size_t>(first);
    kinetic::GridPoint p{start(rng), start(rng), dim == 3 ? start(rng) : 0};
    for (int k = first; k <= last; ++k) {
      c.positions.push_back(p);
      for (int a = 0; a < dim; ++a)
        p[static_cast<std::size_t>(a)] += d(rng);
    }
    t.cells.push_back(c);
  }
  return t;
}

// Clamps the open axes of the walk into [0, box] (a slab between two walls).
void clamp_open_axes(kinetic::Trajectories& t, const io::PeriodicDomain& d, std::int64_t box) {
  for (kinetic::Trajectory& c : t.cells)
    for (kinetic::GridPoint& p : c.positions)
      for (std::size_t a = 0; a < static_cast<std::size_t>(t.dimension); ++a)
        if (!d.periodic[a])
          p[a] = std::clamp<std::int64_t>(p[a], 0, box);
}

TorusAuditStatistics audited_walk(std::uint64_t seed, const io::PeriodicDomain& d, int dim, int n,
                                  std::int64_t rho) {
  const std::int64_t box = 1000;
  auto walk = periodic_walk(seed, n, 5, dim, box, 90);
  clamp_open_axes(walk, d, box);
  const PeriodicCover cover = cover_trajectories(walk, d, squared(rho * rho));
  kinetic::KineticOptions options;
  options.rho2 = squared(rho * rho);
  kinetic::KineticAlphaComplex engine(cover.trajectories, options);
  kinetic::Observer sink;
  TorusAudit audit(cover, d, options.rho2, dim, 1, sink);
  CanonicalFilter filter(cover, audit);
  engine.run(filter);
  // The sentinels' hull holds every cell and copy strictly inside at every time: it never changes.
  CHECK(engine.statistics().hull_flips == 0);
  return audit.statistics();
}

// Few cells keep CGAL's periodic triangulation on 27 (or 9) sheets, the slow case of the oracle:
// n stays below 26 in 3D.
void check_walks(const io::PeriodicDomain& d, int dim, std::uint64_t first_seed, int runs) {
  for (std::uint64_t seed = first_seed; seed < first_seed + static_cast<std::uint64_t>(runs); ++seed) {
    std::mt19937_64 rng(seed * 31);
    const int n = dim == 3 ? 10 + static_cast<int>(rng() % 16) : 12 + static_cast<int>(rng() % 30);
    const std::int64_t rho = 80 + static_cast<std::int64_t>(rng() % 160);
    INFO("seed " << seed << ": " << n << " cells, rho " << rho << ", periodic along " << d.axes());
    const TorusAuditStatistics s = audited_walk(seed, d, dim, n, rho);
    UNSCOPED_INFO("seed " << seed << ": " << s.checks << " audits, " << s.compared << " equal, "
                          << s.betti_only << " by Betti numbers, " << s.skipped << " skipped");
    CHECK(s.checks > 5);
    // Random integer positions on a fine grid are in general position: every audit compares the
    // complexes simplex for simplex.
    CHECK(s.compared == s.checks);
  }
}

} // namespace

TEST_CASE("Random walks on the 3-torus keep the complex of CGAL's periodic triangulation after every batch",
          "[periodic][audit]") {
  check_walks(domain({true, true, true}, {1000, 1000, 1000}), 3, 100, 3);
}

TEST_CASE(
    "Random walks in a slab periodic along x and y keep the complex of the tiled copies after every batch",
    "[periodic][audit]") {
  check_walks(domain({true, true, false}, {1000, 1000, 0}), 3, 200, 3);
}

TEST_CASE(
    "Random walks on the flat torus keep the complex of CGAL's periodic triangulation after every batch",
    "[periodic][audit]") {
  check_walks(domain({true, true, false}, {1000, 1000, 0}), 2, 300, 4);
}

TEST_CASE("A complex that is not the one on the torus fails the audit with one line naming cells",
          "[periodic][audit]") {
  // Cells at (1,5) and (9,6) on a band of period 10 along x: across the seam they are sqrt 5 apart,
  // so with rho = 1.2 the static complex holds their edge; a stream that never adds it must fail.
  const kinetic::Trajectories t = two_still_cells_on_a_band();
  const auto band = domain({true, false, false}, {10, 0, 0});
  const PeriodicCover cover = cover_trajectories(t, band, squared(144, 100));
  kinetic::Observer sink;
  TorusAudit audit(cover, band, squared(144, 100), 2, 1, sink);
  kinetic::EventTime t0;
  audit.initial(t0, {Simplex{0}, Simplex{1}});
  kinetic::EventTime end;
  end.slab = 0;
  end.u = 1.0;
  end.time = 100;
  try {
    audit.finish(end);
    FAIL("a complex without the edge across the seam passed the audit");
  } catch (const InternalError& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::Matchers::Contains("audit failed on the torus") &&
                         Catch::Matchers::Contains("1 missing (e.g. cells {7 9})"));
    CHECK(what.find('\n') == std::string::npos);
  }
}

TEST_CASE("The torus audit checks the start and then every stride-th batch of events", "[periodic][audit]") {
  // Two cells still on a band of period 10 (as above), with the edge across the seam in the complex,
  // and E = 10 batches that change nothing. The start is due; then batch i makes the complex held
  // until the next batch (or the end) due iff i is a multiple of the stride: 1 + floor(E / stride).
  const kinetic::Trajectories t = two_still_cells_on_a_band();
  const auto band = domain({true, false, false}, {10, 0, 0});
  const PeriodicCover cover = cover_trajectories(t, band, squared(144, 100));
  const std::size_t batches = 10;
  for (const std::size_t stride : {1, 3, 4, 11}) {
    CAPTURE(stride);
    kinetic::Observer sink;
    TorusAudit audit(cover, band, squared(144, 100), 2, stride, sink);
    audit.initial(kinetic::EventTime{}, {Simplex{0}, Simplex{1}, Simplex{0, 1}});
    for (std::size_t i = 1; i <= batches; ++i) {
      kinetic::EventTime at;
      at.slab = 0;
      at.u = static_cast<double>(i) / static_cast<double>(batches + 1);
      at.time = 100.0 * at.u;
      audit.batch(at, {});
    }
    kinetic::EventTime end;
    end.slab = 0;
    end.u = 1.0;
    end.time = 100;
    audit.finish(end);
    const TorusAuditStatistics& s = audit.statistics();
    CHECK(s.skipped == 0);
    CHECK(s.checks == 1 + batches / stride);
    CHECK(s.compared == s.checks);
  }
}
