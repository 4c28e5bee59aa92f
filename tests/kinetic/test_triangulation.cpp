// Triangulation (the engine's combinatorial Del) keeps no table of its top simplices: presence and
// the iteration over them are read off the facets' apices. Checked against a std::set oracle under
// random additions and removals, as is the certificate id each facet carries.
#include "medusa/core/error.h"
#include "triangulation.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

namespace {

// True when every facet of t has fewer than two top simplices in `present`.
bool fits(const Simplex& t, const Triangulation& tri) {
  for (std::size_t i = 0; i < t.size(); ++i)
    if (const Triangulation::Apices* a = tri.apices(t.facet(i)); a != nullptr && a->count == 2)
      return false;
  return true;
}

Simplex random_simplex(std::mt19937& rng, std::size_t size, bool allow_infinite) {
  std::uniform_int_distribution<VertexId> vertex(allow_infinite ? -1 : 0, 11);
  std::array<VertexId, 4> v{};
  std::size_t n = 0;
  while (n < size) {
    const VertexId x = vertex(rng);
    if (std::find(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), x) ==
        v.begin() + static_cast<std::ptrdiff_t>(n))
      v[n++] = x;
  }
  return Simplex::from_range(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n));
}

void require_matches(const Triangulation& tri, const std::set<Simplex>& oracle) {
  std::vector<Simplex> listed;
  for (const Simplex& t : tri.tops())
    listed.push_back(t);
  std::sort(listed.begin(), listed.end());
  REQUIRE(listed == std::vector<Simplex>(oracle.begin(), oracle.end())); // each once, nothing else
  REQUIRE(tri.tops().size() == oracle.size());
  for (const Simplex& t : oracle)
    REQUIRE(tri.has_top(t));
}

} // namespace

TEST_CASE("top simplices are found and listed from their facets alone, each once",
          "[kinetic][triangulation]") {
  const unsigned seed = GENERATE(21u, 22u, 23u);
  std::mt19937 rng(seed);
  for (const std::size_t size : {std::size_t{3}, std::size_t{4}}) {
    CAPTURE(seed, size);
    Triangulation tri;
    std::set<Simplex> oracle;
    for (int step = 0; step < 3000; ++step) {
      const Simplex t = random_simplex(rng, size, true);
      const bool present = oracle.count(t) != 0;
      REQUIRE(tri.has_top(t) == present);
      if (present && rng() % 2 == 0) {
        REQUIRE_THROWS_AS(tri.add_top(t, is_finite(t) ? 1 : 0), medusa::InternalError);
        std::vector<int> dropped;
        tri.remove_top(t, dropped);
        REQUIRE(dropped.empty()); // no facet here carries a certificate
        oracle.erase(t);
      } else if (!present && rng() % 3 == 0) {
        std::vector<int> dropped;
        REQUIRE_THROWS_AS(tri.remove_top(t, dropped), medusa::InternalError);
      } else if (!present && fits(t, tri)) {
        tri.add_top(t, is_finite(t) ? 1 : 0);
        oracle.insert(t);
      }
      if (step % 250 == 0)
        require_matches(tri, oracle);
    }
    REQUIRE(oracle.size() > 20); // the walk did build something to list
    require_matches(tri, oracle);
  }
}

TEST_CASE("a facet's certificate id is handed back when its last top simplex goes, and only then",
          "[kinetic][triangulation]") {
  const unsigned seed = GENERATE(31u, 32u);
  std::mt19937 rng(seed);
  for (const std::size_t size : {std::size_t{3}, std::size_t{4}}) {
    CAPTURE(seed, size);
    Triangulation tri;
    std::set<Simplex> tops;
    std::map<Simplex, int> cert_of; // the oracle: the id given to each facet present
    int next_id = 0, handed_back = 0;
    for (int step = 0; step < 3000; ++step) {
      const Simplex t = random_simplex(rng, size, true);
      if (tops.count(t) != 0) {
        // The facets of t that no other top simplex holds go, with their ids.
        std::vector<int> expected;
        for (std::size_t i = 0; i < t.size(); ++i) {
          const Simplex f = t.facet(i);
          const bool shared = std::any_of(tops.begin(), tops.end(), [&](const Simplex& u) {
            return u != t && std::includes(u.begin(), u.end(), f.begin(), f.end());
          });
          if (!shared) {
            expected.push_back(cert_of.at(f));
            cert_of.erase(f);
          }
        }
        std::vector<int> dropped;
        tri.remove_top(t, dropped);
        tops.erase(t);
        std::sort(expected.begin(), expected.end());
        std::sort(dropped.begin(), dropped.end());
        REQUIRE(dropped == expected);
        handed_back += static_cast<int>(dropped.size());
      } else if (fits(t, tri)) {
        tri.add_top(t, is_finite(t) ? 1 : 0);
        tops.insert(t);
        for (std::size_t i = 0; i < t.size(); ++i) {
          Triangulation::Apices* a = tri.apices(t.facet(i));
          REQUIRE(a != nullptr);
          if (a->cert < 0) {
            REQUIRE(cert_of.count(t.facet(i)) == 0); // a new record starts without one
            a->cert = next_id;
            cert_of[t.facet(i)] = next_id++;
          }
        }
      }
      // Facets that stay keep their ids.
      if (step % 100 == 0)
        for (const auto& [f, id] : cert_of)
          REQUIRE(tri.apices(f)->cert == id);
    }
    REQUIRE(handed_back > 20); // the walk did remove facets
  }
}

namespace {

// The augmented triangulation of one top simplex: it and the infinite vertex joined to each facet.
void add_augmented_simplex(Triangulation& tri, const Simplex& t) {
  tri.add_top(t, 1);
  for (std::size_t i = 0; i < t.size(); ++i)
    tri.add_top(t.facet(i).with(infinite_vertex), 0);
}

} // namespace

TEST_CASE("the triangulation's own check accepts an augmented sphere and names what a broken one lacks",
          "[kinetic][triangulation]") {
  for (const Simplex& top : {Simplex{0, 1, 2}, Simplex{0, 1, 2, 3}}) {
    const int dimension = static_cast<int>(top.size()) - 1;
    CAPTURE(dimension);
    Triangulation tri;
    add_augmented_simplex(tri, top);
    REQUIRE(tri.first_violation(dimension).empty());

    // One infinite top simplex less: its facets have one top simplex each.
    std::vector<int> dropped;
    tri.remove_top(top.facet(0).with(infinite_vertex), dropped);
    REQUIRE(tri.first_violation(dimension).find("not two") != std::string::npos);

    // A finite top simplex recorded without an orientation.
    Triangulation flat;
    flat.add_top(top, 0);
    for (std::size_t i = 0; i < top.size(); ++i)
      flat.add_top(top.facet(i).with(infinite_vertex), 0);
    REQUIRE(flat.first_violation(dimension).find("orientation") != std::string::npos);

    // Two spheres sharing only the infinite vertex: every facet has two top simplices, but
    // V - E + F - T (V - E + T in the plane) is one off a sphere's.
    Triangulation two;
    add_augmented_simplex(two, top);
    std::vector<VertexId> shifted(top.begin(), top.end());
    for (VertexId& v : shifted)
      v += 10;
    add_augmented_simplex(two, Simplex::from_range(shifted.begin(), shifted.end()));
    REQUIRE(two.first_violation(dimension).find("Euler") != std::string::npos);
  }
}
