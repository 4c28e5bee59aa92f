// CertificatePool (the engine's certificates and their failure times): under random creations,
// retirements, whole-frame retirements, schedules and pops, the earliest current time it gives is
// the one a brute-force model of the same operations gives, stale entries are never given, and its
// own invariant check holds throughout; a reissued id forgets the cell its facet was in.
#include "certificate_pool.h"
#include "medusa/core/error.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

TEST_CASE("the certificate pool gives exactly the current failure times, earliest first", "[kinetic][pool]") {
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  CertificatePool pool;
  std::map<int, std::uint32_t> alive;                             // model: id -> version of the alive ones
  std::multiset<std::tuple<Rational, int, std::uint32_t>> queued; // model: every entry scheduled
  const auto current_in_model = [&](int id, std::uint32_t version) {
    auto it = alive.find(id);
    return it != alive.end() && it->second == version;
  };
  Rational last(0);
  int popped = 0, stale_skipped = 0, frames = 0;
  for (int step = 0; step < 20000; ++step) {
    const unsigned op = rng() % 20;
    if (op < 6 || alive.empty()) {
      const int id = pool.create(CertKind::radius, Simplex{0, 1});
      REQUIRE(alive.count(id) == 0);
      alive[id] = pool[id].version;
    } else if (op < 9) {
      auto it = std::next(alive.begin(), static_cast<std::ptrdiff_t>(rng() % alive.size()));
      const int id = it->first;
      pool.retire(id);
      REQUIRE_THROWS_AS(pool.retire(id), medusa::InternalError);
      alive.erase(it);
    } else if (op < 15) {
      auto it = std::next(alive.begin(), static_cast<std::ptrdiff_t>(rng() % alive.size()));
      const int d = 1 + static_cast<int>(rng() % 12);
      Rational u(static_cast<int>(rng() % static_cast<unsigned>(d + 1)), d);
      if (u < last)
        u = last;
      pool.schedule(it->first, SlabTime(u));
      queued.insert({u, it->first, it->second});
    } else if (op < 19) {
      // The model's earliest current entry, its stale ones in front dropped as the pool drops them.
      while (!queued.empty() &&
             !current_in_model(std::get<1>(*queued.begin()), std::get<2>(*queued.begin()))) {
        queued.erase(queued.begin());
        ++stale_skipped;
      }
      const QueueEntry* e = pool.earliest();
      REQUIRE((e == nullptr) == queued.empty());
      if (e == nullptr)
        continue;
      REQUIRE(pool.current(*e));
      const Rational earliest = std::get<0>(*queued.begin());
      REQUIRE(compare(e->u, SlabTime(earliest)) == 0);
      const auto given = queued.find({earliest, static_cast<int>(e->cert), e->version});
      REQUIRE(given != queued.end()); // one of the model's earliest current entries
      queued.erase(given);
      last = earliest;
      pool.pop();
      ++popped;
    } else {
      // A frame: every certificate dies, and ids come back from 0 up.
      pool.retire_all();
      pool.clear_times();
      alive.clear();
      queued.clear();
      last = Rational(0);
      ++frames;
      REQUIRE(pool.create(CertKind::delaunay, Simplex{0, 1, 2}) == 0);
      REQUIRE(pool.create(CertKind::delaunay, Simplex{0, 1, 3}) == 1);
      alive[0] = pool[0].version;
      alive[1] = pool[1].version;
    }
    REQUIRE(pool.alive_count(CertKind::radius) + pool.alive_count(CertKind::delaunay) == alive.size());
    if (step % 97 == 0)
      REQUIRE(pool.first_violation().empty());
  }
  REQUIRE(pool.first_violation().empty());
  // Each bound only guards against a walk that stopped exercising the pool: about 4,000 pops, 3,000
  // retirements and 1,000 frames are drawn in 20,000 steps.
  REQUIRE(popped > 1000);
  REQUIRE(stale_skipped > 100);
  REQUIRE(frames > 100);
}

TEST_CASE("a retired certificate's queued time is never given, even when its id is reissued",
          "[kinetic][pool]") {
  CertificatePool pool;
  const int a = pool.create(CertKind::radius, Simplex{0, 1});
  pool.schedule(a, SlabTime(Rational(1, 4)));
  pool.retire(a);
  const int b = pool.create(CertKind::radius, Simplex{2, 3});
  REQUIRE(b == a); // the id is recycled, under a new version
  pool.schedule(b, SlabTime(Rational(1, 2)));
  const QueueEntry* e = pool.earliest();
  REQUIRE(e != nullptr);
  REQUIRE(compare(e->u, SlabTime(Rational(1, 2))) == 0);
  REQUIRE(pool[static_cast<int>(e->cert)].key == Simplex{2, 3});
  REQUIRE(compare(pool.next_time_after(SlabTime(Rational(1, 2)), SlabTime(Rational(1))),
                  SlabTime(Rational(1))) == 0);
  pool.pop();
  REQUIRE(pool.earliest() == nullptr);
  REQUIRE(pool.first_violation().empty());
}

TEST_CASE("a reissued certificate id names no cell until its facet's cell is set again", "[kinetic][pool]") {
  CertificatePool pool;
  const int id = pool.create(CertKind::delaunay, Simplex{0, 1, 2});
  CHECK(pool[id].cell == -1);
  pool.set_cell(id, 41, 3);
  CHECK(pool[id].cell == 41);
  CHECK(pool[id].facet_index == 3);
  CHECK(pool[id].key == (Simplex{0, 1, 2}));
  pool.retire(id);
  const int again = pool.create(CertKind::delaunay, Simplex{1, 2, 3});
  REQUIRE(again == id);
  CHECK(pool[again].cell == -1);
  CHECK(pool[again].facet_index == 0);
  CHECK(pool[again].key == (Simplex{1, 2, 3}));
}
