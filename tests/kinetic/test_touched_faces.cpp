// collect_touched_faces (the engine's private enumeration of the faces a change of Del touches)
// against a brute-force oracle: every face of every changed top simplex counted in an ordered map.
#include "face.h"
#include "touched_faces.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

namespace {

void require_matches_oracle(const std::vector<Simplex>& removed, const std::vector<Simplex>& added) {
  std::map<Simplex, int> delta; // std::map iterates in Simplex's canonical order
  for (const auto* list : {&removed, &added})
    for (const Simplex& t : *list)
      for_each_face(t, [&](const Simplex& f) { delta[f] += list == &removed ? -1 : 1; });
  TouchedFaces got;
  collect_touched_faces(removed, added, got);
  REQUIRE(got.faces.size() == delta.size());
  std::size_t i = 0;
  for (const auto& [face, d] : delta) {
    CAPTURE(i, face, got.faces[i].face);
    REQUIRE(got.faces[i].face == face);
    REQUIRE(got.faces[i].delta == d);
    ++i;
  }
}

// Five distinct vertex ids, sorted; the first is the infinite vertex in a hull flip.
std::vector<VertexId> random_group(std::mt19937_64& rng, std::size_t n, bool hull) {
  std::uniform_int_distribution<VertexId> id(0, 40);
  std::vector<VertexId> v;
  if (hull)
    v.push_back(infinite_vertex);
  while (v.size() < n) {
    VertexId x = id(rng);
    if (std::find(v.begin(), v.end(), x) == v.end())
      v.push_back(x);
  }
  std::sort(v.begin(), v.end());
  return v;
}

} // namespace

TEST_CASE("the touched faces of a 2-3 or 3-2 flip are every face of its group once, in canonical order",
          "[kinetic][triangulation]") {
  const std::uint64_t seed = GENERATE(11, 12, 13);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<VertexId> g = random_group(rng, 5, trial % 3 == 0);
    std::vector<VertexId> order = g;
    std::shuffle(order.begin(), order.end(), rng);
    // Facet abc with apices p, q: tetrahedra abcp, abcq become abpq, bcpq, capq.
    const VertexId a = order[0], b = order[1], c = order[2], p = order[3], q = order[4];
    const std::vector<Simplex> two{{a, b, c, p}, {a, b, c, q}};
    const std::vector<Simplex> three{{a, b, p, q}, {b, c, p, q}, {c, a, p, q}};
    require_matches_oracle(two, three);
    require_matches_oracle(three, two);
  }
}

TEST_CASE("the touched faces of a planar 2-2 flip are every face of its quadrilateral once",
          "[kinetic][triangulation]") {
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<VertexId> g = random_group(rng, 4, trial % 4 == 0);
    std::vector<VertexId> o = g;
    std::shuffle(o.begin(), o.end(), rng);
    require_matches_oracle({{o[0], o[1], o[2]}, {o[0], o[1], o[3]}},
                           {{o[2], o[3], o[0]}, {o[2], o[3], o[1]}});
  }
}

TEST_CASE("the touched faces of a change spanning many vertices are sorted and merged",
          "[kinetic][triangulation]") {
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 50; ++trial) {
    // Unrelated tetrahedra over more than six vertices: the sorted path, with shared faces merged.
    std::vector<Simplex> removed, added;
    for (int k = 0; k < 4; ++k) {
      const std::vector<VertexId> v = random_group(rng, 4, trial % 2 == 0 && k == 0);
      (k % 2 == 0 ? removed : added).push_back(Simplex{v[0], v[1], v[2], v[3]});
    }
    removed.push_back(added.front()); // a top simplex removed and added: its faces' deltas cancel
    require_matches_oracle(removed, added);
  }
}

TEST_CASE("every touched face and each of its facets are found among the touched faces, nothing else is",
          "[kinetic][triangulation]") {
  // The engine looks the facets of a touched face up here (apply_tet_change): by bit mask over a
  // flip's vertices, by binary search for larger changes.
  const std::uint64_t seed = GENERATE(41, 42);
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Simplex> removed, added;
    if (trial % 2 == 0) {
      const std::vector<VertexId> g = random_group(rng, 5, trial % 3 == 0);
      removed = {{g[0], g[1], g[2], g[3]}, {g[0], g[1], g[2], g[4]}};
      added = {{g[0], g[1], g[3], g[4]}, {g[1], g[2], g[3], g[4]}, {g[0], g[2], g[3], g[4]}};
    } else {
      for (int k = 0; k < 4; ++k) {
        const std::vector<VertexId> v = random_group(rng, 4, false);
        (k % 2 == 0 ? removed : added).push_back(Simplex{v[0], v[1], v[2], v[3]});
      }
    }
    TouchedFaces got;
    collect_touched_faces(removed, added, got);
    REQUIRE(!got.faces.empty());
    for (TouchedFace& t : got.faces) {
      CAPTURE(t.face);
      REQUIRE(got.find(t.face) == &t);
      if (t.face.size() > 1)
        for (std::size_t i = 0; i < t.face.size(); ++i)
          REQUIRE(got.find(t.face.facet(i)) != nullptr);
    }
    // Vertex ids are at most 40 (random_group): these are held by no changed top simplex.
    REQUIRE(got.find(Simplex{41}) == nullptr);
    REQUIRE(got.find(Simplex{41, 42}) == nullptr);
    REQUIRE(got.find(Simplex{41, 42, 43, 44}) == nullptr);
    // Faces through the infinite vertex are not touched faces, even among the flip's vertices.
    if (removed.front()[0] == -1)
      REQUIRE(got.find(Simplex{-1, removed.front()[1]}) == nullptr);
  }
  // Six vertices, two top simplices sharing an edge: a pair or triple of the six held by neither
  // is not touched, though all its vertices are.
  TouchedFaces got;
  collect_touched_faces({Simplex{1, 2, 3, 4}}, {Simplex{3, 4, 5, 6}}, got);
  REQUIRE(got.faces.size() == 2 * 15 - 3);
  REQUIRE(got.find(Simplex{1, 5}) == nullptr);
  REQUIRE(got.find(Simplex{2, 3, 6}) == nullptr);
  REQUIRE(got.find(Simplex{3, 4})->delta == 0);
  REQUIRE(got.find(Simplex{5, 6})->delta == 1);
  REQUIRE(got.find(Simplex{1, 2, 3})->delta == -1);
}
