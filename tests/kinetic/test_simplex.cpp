#include "medusa/kinetic/simplex.h"

#include <catch2/catch.hpp>

#include <unordered_set>

using medusa::kinetic::Simplex;

TEST_CASE("a simplex sorts its vertices and knows its dimension", "[kinetic][simplex]") {
  Simplex s{7, 2, 5};
  REQUIRE(s.dim() == 2);
  REQUIRE(s[0] == 2);
  REQUIRE(s[1] == 5);
  REQUIRE(s[2] == 7);
  REQUIRE(s == Simplex{5, 7, 2});
}

TEST_CASE("a simplex made from vertices already sorted equals the one that sorts them, of every size",
          "[kinetic][simplex]") {
  REQUIRE(Simplex::from_sorted({-1, 4, 8, 9}, 4) == Simplex{9, 8, 4, -1});
  REQUIRE(Simplex::from_sorted({2, 5, 7, -1}, 3) == Simplex{7, 2, 5});
  REQUIRE(Simplex::from_sorted({3, 6, -1, -1}, 2) == Simplex{6, 3});
  REQUIRE(Simplex::from_sorted({0, -1, -1, -1}, 1) == Simplex{0});
  REQUIRE(Simplex::from_sorted({3, 6, -1, -1}, 2).dim() == 1);
  REQUIRE_FALSE(Simplex::from_sorted({3, 6, -1, -1}, 2) == Simplex{3, 6, 7});
}

TEST_CASE("the facets of a tetrahedron are its four triangles", "[kinetic][simplex]") {
  Simplex t{0, 1, 2, 3};
  REQUIRE(t.facet(0) == Simplex{1, 2, 3});
  REQUIRE(t.facet(1) == Simplex{0, 2, 3});
  REQUIRE(t.facet(2) == Simplex{0, 1, 3});
  REQUIRE(t.facet(3) == Simplex{0, 1, 2});
}

TEST_CASE("a simplex with one more vertex keeps its vertices sorted, the infinite vertex first",
          "[kinetic][simplex]") {
  REQUIRE(Simplex{2, 5}.with(-1) == Simplex{-1, 2, 5});
  REQUIRE(Simplex{2, 5}.with(-1)[0] == -1);
  REQUIRE(Simplex{2, 5}.with(3)[1] == 3);
  REQUIRE(Simplex{2, 5}.with(9) == Simplex{2, 5, 9});
  REQUIRE(Simplex{1, 4, 8}.with(0) == Simplex{0, 1, 4, 8});
  REQUIRE(Simplex{1, 4, 8}.with(0).dim() == 3);
  REQUIRE(Simplex{}.with(7) == Simplex{7});
}

TEST_CASE("simplices order by dimension first, then lexicographically", "[kinetic][simplex]") {
  REQUIRE(Simplex{9} < Simplex{0, 1});
  REQUIRE(Simplex{0, 5} < Simplex{1, 2});
  REQUIRE_FALSE(Simplex{1, 2} < Simplex{0, 5});
}

TEST_CASE("equal simplices hash equally and distinct ones are kept apart", "[kinetic][simplex]") {
  std::unordered_set<Simplex, medusa::kinetic::SimplexHash> set;
  set.insert(Simplex{1, 2, 3});
  set.insert(Simplex{3, 2, 1});
  set.insert(Simplex{1, 2});
  REQUIRE(set.size() == 2);
}
