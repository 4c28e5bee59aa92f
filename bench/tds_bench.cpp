// Triangulation benchmark: the engine's triangulation held as cells (libkinetic/src/cell_triangulation.h)
// against CGAL's Triangulation_data_structure_3 and its flip operations, on one sequence of 2-3 and
// 3-2 flips. It measures what each structure costs per flip.
//
// The flips are drawn among the geometrically valid ones (CGAL's Triangulation_3::flip, exact
// orientation tests) on the Delaunay triangulation of n random points at the cells' spacing, half
// of them 2-3 flips of random facets and half 3-2 flips undoing earlier ones (draw_flips), and
// recorded as vertex ids. Both structures then replay the same sequence from the same initial
// triangulation, in one process:
//   * CGAL: tds().flip_flippable on the cell (and facet or edge index) that carries the flip, found
//     from the vertex ids by is_facet / is_edge (what a caller that keys its flips by vertex ids
//     pays), and the flip alone (what a kinetic structure that keeps its certificates in the cells
//     would pay);
//   * cells: CellTriangulation, the cell found from the vertex ids by a star walk (timed apart; the
//     engine reaches it from the failed certificate instead) and flipped in place (flip, flip_edge).
//
// Usage: tds_bench [--points N]... [--flips M] [--seed S]
// With no argument: 1,000 and 10,000 points, 20 flips per point.
#include "cell_triangulation.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

using medusa::kinetic::Simplex;
using medusa::kinetic::VertexId;
using medusa::kinetic::detail::CellIndex;
using medusa::kinetic::detail::CellTriangulation;
using Clock = std::chrono::steady_clock;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<VertexId, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;

// A flip by vertex ids: 2-3 on the facet {v0, v1, v2} with apices v3, v4; 3-2 on the edge {v0, v1}
// of degree 3 whose ring is {v2, v3, v4}.
struct Flip {
  bool two_three = true;
  std::array<VertexId, 5> v{};
};

std::vector<std::pair<K::Point_3, VertexId>> random_points(std::size_t n, std::mt19937_64& rng) {
  // Cells about 5 lattice units apart, as in the kinetic benchmark's random walks.
  const double side = 5.0 * std::cbrt(double(n));
  std::uniform_real_distribution<double> coord(0.0, side);
  std::vector<std::pair<K::Point_3, VertexId>> pts;
  for (std::size_t i = 0; i < n; ++i)
    pts.emplace_back(K::Point_3(coord(rng), coord(rng), coord(rng)), static_cast<VertexId>(i));
  return pts;
}

VertexId id(const Dt& dt, Dt::Vertex_handle v) { return dt.is_infinite(v) ? -1 : v->info(); }

// The ring of the edge (c, i, j) when it has degree 3 and no infinite cell, as a 3-2 flip of it.
bool edge_flip(const Dt& dt, Dt::Cell_handle c, int i, int j, Flip& f) {
  f.two_three = false;
  f.v[0] = id(dt, c->vertex(i));
  f.v[1] = id(dt, c->vertex(j));
  std::vector<VertexId> ring;
  auto start = dt.incident_cells(c, i, j), it = start;
  do {
    for (int k = 0; k < 4; ++k) {
      const VertexId x = id(dt, it->vertex(k));
      if (x != f.v[0] && x != f.v[1] && std::find(ring.begin(), ring.end(), x) == ring.end())
        ring.push_back(x);
    }
  } while (++it != start);
  if (ring.size() != 3 || std::find(ring.begin(), ring.end(), -1) != ring.end())
    return false;
  std::copy(ring.begin(), ring.end(), f.v.begin() + 2);
  return true;
}

