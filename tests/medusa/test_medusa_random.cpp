#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/store_reader.h"
#include "medusa_fixtures.h"
#include "random_stream.h"

#include <catch2/catch.hpp>

#include <map>

using namespace medusa;
using namespace medusa::test;

namespace {
constexpr std::uint64_t first_seed = 20240601;
constexpr int seeds = 60;
} // namespace

TEST_CASE("random consistent streams give cells with d d = 0 and facet lifetimes containing their cofaces'",
          "[medusa][builder][random]") {
  std::map<CellKind, std::size_t> kinds;
  std::size_t checked = 0;
  for (std::uint64_t seed = first_seed; seed < first_seed + seeds; ++seed) {
    CAPTURE(seed);
    const Stream stream = random_stream(seed);
    const Medusa m = collect(stream, 8, 5);
    for (const Cell& c : m.cells) {
      ++kinds[c.kind];
      CAPTURE(c.id, c.vertices);
      REQUIRE(c.facets.size() == (c.vertices.size() == 1 ? 0 : c.vertices.size()));
      std::map<CellId, int> second;
      for (std::size_t i = 0; i < c.facets.size(); ++i) {
        const Cell& f = m.cell(c.facets[i]);
        std::vector<VertexId> face = c.vertices.to_vector();
        face.erase(face.begin() + static_cast<std::ptrdiff_t>(i));
        REQUIRE(f.vertices == face);
        REQUIRE(f.birth <= c.birth);
        REQUIRE(c.death <= f.death);
        for (CellId g : f.facets)
          ++second[g];
      }
      for (const auto& [g, count] : second)
        REQUIRE(count % 2 == 0); // d d = 0 over Z/2
      ++checked;
    }
    REQUIRE_NOTHROW(validate_medusa(m, "seed " + std::to_string(seed)));
  }
  REQUIRE(checked > 0);
  // The generator must exercise every kind of instant cell.
  CHECK(kinds[CellKind::flip] > 0);
  CHECK(kinds[CellKind::join] > 0);
  CHECK(kinds[CellKind::repair] > 0);
}

TEST_CASE("K_t of the medusa equals the complex replayed from the stream at every batch and frame",
          "[medusa][query][random]") {
  for (std::uint64_t seed = first_seed; seed < first_seed + seeds; ++seed) {
    CAPTURE(seed);
    const Stream stream = random_stream(seed);
    const Medusa m = collect(stream, 8, 5);
    const ComplexIndex index(m);
    const auto expected = replay(stream);
    REQUIRE(expected.size() == stream.batches.size() + 1);
    const SimplexSet* previous = nullptr;
    for (const auto& [batch, k] : expected) {
      CAPTURE(batch);
      CHECK(tuples(m, index.after(batch)) == k);
      if (previous)
        CHECK(tuples(m, index.before(batch)) == *previous);
      previous = &k;
    }
    CHECK(tuples(m, index.before(m.end.batch)) == *previous);
    CHECK(index.after(m.end.batch).empty());
    // Frames: frame k > 0 is reached after its frame batch; the last frame is K(t_end-).
    CHECK(tuples(m, index.at_frame(0)) == expected.at(0));
    for (const RecordedBatch& b : stream.batches)
      for (std::size_t k : b.frames_after)
        CHECK(tuples(m, index.at_frame(k)) == expected.at(b.time.batch));
    CHECK(tuples(m, index.at_frame(4)) == *previous);
  }
}
