// CellTriangulation (the triangulation held as cells) against the same combinatorics kept as sets of
// simplices keyed by vertices (Sets, below) as a differential oracle: built from CGAL's Delaunay
// triangulations of random points, then changed by random flips, vertex insertions and deletions,
// both must hold the same top simplices, the same apices across each facet and the same certificate
// ids, and hand back the same ids for the facets that go.
#include "cell_triangulation.h"
#include "medusa/core/error.h"
#include "static_delaunay.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

namespace {

// The top simplices of CGAL's Delaunay triangulation of n random grid points (infinite vertex -1).
std::vector<Simplex> random_delaunay(int dim, std::size_t n, std::mt19937& rng) {
  StaticInput input;
  std::uniform_int_distribution<std::int64_t> coordinate(0, 1000);
  for (std::size_t i = 0; i < n; ++i) {
    MovingPoint p;
    for (int k = 0; k < dim; ++k)
      p.a[static_cast<std::size_t>(k)] = coordinate(rng);
    input.ids.push_back(static_cast<VertexId>(i));
    input.motion.push_back(p);
  }
  int dimension = 0;
  std::vector<Simplex> tops = delaunay_at(dim, input, CGAL::Gmpq(0), dimension);
  REQUIRE(dimension == dim);
  return tops;
}

// Any orientation will do for the combinatorics: +1 or -1 by the parity of the smallest vertex.
int orientation_of(const Simplex& t) { return t[0] == infinite_vertex ? 0 : (t[0] % 2 == 0 ? 1 : -1); }

// The oracle: top simplices with their orientations, and each facet's apices and certificate id, in
// ordered maps keyed by vertices. A facet goes when its last top simplex is removed, and its id with
// it: the order CellTriangulation::replace promises for the ids it hands back.
struct Sets {
  struct Facet {
    std::vector<VertexId> apices;
    int cert = -1;
  };
  std::map<Simplex, int> tops;
  std::map<Simplex, Facet> facets;

