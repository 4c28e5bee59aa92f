// CellLists, the end-to-end lists of class representatives, against a vector of vectors.
#include "medusa/core/error.h"
#include "medusa/persistence/cell_lists.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using medusa::CellId;
using medusa::persistence::CellLists;
using Oracle = std::vector<std::vector<CellId>>;

namespace {

std::vector<CellId> ids_of(const CellLists& lists) {
  std::vector<CellId> ids;
  lists.for_each_id([&](CellId id) { ids.push_back(id); });
  return ids;
}

std::vector<CellId> concatenated(const Oracle& oracle) {
  std::vector<CellId> ids;
  for (const std::vector<CellId>& list : oracle)
    ids.insert(ids.end(), list.begin(), list.end());
  return ids;
}

void require_same(const CellLists& lists, const Oracle& oracle) {
  REQUIRE(lists.size() == oracle.size());
  REQUIRE(lists.empty() == oracle.empty());
  std::size_t i = 0;
  for (CellLists::List list : lists) {
    REQUIRE(list.to_vector() == oracle[i]);
    REQUIRE(list.size() == oracle[i].size());
    REQUIRE(list == CellLists::List(oracle[i]));
    ++i;
  }
  REQUIRE(i == oracle.size());
  REQUIRE(ids_of(lists) == concatenated(oracle));
  REQUIRE(lists.offsets().size() == oracle.size() + 1);
  REQUIRE(lists.offsets().front() == 0);
  for (std::size_t k = 0; k < oracle.size(); ++k)
    REQUIRE(lists.offsets()[k + 1] - lists.offsets()[k] == oracle[k].size());
}

} // namespace

TEST_CASE("Cell lists hold what a vector of vectors holds through any sequence of edits") {
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    INFO("seed " << seed);
    std::mt19937_64 random(seed);
    CellLists lists;
    Oracle oracle;
    for (int step = 0; step < 80; ++step) {
      const auto roll = random() % 14;
      if (roll < 8) {
        // Mostly short lists, as representatives are; some long ones, so that blocks fill and a list
        // that does not fit the last one starts the next.
        std::vector<CellId> ids(roll == 1 ? random() % 3000 : random() % 6);
        for (CellId& id : ids)
          id = random() % 1000;
        if (roll == 0)
          lists.push_back(ids, [](CellId id) { return id; });
        else
          lists.push_back(ids);
        oracle.push_back(ids);
      } else if (roll < 10 && !oracle.empty()) { // a list of its own, appended to itself
        const std::size_t k = random() % lists.size();
        lists.push_back(lists[k]);
        oracle.push_back(oracle[k]);
      } else if (roll == 10) {
        std::vector<char> keep(oracle.size());
        for (char& k : keep)
          k = random() % 3 != 0;
        lists.keep_if([&](std::size_t i) { return keep[i] != 0; });
        Oracle kept;
        for (std::size_t i = 0; i < oracle.size(); ++i)
          if (keep[i])
            kept.push_back(oracle[i]);
        oracle = kept;
      } else if (roll == 11) { // each list reversed and its ids doubled
        lists.rebuild([](std::size_t, CellLists::List list, CellLists& out) {
          std::vector<CellId> ids(list.begin(), list.end());
          out.push_back(std::vector<CellId>(ids.rbegin(), ids.rend()), [](CellId id) { return 2 * id; });
        });
        for (std::vector<CellId>& ids : oracle) {
          std::reverse(ids.begin(), ids.end());
          for (CellId& id : ids)
            id *= 2;
        }
      } else if (roll == 12) { // through the store's arrays
        lists = CellLists::from_offsets(lists.offsets(), ids_of(lists), "s.h5", "/c");
      } else {
        CellLists moved = std::move(lists);
        REQUIRE(lists.empty());
        lists = std::move(moved);
      }
      require_same(lists, oracle);
    }
  }
}

TEST_CASE("Cell lists with the same offsets and different ids differ") {
  CHECK(CellLists{{1, 2}, {3}} != CellLists{{1, 2}, {4}});
  CHECK(CellLists{{1, 2}, {3}} != CellLists{{1}, {2, 3}});
  CHECK(CellLists{{1, 2}, {}} == CellLists::from_offsets({0, 2, 2}, {1, 2}, "s.h5", "/c"));
}

