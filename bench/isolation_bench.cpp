// Root isolation benchmark: the engine's isolation of a certificate's next failure time in doubles
// (libkinetic root_isolation.h: the in-sphere polynomial enclosed from doubles, Bernstein-Descartes
// isolation, narrowing to 2^-24 as when a failure time is scheduled) against CGAL's
// Algebraic_kernel_d_1 over Gmpz with MPFI (the exact integer polynomial, solve_1, the first root in
// (0, 1) approximated to 2^-24), on the same certificates: the measurement behind isolating in
// doubles first and calling CGAL's kernel only for times that stay close. Every root isolated in doubles is
// checked to lie in the interval that CGAL's exact root gives; a disagreement stops the program with exit
// code 1.
//
// The certificates are the in-sphere certificates of every finite facet with two finite apices in
// the Delaunay triangulation of n random points at the cells' spacing, over one slab of a random
// walk (the kinetic benchmark's motion: 0.7 lattice units per coordinate and frame), kept when they
// change sign in (0, 1): those are the ones that need a root isolated.
//
// Usage: isolation_bench [--points N]... [--seed S]
#include "algebraic_time.h"
#include "certificate_enclosure.h"
#include "certificate_polynomials.h"
#include "root_isolation.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace medusa::kinetic;
using Clock = std::chrono::steady_clock;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;

using Certificate = std::array<int, 5>; // facet p0 p1 p2, apices p3 and y

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One slab of the kinetic benchmark's random walk on the 10^-6 grid.
std::vector<MovingPoint> random_slab(std::size_t n, std::mt19937_64& rng) {
  const std::int64_t unit = 1000000;
  const double side = 5.0 * std::cbrt(double(n));
  std::uniform_real_distribution<double> start(0, side * double(unit));
  std::normal_distribution<double> step(0, 0.7 * double(unit));
  std::vector<MovingPoint> m(n);
  for (MovingPoint& p : m)
    for (std::size_t a = 0; a < 3; ++a) {
      p.a[a] = std::int64_t(start(rng));
      p.b[a] = std::int64_t(step(rng));
    }
  return m;
}

struct Ours {
  FirstSignChange::Status status = FirstSignChange::Status::undecided;
  double lo = 0, hi = 0;
};

// The engine's path: enclosure from doubles, first sign change on [0, 1], narrowed to 2^-24.
Ours isolate_in_doubles(const std::vector<MovingPoint>& m, const Certificate& c) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IntervalPoly f = in_sphere_enclosure(m[std::size_t(c[0])], m[std::size_t(c[1])], m[std::size_t(c[2])],
                                             m[std::size_t(c[3])], m[std::size_t(c[4])]);
  const FirstSignChange next = first_sign_change(f, 0.0, 12);
  Ours r;
  r.status = next.status;
  if (next.status == FirstSignChange::Status::root) {
    r.lo = next.lo;
    r.hi = next.hi;
    narrow_root(f, r.lo, r.hi, next.sign, 0x1p-24);
  }
  return r;
}

ExactPoly exact_polynomial(const std::vector<MovingPoint>& m, const Certificate& c) {
  return to_exact_poly(certificate::in_sphere<mpz_class>(m[std::size_t(c[0])], m[std::size_t(c[1])],
                                                         m[std::size_t(c[2])], m[std::size_t(c[3])],
                                                         m[std::size_t(c[4])]));
}

// CGAL's path on the exact polynomial: all real roots, then the first one of odd multiplicity in
// (0, 1) (a sign change), approximated to 2^-24. False when there is none.
bool first_root_exactly(const ExactPoly& f, AlgebraicReal& root, std::pair<Rational, Rational>& approx) {
  const RealRoots r = real_roots(f);
  const AlgebraicReal zero(0), one(1);
  for (const auto& [x, multiplicity] : r.roots)
    if (multiplicity % 2 == 1 && zero < x && x < one) {
      root = x;
      const auto a = AlgebraicKernel().approximate_absolute_1_object()(x, 24);
      approx = {Rational(a.first), Rational(a.second)};
      return true;
    }
  return false;
}