  void add_top(const Simplex& t, int orientation) {
    REQUIRE(tops.emplace(t, orientation).second);
    for (std::size_t i = 0; i < t.size(); ++i) {
      Facet& f = facets[t.facet(i)];
      f.apices.push_back(t[i]);
      REQUIRE(f.apices.size() <= 2);
    }
  }
  void remove_top(const Simplex& t, std::vector<int>& dropped) {
    REQUIRE(tops.erase(t) == 1);
    for (std::size_t i = 0; i < t.size(); ++i) {
      const auto it = facets.find(t.facet(i));
      REQUIRE(it != facets.end());
      auto& apices = it->second.apices;
      apices.erase(std::find(apices.begin(), apices.end(), t[i]));
      if (apices.empty()) {
        if (it->second.cert >= 0)
          dropped.push_back(it->second.cert);
        facets.erase(it);
      }
    }
  }
  VertexId other_apex(const Simplex& f, VertexId apex) const {
    const std::vector<VertexId>& a = facets.at(f).apices;
    REQUIRE(a.size() == 2);
    return a[0] == apex ? a[1] : a[0];
  }
  std::vector<Simplex> tops_containing(const Simplex& s) const {
    std::vector<Simplex> result;
    for (const auto& [t, orientation] : tops)
      if (std::all_of(s.begin(), s.end(), [&](VertexId v) { return t.contains(v); }))
        result.push_back(t);
    return result;
  }
  // Every facet has two apices.
  bool closed() const {
    return std::all_of(facets.begin(), facets.end(),
                       [](const auto& f) { return f.second.apices.size() == 2; });
  }
};

template <int D> struct Pair {
  Sets sets;
  CellTriangulation<D> cells;
  int next_cert = 0;

  void assign(const std::vector<Simplex>& tops) {
    std::vector<typename CellTriangulation<D>::NewTop> added;
    for (const Simplex& t : tops) {
      sets.add_top(t, orientation_of(t));
      added.push_back({t, orientation_of(t)});
    }
    cells.assign(added);
  }
  // Gives every facet a fresh certificate id in both.
  void certify_all() {
    cells.for_each_cell([&](CellIndex c) {
      for (int i = 0; i <= D; ++i)
        if (cells.cert(c, i) < 0) {
          const int id = next_cert++;
          cells.set_cert(c, i, id);
          sets.facets.at(cells.facet(c, i)).cert = id;
        }
    });
  }
  // Replaces `removed` by `added` in both; returns the ids each handed back, in order.
  std::pair<std::vector<int>, std::vector<int>> replace(const std::vector<Simplex>& removed,
                                                        const std::vector<Simplex>& added) {
    std::pair<std::vector<int>, std::vector<int>> dropped;
    std::vector<CellIndex> held;
    for (const Simplex& t : removed) {
      held.push_back(cells.find(t));
      REQUIRE(held.back() != no_cell);
      sets.remove_top(t, dropped.first);
    }
    std::vector<typename CellTriangulation<D>::NewTop> news;
    for (const Simplex& t : added) {
      sets.add_top(t, orientation_of(t));
      news.push_back({t, orientation_of(t)});
    }
    std::vector<CellIndex> created;
    cells.replace(held, news, dropped.second, &created);
    REQUIRE(created.size() == added.size());
    for (std::size_t k = 0; k < added.size(); ++k)
      REQUIRE(cells.top(created[k]) == added[k]);
    return dropped;
  }

  void require_same() const {
    REQUIRE(sets.closed());
    const std::string violation = cells.first_violation();
    CAPTURE(violation);
    REQUIRE(violation.empty());
    std::set<Simplex> a, b;
    for (const auto& [t, orientation] : sets.tops)
      a.insert(t);
    cells.for_each_cell([&](CellIndex c) { b.insert(cells.top(c)); });
    REQUIRE(a == b);
    REQUIRE(cells.size() == a.size());
    cells.for_each_cell([&](CellIndex c) {
      const Simplex t = cells.top(c);
      REQUIRE(cells.find(t) == c);
      REQUIRE(cells.orientation(c) == sets.tops.at(t));
      for (int i = 0; i <= D; ++i) {
        const Simplex f = cells.facet(c, i);
        REQUIRE(sets.other_apex(f, t[static_cast<std::size_t>(i)]) == cells.apex_across(c, i));
        REQUIRE(sets.facets.at(f).cert == cells.cert(c, i));
        const auto apices = cells.apices(c, i);
        REQUIRE(apices.v[0] == t[static_cast<std::size_t>(i)]);
        REQUIRE(apices.v[1] == cells.apex_across(c, i));
        REQUIRE(apices.orientation[1] == sets.tops.at(f.with(apices.v[1])));
      }
    });
  }
};

// The top simplices containing every vertex of s, from the walk and from the sets.
template <int D> void require_same_stars(const Pair<D>& p, const Simplex& s) {
  std::set<Simplex> walked;
  p.cells.for_each_cell_containing(s, [&](CellIndex c) { REQUIRE(walked.insert(p.cells.top(c)).second); });
  const std::vector<Simplex> listed = p.sets.tops_containing(s);
  REQUIRE(walked == std::set<Simplex>(listed.begin(), listed.end()));
}

// One random combinatorial flip through a facet or around a ridge (docs/MATH.md §4.5), of those that
// leave a simplicial sphere: 2-3 through facet f (apices d, e) when the edge de is absent, 3-2 around
// an edge of degree 3 whose link triangle is absent; 2-2 through an edge in the plane when the other
// diagonal is absent. Returns false when the random facet allows none.
template <int D>
bool random_flip(Pair<D>& p, std::mt19937& rng, std::vector<Simplex>& removed, std::vector<Simplex>& added) {
  std::vector<CellIndex> living;
  p.cells.for_each_cell([&](CellIndex c) { living.push_back(c); });
  const CellIndex c = living[std::uniform_int_distribution<std::size_t>(0, living.size() - 1)(rng)];
  const int i = std::uniform_int_distribution<int>(0, D)(rng);
  const Simplex t = p.cells.top(c), f = p.cells.facet(c, i);
  const VertexId d = t[static_cast<std::size_t>(i)], e = p.cells.apex_across(c, i);
  removed.clear();
  added.clear();
  if (p.sets.tops_containing(Simplex{d, e}).empty()) {
    removed = {t, f.with(e)};
    for (std::size_t k = 0; k < f.size(); ++k)
      added.push_back(f.facet(k).with(d).with(e));
    return true;
  }
  if constexpr (D == 3) {
    // 3-2 around the edge of t without d and one other vertex of f.
    const VertexId x = f[std::uniform_int_distribution<std::size_t>(0, f.size() - 1)(rng)];
    std::vector<VertexId> edge;
    for (VertexId v : f)
      if (v != x)
        edge.push_back(v);
    const Simplex ridge = Simplex::from_range(edge.begin(), edge.end());
    const std::vector<Simplex> around = p.sets.tops_containing(ridge);
    if (around.size() != 3)
      return false;
    std::set<VertexId> link;
    for (const Simplex& s : around)
      for (VertexId v : s)
        if (!ridge.contains(v))
          link.insert(v);
    const Simplex triangle = Simplex::from_range(link.begin(), link.end());
    if (triangle.size() != 3 || !p.sets.tops_containing(triangle).empty())
      return false;
    // X_0, X_1, X_2: the top simplex without the first, second and third vertex of the ring.
    for (VertexId r : triangle)
      for (const Simplex& s : around)
        if (!s.contains(r))
          removed.push_back(s);
    added = {triangle.with(ridge[0]), triangle.with(ridge[1])};
    return true;
  }
  return false;
}

template <int D> void flips_agree(unsigned seed) {
  std::mt19937 rng(seed);
  Pair<D> p;
  p.assign(random_delaunay(D, D == 3 ? 40 : 30, rng));
  p.require_same();
  p.certify_all();
  p.require_same();
  std::size_t flips = 0, dropped = 0;
  std::vector<Simplex> removed, added;
  for (int step = 0; step < 300; ++step) {
    if (!random_flip(p, rng, removed, added))
      continue;
    const auto ids = p.replace(removed, added);
    REQUIRE(ids.first == ids.second);
    dropped += ids.first.size();
    ++flips;
    p.require_same();
    p.certify_all();
    if (step % 25 == 0)
      for (VertexId v = -1; v < 6; ++v)
        require_same_stars(p, Simplex{v});
  }
  CAPTURE(flips, dropped);
  REQUIRE(flips > 50);   // the walk did flip
  REQUIRE(dropped > 50); // and facets went with their certificates
}

} // namespace