TEST_CASE("A moved-from cell lists is empty and takes new lists") {
  CellLists lists{{1, 2}, {3}};
  const CellLists moved = std::move(lists);
  CHECK(moved.size() == 2);
  CHECK(lists.empty());
  CHECK(lists.offsets() == std::vector<std::uint64_t>{0});
  lists.push_back({7});
  CHECK(lists == CellLists{{7}});
}

TEST_CASE("A list whose ids fail to convert leaves the lists as they were") {
  CellLists lists{{1, 2}};
  const std::vector<CellId> ids = {3, 4, 5};
  const auto fail_at_5 = [](CellId id) {
    if (id == 5)
      throw medusa::InputError("no id 5");
    return id;
  };
  CHECK_THROWS_AS(lists.push_back(ids, fail_at_5), medusa::InputError);
  CHECK(lists == CellLists{{1, 2}});
  CellLists fresh; // the failed list would have opened the first block
  CHECK_THROWS_AS(fresh.push_back(ids, fail_at_5), medusa::InputError);
  CHECK(fresh.empty());
  fresh.push_back({9});
  lists.push_back({9});
  CHECK(fresh == CellLists{{9}});
  CHECK(lists == CellLists{{1, 2}, {9}});
}

TEST_CASE("A rebuild that throws leaves the cell lists empty, not half let go") {
  CellLists lists;
  for (CellId k = 0; k < 2000; ++k)
    lists.push_back({k, k + 1, k + 2});
  CHECK_THROWS_AS(lists.rebuild([](std::size_t i, CellLists::List list, CellLists& out) {
    if (i == 1500)
      throw medusa::InputError("stop");
    out.push_back(list);
  }),
                  medusa::InputError);
  CHECK(lists.empty());
  CHECK(lists.offsets() == std::vector<std::uint64_t>{0});
}

TEST_CASE(
    "Cell lists from a store are refused unless their offsets start at zero, ascend and end at the ids") {
  const std::vector<CellId> ids = {4, 5, 6};
  CHECK(CellLists::from_offsets({0, 2, 2, 3}, ids, "s.h5", "/c") == CellLists{{4, 5}, {}, {6}});
  CHECK_THROWS_AS(CellLists::from_offsets({}, {}, "s.h5", "/c"), medusa::StoreError);
  CHECK_THROWS_AS(CellLists::from_offsets({1, 3}, ids, "s.h5", "/c"), medusa::StoreError);
  CHECK_THROWS_AS(CellLists::from_offsets({0, 2, 1, 3}, ids, "s.h5", "/c"), medusa::StoreError);
  CHECK_THROWS_AS(CellLists::from_offsets({0, 2}, ids, "s.h5", "/c"), medusa::StoreError);
  CHECK_THROWS_AS(CellLists::from_offsets({0, 4}, ids, "s.h5", "/c"), medusa::StoreError);
}

TEST_CASE("A cell list asked for past the last one is an internal error, not a read past the end") {
  const CellLists lists{{1}, {2, 3}};
  CHECK(lists.at(1).to_vector() == std::vector<CellId>{2, 3});
  CHECK_THROWS_AS(lists.at(2), medusa::InternalError);
}

TEST_CASE("Appending to cell lists never moves the lists already held, however long") {
  CellLists lists;
  lists.push_back({1, 2, 3});
  const CellId* first = lists[0].begin();
  std::vector<CellId> longest((std::size_t{1} << 20) + 5);
  for (std::size_t k = 0; k < longest.size(); ++k)
    longest[k] = k;
  lists.push_back(longest);
  const CellId* second = lists[1].begin();
  for (CellId k = 0; k < 5000; ++k)
    lists.push_back({k, k + 1});
  CHECK(lists[0].begin() == first);
  CHECK(lists[1].begin() == second);
  CHECK(lists[0].to_vector() == std::vector<CellId>{1, 2, 3});
  CHECK(lists[1].to_vector() == longest);
  CHECK(lists[5001].to_vector() == std::vector<CellId>{4999, 5000});
  CHECK(lists.offsets().back() == 3 + longest.size() + 2 * 5000);
}