void run_case(std::size_t n, std::uint64_t seed) {
  std::printf("\n== %zu random points, one slab of the random walk (seed %llu) ==\n", n,
              static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  const std::vector<MovingPoint> m = random_slab(n, rng);
  std::vector<std::pair<K::Point_3, int>> pts;
  for (std::size_t i = 0; i < n; ++i)
    pts.emplace_back(K::Point_3(double(m[i].a[0]), double(m[i].a[1]), double(m[i].a[2])), int(i));
  const Dt dt(pts.begin(), pts.end());

  // Every in-sphere certificate; those that change sign in (0, 1), by the exact polynomial's roots.
  std::vector<Certificate> all, failing;
  for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
    const Dt::Cell_handle c = f->first, n2 = c->neighbor(f->second);
    if (dt.is_infinite(c) || dt.is_infinite(n2))
      continue;
    Certificate cert{};
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != f->second)
        cert[std::size_t(k++)] = c->vertex(i)->info();
    cert[3] = c->vertex(f->second)->info();
    cert[4] = n2->vertex(n2->index(c))->info();
    all.push_back(cert);
  }
  std::vector<std::pair<AlgebraicReal, std::pair<Rational, Rational>>> exact_roots;
  for (const Certificate& c : all) {
    AlgebraicReal root;
    std::pair<Rational, Rational> approx;
    if (first_root_exactly(exact_polynomial(m, c), root, approx)) {
      failing.push_back(c);
      exact_roots.emplace_back(root, approx);
    }
  }
  std::printf("in-sphere certificates %zu, of which %zu change sign in the slab (isolated below)\n",
              all.size(), failing.size());
  if (failing.empty()) {
    std::fprintf(stderr, "isolation_bench: no certificate fails in the slab; nothing to measure\n");
    std::exit(1);
  }

  // Agreement: each root isolated in doubles contains CGAL's exact root.
  std::size_t undecided = 0;
  for (std::size_t i = 0; i < failing.size(); ++i) {
    const Ours r = isolate_in_doubles(m, failing[i]);
    if (r.status != FirstSignChange::Status::root) {
      ++undecided; // the engine falls back to exact isolation for these
      continue;
    }
    const SlabTime exact(exact_roots[i].first);
    if (!(compare(SlabTime(Rational(r.lo)), exact) <= 0 && compare(exact, SlabTime(Rational(r.hi))) <= 0)) {
      std::fprintf(stderr,
                   "isolation_bench: certificate %zu: root isolated in (%.17g, %.17g), exact root outside\n",
                   i, r.lo, r.hi);
      std::exit(1);
    }
  }
  std::printf(
      "roots isolated in doubles: %zu, each containing CGAL's exact root; undecided in doubles: %zu\n",
      failing.size() - undecided, undecided);

  // Timings: best of three rounds of each path over all failing certificates.
  double ours = 1e300, exact_poly = 1e300, exact_isolation = 1e300;
  for (int round = 0; round < 3; ++round) {
    auto t = Clock::now();
    std::size_t keep = 0;
    for (const Certificate& c : failing)
      keep += isolate_in_doubles(m, c).status == FirstSignChange::Status::root;
    ours = std::min(ours, seconds_since(t));
    std::vector<ExactPoly> polys;
    polys.reserve(failing.size());
    t = Clock::now();
    for (const Certificate& c : failing)
      polys.push_back(exact_polynomial(m, c));
    exact_poly = std::min(exact_poly, seconds_since(t));
    t = Clock::now();
    for (const ExactPoly& f : polys) {
      AlgebraicReal root;
      std::pair<Rational, Rational> approx;
      keep += first_root_exactly(f, root, approx);
    }
    exact_isolation = std::min(exact_isolation, seconds_since(t));
    if (keep == 0)
      std::printf("(none)\n"); // keeps the loops from being optimised away
  }
  const double per = 1e9 / double(failing.size());
  std::printf("per certificate, best of 3 rounds:\n");
  std::printf("  ours: enclosure from doubles + Bernstein isolation + narrowing to 2^-24   %10.0f ns\n",
              ours * per);
  std::printf("  CGAL Algebraic_kernel_d_1: exact polynomial (GMP)                        %10.0f ns\n",
              exact_poly * per);
  std::printf("  CGAL Algebraic_kernel_d_1: solve_1 + first root to 2^-24                 %10.0f ns\n",
              exact_isolation * per);
  std::printf("  CGAL total / ours: %.1f\n", (exact_poly + exact_isolation) / ours);
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes;
  std::uint64_t seed = 20261125;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "isolation_bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--points")
      sizes.push_back(std::stoul(value()));
    else if (a == "--seed")
      seed = std::stoull(value());
    else if (a == "--help" || a == "-h") {
      std::printf(
          "usage: isolation_bench [--points N]... [--seed S]\n"
          "  isolates the failure times of the in-sphere certificates that fail in one random-walk slab,\n"
          "  in doubles (the engine) and with CGAL's Algebraic_kernel_d_1; default 1,000 points\n");
      return 0;
    } else {
      std::fprintf(stderr, "isolation_bench: unknown argument %s (try --help)\n", a.c_str());
      return 2;
    }
  }
  if (sizes.empty())
    sizes = {1000};
  for (std::size_t n : sizes)
    run_case(n, seed);
  return 0;
}