TEST_CASE("a cell triangulation of CGAL's Delaunay tetrahedra follows the sets of its simplices through "
          "random 2-3 and 3-2 flips",
          "[kinetic][cell_triangulation]") {
  const unsigned seed = GENERATE(31u, 32u, 33u);
  CAPTURE(seed);
  flips_agree<3>(seed);
}

TEST_CASE(
    "a cell triangulation of CGAL's Delaunay triangles follows the sets of its simplices through random "
    "2-2 flips",
    "[kinetic][cell_triangulation]") {
  const unsigned seed = GENERATE(41u, 42u, 43u);
  CAPTURE(seed);
  flips_agree<2>(seed);
}

// The same flips applied to a second cell triangulation by flip() and flip_edge() on held cells,
// with the certificate ids of the first: both must agree after each, in the ids handed back too.
template <int D> void held_flips_agree(unsigned seed) {
  std::mt19937 rng(seed);
  Pair<D> p;
  const std::vector<Simplex> tops = random_delaunay(D, D == 3 ? 40 : 30, rng);
  p.assign(tops);
  p.certify_all();
  CellTriangulation<D> held;
  {
    std::vector<typename CellTriangulation<D>::NewTop> news;
    for (const Simplex& t : tops)
      news.push_back({t, orientation_of(t)});
    held.assign(news);
  }
  const auto copy_certs = [&] {
    held.for_each_cell([&](CellIndex c) {
      for (int i = 0; i <= D; ++i)
        if (held.cert(c, i) < 0)
          held.set_cert(c, i, p.sets.facets.at(held.facet(c, i)).cert);
    });
  };
  copy_certs();
  std::size_t through = 0, around = 0;
  std::vector<Simplex> removed, added;
  for (int step = 0; step < 300; ++step) {
    if (!random_flip(p, rng, removed, added))
      continue;
    const auto ids = p.replace(removed, added);
    std::vector<int> dropped;
    if (removed.size() == 2) {
      const CellIndex c = held.find(removed[0]);
      const Simplex other = removed[1];
      int i = 0;
      while (other.contains(held.vertex(c, i)))
        ++i;
      std::array<int, D> orientations{};
      std::array<CellIndex, D> created{};
      for (std::size_t k = 0; k < D; ++k)
        orientations[k] = orientation_of(added[k]);
      held.flip(c, i, orientations, dropped, created);
      for (std::size_t k = 0; k < D; ++k)
        REQUIRE(held.top(created[k]) == added[k]);
      ++through;
    } else {
      if constexpr (D == 3) {
        const CellIndex c = held.find(removed[0]);
        int i = -1, j = -1;
        for (int k = 0; k < 4; ++k)
          if (removed[1].contains(held.vertex(c, k)) && removed[2].contains(held.vertex(c, k)))
            (i < 0 ? i : j) = k;
        std::array<CellIndex, 2> created{};
        held.flip_edge(c, i, j, {orientation_of(added[0]), orientation_of(added[1])}, dropped, created);
        REQUIRE(held.top(created[0]) == added[0]);
        REQUIRE(held.top(created[1]) == added[1]);
        ++around;
      }
    }
    REQUIRE(dropped == ids.second);
    p.require_same();
    p.certify_all();
    copy_certs();
    const std::string violation = held.first_violation();
    CAPTURE(violation);
    REQUIRE(violation.empty());
    std::set<Simplex> a, b;
    p.cells.for_each_cell([&](CellIndex c) { a.insert(p.cells.top(c)); });
    held.for_each_cell([&](CellIndex c) {
      b.insert(held.top(c));
      REQUIRE(held.orientation(c) == orientation_of(held.top(c)));
      for (int i = 0; i <= D; ++i) {
        REQUIRE(held.apex_across(c, i) == p.sets.other_apex(held.facet(c, i), held.vertex(c, i)));
        REQUIRE(held.cert(c, i) == p.sets.facets.at(held.facet(c, i)).cert);
      }
    });
    REQUIRE(a == b);
  }
  CAPTURE(through, around);
  REQUIRE(through > 50);
  REQUIRE((D == 2 || around > 20));
}

