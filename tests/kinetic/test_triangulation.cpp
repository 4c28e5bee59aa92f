// Triangulation (the engine's combinatorial Del) keeps no table of its top simplices: presence and
// the iteration over them are read off the facets' apices. Checked against a std::set oracle under
// random additions and removals.
#include "medusa/kinetic/error.h"
#include "triangulation.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
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
  for (const Simplex& t : tri.tets())
    listed.push_back(t);
  std::sort(listed.begin(), listed.end());
  REQUIRE(listed == std::vector<Simplex>(oracle.begin(), oracle.end())); // each once, nothing else
  REQUIRE(tri.tets().size() == oracle.size());
  for (const Simplex& t : oracle)
    REQUIRE(tri.has_tet(t));
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
      REQUIRE(tri.has_tet(t) == present);
      if (present && rng() % 2 == 0) {
        REQUIRE_THROWS_AS(tri.add_tet(t, is_finite(t) ? 1 : 0), medusa::InternalError);
        tri.remove_tet(t);
        oracle.erase(t);
      } else if (!present && rng() % 3 == 0) {
        REQUIRE_THROWS_AS(tri.remove_tet(t), medusa::InternalError);
      } else if (!present && fits(t, tri)) {
        tri.add_tet(t, is_finite(t) ? 1 : 0);
        oracle.insert(t);
      }
      if (step % 250 == 0)
        require_matches(tri, oracle);
    }
    REQUIRE(oracle.size() > 20); // the walk did build something to list
    require_matches(tri, oracle);
  }
}
