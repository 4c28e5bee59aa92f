// The flat hash map of the kinetic engine (libkinetic/include/medusa/kinetic/flat_simplex_map.h) against
// std::unordered_map as the oracle, through random insertions, erasures and look-ups.
#include "medusa/kinetic/flat_simplex_map.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <iostream>
#include <random>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

using medusa::kinetic::FiniteKeys;
using medusa::kinetic::FlatSimplexMap;
using medusa::kinetic::Simplex;
using medusa::kinetic::SimplexHash;
using medusa::kinetic::WholeKeys;

namespace {

// Vertices from `lowest` (-1, the infinite vertex, or 0 for finite keys) to `vertices`.
Simplex random_simplex(std::mt19937_64& rng, int vertices, int lowest = -1) {
  std::uniform_int_distribution<int> size(1, 4), vertex(lowest, vertices);
  const int n = size(rng);
  std::int32_t v[4];
  int k = 0;
  while (k < n) {
    std::int32_t x = vertex(rng);
    bool fresh = true;
    for (int i = 0; i < k; ++i)
      fresh = fresh && v[i] != x;
    if (fresh)
      v[k++] = x;
  }
  return Simplex::from_range(v, v + n);
}

// Every key of the oracle is found with its value, and the table holds nothing else.
template <class V, class Keys>
void require_equal(const FlatSimplexMap<V, Keys>& table,
                   const std::unordered_map<Simplex, V, SimplexHash>& oracle) {
  REQUIRE(table.size() == oracle.size());
  for (const auto& kv : oracle) {
    auto it = table.find(kv.first);
    REQUIRE(it != table.end());
    REQUIRE(it->second == kv.second);
  }
  std::size_t visited = 0;
  for (const auto& slot : table) {
    REQUIRE(oracle.count(slot.simplex()) == 1);
    ++visited;
  }
  REQUIRE(visited == oracle.size());
}

} // namespace

// Random insertions, erasures and look-ups on the table and on std::unordered_map, compared at every
// step; value(step) gives the value stored at a step.
template <class V, class Keys = WholeKeys, class Value>
void agree_with_unordered_map(const char* what, Value value) {
  const std::uint64_t seed = std::random_device{}();
  std::cout << what << " seed " << seed << '\n';
  std::mt19937_64 rng(seed);
  const int lowest = std::is_same_v<Keys, FiniteKeys> ? 0 : -1;
  FlatSimplexMap<V, Keys> table;
  std::unordered_map<Simplex, V, SimplexHash> oracle;
  std::uniform_int_distribution<int> op(0, 9);
  // Few vertices, so keys repeat and erasures hit present keys often (backward shifts happen).
  for (int step = 0; step < 200000; ++step) {
    Simplex s = random_simplex(rng, 40, lowest);
    const int o = op(rng);
    if (o < 5) {
      auto [it, fresh] = table.try_emplace(s);
      REQUIRE(fresh == (oracle.count(s) == 0));
      it->second = value(step);
      oracle[s] = value(step);
    } else if (o < 8) {
      REQUIRE(table.erase(s) == oracle.erase(s));
    } else {
      auto it = table.find(s);
      REQUIRE((it != table.end()) == (oracle.count(s) == 1));
      if (it != table.end())
        REQUIRE(it->second == oracle.at(s));
    }
    if (step % 20000 == 0)
      require_equal(table, oracle);
  }
  require_equal(table, oracle);
}

TEST_CASE("the flat simplex map agrees with std::unordered_map through random insertions and erasures") {
  agree_with_unordered_map<int>("flat simplex map", [](int step) { return step; });
}

TEST_CASE("a flat simplex map of finite keys agrees with std::unordered_map through random insertions and "
          "erasures") {
  agree_with_unordered_map<int, FiniteKeys>("flat simplex map of finite keys", [](int step) { return step; });
}

TEST_CASE(
    "a flat simplex map of finite keys holds a slot in 32 bytes and its entries in the order of a map of "
    "whole keys") {
  // The face table (FiniteKeys) is iterated by the engine, whose output must not depend on how keys
  // are stored: the same hash and growth give the same slots.
  struct Value16 {
    std::int64_t a = 0, b = 0;
  };
  static_assert(sizeof(FlatSimplexMap<Value16, FiniteKeys>::Slot) == 32);
  std::mt19937_64 rng(11);
  FlatSimplexMap<int, WholeKeys> whole;
  FlatSimplexMap<int, FiniteKeys> finite;
  for (int i = 0; i < 5000; ++i) {
    const Simplex s = random_simplex(rng, 300, 0);
    whole[s] = i;
    finite[s] = i;
    if (i % 3 == 0) {
      const Simplex gone = random_simplex(rng, 300, 0);
      REQUIRE(whole.erase(gone) == finite.erase(gone));
    }
  }
  REQUIRE(whole.size() > 1000);
  REQUIRE(whole.capacity() == finite.capacity());
  auto w = whole.begin();
  for (const auto& slot : finite) {
    REQUIRE(w != whole.end());
    REQUIRE(slot.simplex() == w->first);
    REQUIRE(slot.second == w->second);
    ++w;
  }
  REQUIRE(w == whole.end());
}