TEST_CASE("flips on held cells give what replacing the cells gives, certificate ids included",
          "[kinetic][cell_triangulation]") {
  const unsigned seed = GENERATE(71u, 72u);
  CAPTURE(seed);
  held_flips_agree<3>(seed);
  held_flips_agree<2>(seed);
}

TEST_CASE("a vertex inserted into a cell and deleted again leaves the cells and certificates as they were",
          "[kinetic][cell_triangulation]") {
  std::mt19937 rng(51);
  Pair<3> p;
  p.assign(random_delaunay(3, 30, rng));
  p.certify_all();
  const std::size_t before = p.cells.size();
  // Every finite cell in turn: split by a new vertex 99 (1-4), then the star of 99 merged back (4-1).
  std::vector<Simplex> finite;
  p.cells.for_each_cell([&](CellIndex c) {
    if (p.cells.vertex(c, 0) != infinite_vertex)
      finite.push_back(p.cells.top(c));
  });
  REQUIRE(!finite.empty());
  for (const Simplex& t : finite) {
    std::vector<Simplex> star;
    for (std::size_t k = 0; k < t.size(); ++k)
      star.push_back(t.facet(k).with(99));
    const auto split = p.replace({t}, star);
    REQUIRE(split.first.empty());
    p.require_same();
    require_same_stars(p, Simplex{99});
    p.certify_all(); // the six new inner facets
    const auto merged = p.replace(star, {t});
    REQUIRE(merged.first == merged.second);
    REQUIRE(merged.first.size() == 6);
    REQUIRE(p.cells.cell_of(99) == no_cell);
    p.require_same();
  }
  REQUIRE(p.cells.size() == before);
}

