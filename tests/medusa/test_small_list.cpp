// SmallList, the in-place list of a medusa cell's vertices and facets, against std::vector.
#include "medusa/medusa/cell.h"
#include "medusa/medusa/small_list.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace {

using medusa::SmallList;
using List = SmallList<std::int32_t, 4>;

void require_same(const List& list, const std::vector<std::int32_t>& oracle) {
  REQUIRE(list.size() == oracle.size());
  REQUIRE(list.empty() == oracle.empty());
  REQUIRE(list.to_vector() == oracle);
  REQUIRE(list == oracle);
  REQUIRE(list.is_inline() == (list.capacity() == 4));
  REQUIRE(list.capacity() >= list.size());
}

} // namespace

TEST_CASE("a small list holds what a vector holds through any sequence of edits", "[small_list]") {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    INFO("seed " << seed);
    std::mt19937_64 rng(seed);
    const auto below = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    List list;
    std::vector<std::int32_t> oracle;
    bool went_to_heap = false;
    for (int step = 0; step < 60; ++step) {
      switch (below(8)) {
      case 0:
      case 1:
      case 2: {
        const std::int32_t v = below(1000);
        list.push_back(v);
        oracle.push_back(v);
        break;
      }
      case 3:
        if (!oracle.empty()) {
          list.pop_back();
          oracle.pop_back();
        }
        break;
      case 4: {
        const auto n = static_cast<std::size_t>(below(12));
        list.resize(n);
        oracle.resize(n);
        break;
      }
      case 5: {
        std::vector<std::int32_t> values(static_cast<std::size_t>(below(10)));
        for (auto& v : values)
          v = below(1000);
        list.assign(values.begin(), values.end());
        oracle = values;
        break;
      }
      case 6: { // a copy is equal, then independent of its source
        List copy = list;
        require_same(copy, oracle);
        copy.push_back(-1);
        require_same(list, oracle);
        list = copy;
        oracle.push_back(-1);
        break;
      }
      default: { // a move takes the values and leaves the source empty and in place
        List moved = std::move(list);
        require_same(moved, oracle);
        REQUIRE(list.empty()); // NOLINT(bugprone-use-after-move): the moved-from state is specified
        REQUIRE(list.is_inline());
        list = std::move(moved);
        break;
      }
      }
      went_to_heap = went_to_heap || !list.is_inline();
      require_same(list, oracle);
    }
    if (seed == 1)
      REQUIRE(went_to_heap);
  }
}

TEST_CASE("a small list keeps up to its capacity in place and moves to the heap beyond", "[small_list]") {
  List list{1, 2, 3, 4};
  REQUIRE(list.is_inline());
  list.push_back(list.front()); // an element of the list itself, pushed as the list grows
  REQUIRE_FALSE(list.is_inline());
  REQUIRE(list == std::vector<std::int32_t>{1, 2, 3, 4, 1});
  list.push_back(list.back());
  REQUIRE(list == std::vector<std::int32_t>{1, 2, 3, 4, 1, 1});
  List small{7, 8};
  list = small;
  REQUIRE(list == small);
  REQUIRE(list.capacity() > 4); // a heap block, once made, is kept
  list = List{};
  REQUIRE(list.empty());
}

TEST_CASE("small lists compare as their values do", "[small_list]") {
  REQUIRE(List{1, 2} == List{1, 2});
  REQUIRE(List{1, 2} != List{1, 2, 3});
  REQUIRE(List{1, 2} < List{1, 2, 3});
  REQUIRE(List{1, 2, 3, 4, 5} < List{1, 3});
  REQUIRE_FALSE(List{1, 3} < List{1, 2, 3, 4, 5});
  REQUIRE(List{} < List{0});
}

TEST_CASE("a medusa cell up to a tetrahedron allocates nothing", "[small_list]") {
  medusa::Cell cell;
  cell.vertices = {0, 1, 2, 3};
  cell.facets = {4, 5, 6, 7};
  REQUIRE(cell.vertices.is_inline());
  REQUIRE(cell.facets.is_inline());
  REQUIRE(cell.dim() == 3);
  medusa::Cell flip = cell;
  flip.vertices.push_back(8);
  flip.facets.push_back(9);
  REQUIRE(flip.dim() == 4);
  REQUIRE_FALSE(flip.vertices.is_inline());
  REQUIRE(cell.vertices == medusa::CellVertices{0, 1, 2, 3});
}