TEST_CASE("a flat simplex map of values that own memory keeps each value whole as growth and erasures move "
          "it") {
  // The medusa builder's records hold their facet lists, on the heap beyond four: a growth moves every
  // value and an erasure's backward shift moves its neighbours (the sanitizers' build checks that no
  // list is lost or freed twice on the way).
  agree_with_unordered_map<std::vector<int>>("flat simplex map of vectors", [](int step) {
    return std::vector<int>(static_cast<std::size_t>(step % 9), step);
  });
}

TEST_CASE("a flat simplex map filled in another table's slot order holds every entry") {
  // Copying in slot order is the case a home function shared between tables would degrade
  // (engine initialisation copies every face this way).
  FlatSimplexMap<int> source;
  std::unordered_map<Simplex, int, SimplexHash> oracle;
  for (std::int32_t a = 0; a < 60; ++a)
    for (std::int32_t b = a + 1; b < 60; ++b)
      for (std::int32_t c = b + 1; c < 60; c += 7) {
        Simplex s{a, b, c};
        source[s] = a * 10000 + b * 100 + c;
        oracle[s] = a * 10000 + b * 100 + c;
      }
  FlatSimplexMap<int> copy;
  for (const auto& slot : source)
    copy.emplace(slot.first, slot.second);
  require_equal(copy, oracle);
  REQUIRE_THROWS(copy.at(Simplex{-1, 0}));
}

TEST_CASE("after reserve, new keys up to the reserved count move no entry of a flat simplex map") {
  // The engine holds pointers to entries while it adds the faces of a change (apply_tet_change).
  std::mt19937_64 rng(7);
  FlatSimplexMap<int> table;
  for (int i = 0; i < 200; ++i)
    table[random_simplex(rng, 100)] = i;
  const std::size_t before = table.size();
  const std::size_t extra = 500; // more than the table's spare room: reserve must grow it
  table.reserve(before + extra);
  std::vector<std::pair<const FlatSimplexMap<int>::Slot*, Simplex>> held;
  for (const auto& slot : table)
    held.emplace_back(&slot, slot.first);
  std::size_t inserted = 0;
  while (inserted < extra)
    if (table.try_emplace(random_simplex(rng, 100)).second)
      ++inserted;
  REQUIRE(table.size() == before + extra);
  for (const auto& [slot, key] : held)
    REQUIRE(slot->first == key);
}

TEST_CASE("a cleared flat simplex map, small or large, holds nothing and takes new entries") {
  // Small tables keep their slots when cleared (the engine's per-batch tables), large ones release them.
  std::mt19937_64 rng(9);
  for (int n : {10, 150, 2000}) {
    CAPTURE(n);
    FlatSimplexMap<int> table;
    std::vector<Simplex> old_keys;
    for (int i = 0; i < n; ++i) {
      const Simplex s = random_simplex(rng, 60);
      table[s] = i;
      old_keys.push_back(s);
    }
    table.clear();
    REQUIRE(table.size() == 0);
    REQUIRE(table.begin() == table.end());
    for (const Simplex& s : old_keys)
      REQUIRE(table.find(s) == table.end());
    std::unordered_map<Simplex, int, SimplexHash> oracle;
    for (int i = 0; i < n; ++i) {
      const Simplex s = random_simplex(rng, 60);
      table[s] = -i;
      oracle[s] = -i;
    }
    require_equal(table, oracle);
  }
}

TEST_CASE("a growing flat simplex map is between half and three quarters full, and a large reservation three "
          "fifths") {
  // Capacities grow by half, not by doubling (flat_simplex_map.h): right after each growth
  // the table is half full, and it grows again only when an insertion would pass three quarters.
  FlatSimplexMap<int> table;
  std::size_t growths = 0, capacity = 0;
  for (int v = 0; v < 100000; ++v) {
    table[Simplex{v, v + 1}] = v;
    if (table.capacity() != capacity) {
      if (capacity != 0) {
        ++growths;
        REQUIRE(table.capacity() == capacity + capacity / 2);
        REQUIRE(2 * table.size() <= table.capacity() + 2);
      }
      capacity = table.capacity();
    }
    REQUIRE(4 * table.size() <= 3 * table.capacity());
  }
  REQUIRE(growths > 10);
  REQUIRE(table.size() == 100000);
  for (int v = 0; v < 100000; v += 997)
    REQUIRE(table.at(Simplex{v, v + 1}) == v);
  FlatSimplexMap<int> reserved;
  reserved.reserve(600000);
  REQUIRE(reserved.capacity() == 1000000);
}