// Every vertex, edge and triangle of the triangulation, and as many pairs and triples of vertices
// that are not faces: the walks find a cell holding each face and none for the others, and from any
// cell holding a face the walk across its facets reaches exactly the cells the sets list.
template <int D> void walks_agree(unsigned seed) {
  std::mt19937 rng(seed);
  Pair<D> p;
  p.assign(random_delaunay(D, D == 3 ? 40 : 30, rng));
  std::set<Simplex> faces;
  for (const auto& [t, orientation] : p.sets.tops)
    for (unsigned mask = 1; mask + 1 < (1u << t.size()); ++mask) {
      std::vector<VertexId> v;
      for (std::size_t k = 0; k < t.size(); ++k)
        if (mask & (1u << k))
          v.push_back(t[k]);
      faces.insert(Simplex::from_range(v.begin(), v.end()));
    }
  std::size_t absent = 0, present = 0;
  std::uniform_int_distribution<VertexId> vertex(-1, D == 3 ? 39 : 29);
  while (absent < faces.size() / 4) {
    const VertexId a = vertex(rng), b = vertex(rng), c = vertex(rng);
    for (const Simplex& s : {Simplex{a, b}, Simplex{a, b, c}})
      if (std::set<VertexId>(s.begin(), s.end()).size() == s.size() && !faces.count(s) &&
          !p.sets.tops.count(s)) {
        REQUIRE(p.cells.cell_containing(s) == no_cell);
        ++absent;
      }
  }
  for (const Simplex& s : faces) {
    CAPTURE(s);
    const std::vector<Simplex> listed = p.sets.tops_containing(s);
    const std::set<Simplex> expected(listed.begin(), listed.end());
    const CellIndex found = p.cells.cell_containing(s);
    REQUIRE(found != no_cell);
    REQUIRE(expected.count(p.cells.top(found)));
    for (const Simplex& t : listed) {
      std::set<Simplex> walked;
      p.cells.for_each_cell_containing_from(
          p.cells.find(t), s, [&](CellIndex c) { REQUIRE(walked.insert(p.cells.top(c)).second); });
      REQUIRE(walked == expected);
    }
    ++present;
  }
  CAPTURE(present, absent);
  REQUIRE(present > 100);
}

// Round every ridge (an edge in 3D, a vertex in the plane), from every cell holding it: the cells come
// as a ring, each sharing a facet that holds the ridge with the next and the last with the first, each
// once, starting across the later of the first cell's two facets that hold it.
template <int D> void rings_close(unsigned seed) {
  std::mt19937 rng(seed);
  Pair<D> p;
  p.assign(random_delaunay(D, D == 3 ? 40 : 30, rng));
  const auto across_ridge = [&](CellIndex c, const Simplex& s) {
    std::vector<CellIndex> across;
    for (int i = 0; i <= D; ++i)
      if (!s.contains(p.cells.vertex(c, i)))
        across.push_back(p.cells.neighbor(c, i));
    return across;
  };
  std::set<Simplex> ridges;
  for (const auto& [t, orientation] : p.sets.tops)
    for (std::size_t i = 0; i < t.size(); ++i) {
      if constexpr (D == 3) {
        for (std::size_t j = i + 1; j < t.size(); ++j)
          ridges.insert(Simplex{t[i], t[j]});
      } else {
        ridges.insert(Simplex{t[i]});
      }
    }
  std::size_t rings = 0;
  for (const Simplex& s : ridges) {
    CAPTURE(s);
    const std::vector<Simplex> listed = p.sets.tops_containing(s);
    for (const Simplex& t : listed) {
      const CellIndex start = p.cells.find(t);
      std::vector<CellIndex> ring;
      p.cells.for_each_cell_containing_from(start, s, [&](CellIndex c) { ring.push_back(c); });
      REQUIRE(ring.size() == listed.size());
      REQUIRE(std::set<CellIndex>(ring.begin(), ring.end()).size() == ring.size());
      REQUIRE(ring.front() == start);
      REQUIRE(across_ridge(start, s).size() == 2);
      REQUIRE(ring[1 % ring.size()] == across_ridge(start, s)[1]);
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::vector<CellIndex> across = across_ridge(ring[k], s);
        REQUIRE(std::count(across.begin(), across.end(), ring[(k + 1) % ring.size()]) >= 1);
      }
      ++rings;
    }
  }
  CAPTURE(rings);
  REQUIRE(rings > 100);
}