// Valid finite flips on dt, drawn as a kinetic run makes them: half are 2-3 flips of random facets,
// half are 3-2 flips undoing the oldest 2-3 flip still undoable. So the triangulation stays within
// a bounded number of flips of the Delaunay one (vertex degrees do not grow, as they would under
// random flips alone), and each undo comes long after its flip, with its records out of the cache,
// as the kinetic flips of a slab are scattered over the whole triangulation.
std::vector<Flip> draw_flips(Dt& dt, const std::vector<Dt::Vertex_handle>& by_id, std::size_t count,
                             std::mt19937_64& rng) {
  std::vector<Flip> flips;
  std::vector<Flip> outstanding; // 2-3 flips not undone yet, oldest first (from `oldest` on)
  std::size_t oldest = 0;
  const std::size_t limit = std::max<std::size_t>(16, by_id.size() / 8);
  std::vector<Dt::Cell_handle> cells;
  std::uniform_int_distribution<std::size_t> vertex(0, by_id.size() - 1);
  std::uniform_int_distribution<int> index(0, 3);
  while (flips.size() < count) {
    if (outstanding.size() - oldest >= limit || (oldest < outstanding.size() && (rng() & 1u))) {
      // Undo the oldest 2-3 flip: a 3-2 flip of the edge between its apices, if still possible.
      const Flip done = outstanding[oldest++];
      Dt::Cell_handle c;
      int i = 0, j = 0;
      Flip f;
      if (dt.tds().is_edge(by_id[std::size_t(done.v[3])], by_id[std::size_t(done.v[4])], c, i, j) &&
          edge_flip(dt, c, i, j, f) && dt.flip(c, i, j))
        flips.push_back(f);
      continue;
    }
    cells.clear();
    dt.finite_incident_cells(by_id[vertex(rng)], std::back_inserter(cells));
    if (cells.empty())
      continue;
    Dt::Cell_handle c = cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(rng)];
    const int i = index(rng);
    Dt::Cell_handle n = c->neighbor(i);
    if (dt.is_infinite(n))
      continue;
    Flip f;
    for (int j = 0, k = 0; j < 4; ++j)
      if (j != i)
        f.v[static_cast<std::size_t>(k++)] = id(dt, c->vertex(j));
    f.v[3] = id(dt, c->vertex(i));
    f.v[4] = id(dt, n->vertex(n->index(c)));
    if (dt.flip(c, i)) {
      flips.push_back(f);
      outstanding.push_back(f);
    }
  }
  return flips;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The engine's triangulation held as cells (CellTriangulation), each flip made on the cell that
// carries it (flip through a facet, flip_edge around an edge). The cell is found from the vertex ids
// by a walk over a vertex's star, timed apart as CGAL's look-up is (`lookup_seconds`): a certificate
// that names its (cell, facet) needs no look-up.
double replay_cells(const std::vector<Simplex>& initial, const std::vector<Flip>& flips, double clock_cost,
                    double& lookup_seconds, std::size_t& check) {
  CellTriangulation<3> tri;
  {
    std::vector<CellTriangulation<3>::NewTop> tops;
    for (const Simplex& t : initial)
      tops.push_back({t, t[0] == -1 ? 0 : 1});
    tri.assign(tops);
  }
  std::vector<int> dropped;
  std::array<CellIndex, 3> three{};
  std::array<CellIndex, 2> two{};
  lookup_seconds = 0;
  const auto start = Clock::now();
  for (const Flip& f : flips) {
    const auto& v = f.v;
    // v0 v1 v2 v3 is a top simplex before either kind of flip (Flip).
    const auto t0 = Clock::now();
    const CellIndex c = tri.find(Simplex{v[0], v[1], v[2], v[3]});
    lookup_seconds += std::chrono::duration<double>(Clock::now() - t0).count() - clock_cost;
    if (f.two_three)
      tri.flip(c, tri.index_of(c, v[3]), {1, 1, 1}, dropped, three);
    else
      tri.flip_edge(c, tri.index_of(c, v[0]), tri.index_of(c, v[1]), {1, 1}, dropped, two);
  }
  const double s = seconds_since(start);
  check = tri.size();
  return s;
}

double clock_cost() {
  const int reps = 100000;
  const auto s0 = Clock::now();
  for (int r = 0; r < reps; ++r)
    (void)Clock::now();
  return seconds_since(s0) / reps;
}

// CGAL's structure, replaying the flips on a copy of the initial triangulation. `lookup_seconds`
// receives the time of the is_facet / is_edge look-ups alone (timed per flip; the clock's own cost,
// measured, is taken out).
double replay_cgal(const Dt& initial, const std::vector<Flip>& flips, double& lookup_seconds,
                   std::size_t& check) {
  Dt dt(initial);
  std::vector<Dt::Vertex_handle> by_id(dt.number_of_vertices());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    by_id[static_cast<std::size_t>(v->info())] = v;
  Tds& tds = dt.tds();
  const double clock = clock_cost();
  lookup_seconds = 0;
  const auto start = Clock::now();
  for (const Flip& f : flips) {
    const auto& v = f.v;
    Dt::Cell_handle c;
    int i = 0, j = 0, k = 0;
    const auto t0 = Clock::now();
    bool found;
    if (f.two_three)
      found = tds.is_facet(by_id[std::size_t(v[0])], by_id[std::size_t(v[1])], by_id[std::size_t(v[2])], c, i,
                           j, k);
    else
      found = tds.is_edge(by_id[std::size_t(v[0])], by_id[std::size_t(v[1])], c, i, j);
    lookup_seconds += std::chrono::duration<double>(Clock::now() - t0).count() - clock;
    if (!found) {
      std::fprintf(stderr, "tds_bench: a recorded flip is not in CGAL's replay\n");
      std::exit(1);
    }
    if (f.two_three)
      tds.flip_flippable(c, 6 - i - j - k);
    else
      tds.flip_flippable(c, i, j);
  }
  const double s = seconds_since(start);
  check = dt.tds().number_of_cells();
  return s;
}

