// Signatures of every time slice by one coned reduction (docs/MATH.md §6.8) against the per-slice
// recomputation of docs/MATH.md §6.6 (libmedusa's signature_of: union-find and matrix ranks).
#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/signatures.h"
#include "medusa/persistence/slice_signatures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>

using namespace medusa;

namespace {

// A random zigzag of simplicial complexes on a few vertices (abstract, dimension <= 3, so every Betti
// number 0..3 occurs), recorded as medusa cells: each maximal presence of a simplex is one cell whose
// facets are the cells of its facets alive at its birth. Some simplices live inside one batch only
// (birth and death at two ranks of the same batch): they lie in no slice.
Medusa random_zigzag(std::mt19937_64& rng, int vertex_count, std::uint64_t batches) {
  Medusa m;
  m.input.frame_times = {};
  for (int v = 0; v < vertex_count; ++v) {
    kinetic::Trajectory t;
    t.type = 1 + v % 2;
    m.input.cells.push_back(t);
  }
  std::map<std::vector<VertexId>, CellId> active;
  auto open = [&](const std::vector<VertexId>& s, std::uint32_t batch, std::uint32_t rank) {
    Cell c;
    c.id = m.cells.size();
    c.vertices = s;
    c.birth = {batch, rank, static_cast<double>(batch)};
    for (std::size_t j = 0; j < s.size() && s.size() > 1; ++j) {
      std::vector<VertexId> facet = s;
      facet.erase(facet.begin() + static_cast<std::ptrdiff_t>(j));
      c.facets.push_back(active.at(facet));
    }
    active[s] = c.id;
    m.cells.push_back(c);
  };
  auto close = [&](const std::vector<VertexId>& s, std::uint32_t batch, std::uint32_t rank) {
    Cell& c = m.cells[active.at(s)];
    c.death = {batch, rank, static_cast<double>(batch)};
    active.erase(s);
  };
  auto has_coface = [&](const std::vector<VertexId>& s) {
    for (const auto& [t, id] : active)
      if (t.size() == s.size() + 1 && std::includes(t.begin(), t.end(), s.begin(), s.end()))
        return true;
    return false;
  };
  auto addable = [&](const std::vector<VertexId>& s) {
    if (active.count(s))
      return false;
    if (s.size() == 1)
      return true;
    for (std::size_t j = 0; j < s.size(); ++j) {
      std::vector<VertexId> facet = s;
      facet.erase(facet.begin() + static_cast<std::ptrdiff_t>(j));
      if (!active.count(facet))
        return false;
    }
    return true;
  };
  std::uniform_int_distribution<int> vertex(0, vertex_count - 1), size(1, 4), coin(0, 9);
  auto random_simplex = [&] {
    std::vector<VertexId> s;
    const int k = size(rng);
    while (static_cast<int>(s.size()) < k) {
      const VertexId v = vertex(rng);
      if (std::find(s.begin(), s.end(), v) == s.end())
        s.push_back(v);
    }
    std::sort(s.begin(), s.end());
    return s;
  };
  for (VertexId v = 0; v < vertex_count; ++v)
    open({v}, 0, 0);
  for (int i = 0; i < 40; ++i) {
    const auto s = random_simplex();
    if (addable(s))
      open(s, 0, 0);
  }
  for (std::uint64_t b = 1; b < batches; ++b) {
    m.batches.push_back({b, 0, 0.0, static_cast<double>(b), false, 3});
    std::uint32_t rank = 1;
    if (b == batches / 3) {
      // The boundary of the 4-simplex on vertices 0..4 (a 3-sphere, b3 = 1), filled in by size.
      for (std::size_t k = 1; k <= 4; ++k)
        for (unsigned mask = 1; mask < 32; ++mask) {
          std::vector<VertexId> s;
          for (VertexId v = 0; v < 5; ++v)
            if (mask & (1u << v))
              s.push_back(v);
          if (s.size() == k && addable(s))
            open(s, b, 1);
        }
      continue;
    }
    for (int op = 0; op < 3; ++op, ++rank) {
      const auto s = random_simplex();
      if (addable(s)) {
        open(s, b, rank);
        if (coin(rng) == 0 && !has_coface(s))
          close(s, b, rank + 1); // lives inside the batch
      } else if (active.count(s) && !has_coface(s)) {
        close(s, b, rank);
      }
    }
  }
  BatchRecord first{0, 0, 0.0, 0.0, true, 0};
  m.batches.insert(m.batches.begin(), first);
  m.end = {static_cast<std::uint32_t>(batches), 0, static_cast<double>(batches)};
  for (const auto& [s, id] : std::map<std::vector<VertexId>, CellId>(active))
    m.cells[id].death = m.end;
  return m;
}

} // namespace

TEST_CASE("one coned reduction gives the signature of every slice of a random zigzag of complexes",
          "[persistence][slice]") {
  constexpr std::uint64_t seed = 20261128;
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  std::size_t slices = 0;
  std::array<std::size_t, 4> nonzero{};
  for (int run = 0; run < 30; ++run) {
    CAPTURE(run);
    const Medusa m = random_zigzag(rng, 5 + run % 4, 60);
    for (std::optional<int> type : {std::optional<int>{}, std::optional<int>{1}, std::optional<int>{2}}) {
      const std::vector<SignatureSample> fast = persistence::signatures_by_reduction(m, type);
      const std::vector<SignatureSample> reference = signatures_over_time(ComplexIndex(m, type));
      REQUIRE(fast.size() == reference.size());
      for (std::size_t s = 0; s < fast.size(); ++s) {
        CAPTURE(s, type.value_or(0));
        CHECK(fast[s].batch == reference[s].batch);
        CHECK(fast[s].before == reference[s].before);
        CHECK(fast[s].signature.f == reference[s].signature.f);
        CHECK(fast[s].signature.euler == reference[s].signature.euler);
        CHECK(fast[s].signature.betti == reference[s].signature.betti);
        for (std::size_t k = 0; k < 4; ++k)
          nonzero[k] += reference[s].signature.betti[k] > 0 ? 1 : 0;
        ++slices;
      }
    }
  }
  REQUIRE(slices == 30 * 3 * 61);
  // The zigzags exercise every degree.
  for (std::size_t k = 0; k < 4; ++k) {
    CAPTURE(k);
    CHECK(nonzero[k] > 0);
  }
}

TEST_CASE("slices out of time order are refused", "[persistence][slice]") {
  Medusa m;
  Cell v;
  v.vertices.push_back(0);
  v.death = {2, 0, 2.0};
  m.cells.push_back(v);
  const std::vector<persistence::SliceBounds> backwards{{2, 2}, {1, 1}};
  CHECK_THROWS_AS(persistence::slice_signatures(m.cells, {}, backwards), medusa::InternalError);
  const std::vector<persistence::SliceBounds> ok{{1, 1}, {2, 2}};
  const std::vector<Signature> s = persistence::slice_signatures(m.cells, {}, ok);
  REQUIRE(s.size() == 2);
  CHECK(s[0].betti[0] == 1);
  CHECK(s[1].betti[0] == 1);
}