TEST_CASE("the cells round a ridge come as a ring, in the order of a walk across its facets",
          "[kinetic][cell_triangulation]") {
  const unsigned seed = GENERATE(83u, 84u);
  CAPTURE(seed);
  rings_close<3>(seed);
  rings_close<2>(seed);
}

TEST_CASE("the walks find a cell holding each face of the triangulation, none for other simplices, and "
          "every cell holding it from any one",
          "[kinetic][cell_triangulation]") {
  const unsigned seed = GENERATE(81u, 82u);
  CAPTURE(seed);
  walks_agree<3>(seed);
  walks_agree<2>(seed);
}

TEST_CASE("a replacement that does not close its hole is refused and changes nothing",
          "[kinetic][cell_triangulation]") {
  std::mt19937 rng(61);
  Pair<3> p;
  p.assign(random_delaunay(3, 20, rng));
  p.certify_all();
  CellIndex c = no_cell;
  p.cells.for_each_cell([&](CellIndex x) {
    if (c == no_cell && p.cells.vertex(x, 0) != infinite_vertex)
      c = x;
  });
  const Simplex t = p.cells.top(c);
  using NewTop = CellTriangulation<3>::NewTop;
  std::vector<int> dropped;
  // Three of the four tetrahedra of a 1-4 split: the fourth facet of t stays uncovered.
  std::vector<NewTop> three;
  for (std::size_t k = 0; k < 3; ++k)
    three.push_back({t.facet(k).with(99), 1});
  REQUIRE_THROWS_AS(p.cells.replace({c}, three, dropped), medusa::InternalError);
  // A simplex that is not a top simplex, and a cell removed twice.
  REQUIRE_THROWS_AS(p.cells.replace({c}, {NewTop{t.facet(0), 1}}, dropped), medusa::InternalError);
  REQUIRE_THROWS_AS(p.cells.replace({c, c}, {NewTop{t, 1}}, dropped), medusa::InternalError);
  REQUIRE(dropped.empty());
  p.require_same();
  // A pseudo-manifold check on the whole: a lone tetrahedron has open facets.
  CellTriangulation<3> lone;
  REQUIRE_THROWS_AS(lone.assign({NewTop{Simplex{0, 1, 2, 3}, 1}}), medusa::InternalError);
  REQUIRE(lone.size() == 0);
}

TEST_CASE("the cell triangulation's own check names a broken orientation and a second sphere",
          "[kinetic][cell_triangulation]") {
  using NewTop = CellTriangulation<2>::NewTop;
  const auto augmented = [](const Simplex& t, VertexId shift, int orientation) {
    std::vector<NewTop> tops;
    std::vector<VertexId> v(t.begin(), t.end());
    for (VertexId& x : v)
      x += shift;
    const Simplex s = Simplex::from_range(v.begin(), v.end());
    tops.push_back({s, orientation});
    for (std::size_t i = 0; i < s.size(); ++i)
      tops.push_back({s.facet(i).with(infinite_vertex), 0});
    return tops;
  };
  CellTriangulation<2> sphere;
  sphere.assign(augmented(Simplex{0, 1, 2}, 0, 1));
  REQUIRE(sphere.first_violation().empty());
  CellTriangulation<2> flat;
  flat.assign(augmented(Simplex{0, 1, 2}, 0, 0));
  REQUIRE(flat.first_violation().find("orientation") != std::string::npos);
  // Two spheres: every facet has two cells, but V - E + T is 3, not 2 (the infinite vertex is shared).
  std::vector<NewTop> two = augmented(Simplex{0, 1, 2}, 0, 1);
  const std::vector<NewTop> second = augmented(Simplex{0, 1, 2}, 10, 1);
  two.insert(two.end(), second.begin(), second.end());
  CellTriangulation<2> both;
  both.assign(two);
  REQUIRE(both.first_violation().find("Euler") != std::string::npos);
}