void run_case(std::size_t n, std::size_t flips_per_point, std::uint64_t seed) {
  std::printf("\n== %zu random points, %zu flips (seed %llu) ==\n", n, n * flips_per_point,
              static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  const auto pts = random_points(n, rng);
  const Dt initial(pts.begin(), pts.end());
  std::vector<Simplex> tets;
  for (auto c = initial.all_cells_begin(); c != initial.all_cells_end(); ++c) {
    std::array<VertexId, 4> v{};
    for (int i = 0; i < 4; ++i)
      v[static_cast<std::size_t>(i)] = id(initial, c->vertex(i));
    tets.push_back(Simplex::from_range(v.begin(), v.end()));
  }
  std::vector<Flip> flips;
  {
    Dt scratch(initial);
    std::vector<Dt::Vertex_handle> by_id(n);
    for (auto v = scratch.finite_vertices_begin(); v != scratch.finite_vertices_end(); ++v)
      by_id[static_cast<std::size_t>(v->info())] = v;
    flips = draw_flips(scratch, by_id, n * flips_per_point, rng);
  }
  const std::size_t n23 =
      std::size_t(std::count_if(flips.begin(), flips.end(), [](const Flip& f) { return f.two_three; }));
  std::printf(
      "initial triangulation: %zu top simplices (infinite ones included), %.1f per vertex; flips: %zu "
      "2-3, %zu 3-2\n",
      tets.size(), 4.0 * double(tets.size()) / double(n), n23, flips.size() - n23);

  // Alternate the two replays, three rounds, and keep each one's best (the machine's noise is
  // one-sided).
  double cgal = 1e300, lookup = 1e300, cells = 1e300, cells_lookup = 1e300;
  std::size_t cgal_cells = 0, cell_count = 0;
  const double clock = clock_cost();
  for (int round = 0; round < 3; ++round) {
    double l = 0;
    const double c = replay_cgal(initial, flips, l, cgal_cells);
    if (c < cgal) {
      cgal = c;
      lookup = l;
    }
    const double h = replay_cells(tets, flips, clock, l, cell_count);
    if (h < cells) {
      cells = h;
      cells_lookup = l;
    }
  }
  if (cell_count != cgal_cells) {
    std::fprintf(stderr, "tds_bench: the replays disagree: %zu top simplices against CGAL's %zu cells\n",
                 cell_count, cgal_cells);
    std::exit(1);
  }
  const double per = 1e9 / double(flips.size());
  const double flip_only = cgal - lookup, cells_only = cells - cells_lookup;
  std::printf("per flip, best of 3 alternating rounds:\n");
  std::printf("  CGAL TDS, is_facet/is_edge look-up + flip_flippable          %8.1f ns\n", cgal * per);
  std::printf("  CGAL TDS, flip_flippable alone (look-up timed apart: %.1f ns) %8.1f ns\n", lookup * per,
              flip_only * per);
  std::printf("  cells (CellTriangulation::find + flip on the cell)            %8.1f ns   cells/CGAL %.2f\n",
              cells * per, cells / cgal);
  std::printf("  cells, flip alone (find timed apart: %.1f ns)                 %8.1f ns   cells/CGAL %.2f\n",
              cells_lookup * per, cells_only * per, cells_only / flip_only);
  std::printf("all end with %zu top simplices (%.1f per vertex)\n", cell_count,
              4.0 * double(cell_count) / double(n));
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes;
  std::size_t flips_per_point = 20;
  std::uint64_t seed = 20261125;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "tds_bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--points")
      sizes.push_back(std::stoul(value()));
    else if (a == "--flips")
      flips_per_point = std::stoul(value());
    else if (a == "--seed")
      seed = std::stoull(value());
    else if (a == "--help" || a == "-h") {
      std::printf(
          "usage: tds_bench [--points N]... [--flips PER_POINT] [--seed S]\n"
          "  replays one sequence of random valid 2-3 and 3-2 flips on the engine's cell triangulation and\n"
          "  on CGAL's Triangulation_data_structure_3; default 1,000 and 10,000 points, 20 flips per "
          "point\n");
      return 0;
    } else {
      std::fprintf(stderr, "tds_bench: unknown argument %s (try --help)\n", a.c_str());
      return 2;
    }
  }
  if (sizes.empty())
    sizes = {1000, 10000};
  for (std::size_t n : sizes)
    run_case(n, flips_per_point, seed);
  return 0;
}
