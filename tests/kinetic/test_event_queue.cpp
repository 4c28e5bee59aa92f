// EventQueue (the engine's queue of failure times) pops its entries in exact time order, each once,
// whatever the interleaving of pushes and pops: checked against a sorted oracle of rationals, with
// equal times of different representations (1/3 and 2/6) and times whose enclosures overlap.
#include "event_queue.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

TEST_CASE("the event queue pops its entries in exact time order, each once, through pushes and pops",
          "[kinetic][queue]") {
  const unsigned seed = std::random_device{}();
  CAPTURE(seed);
  std::mt19937 rng(seed);
  EventQueue queue;
  std::set<std::pair<Rational, std::uint32_t>> oracle; // (time, certificate id)
  std::uint32_t next = 0;
  int popped = 0, ties = 0;
  Rational last(-1);
  for (int step = 0; step < 20000; ++step) {
    if (oracle.empty() || rng() % 3 != 0) {
      // Times k/d with small d: many equal values under different fractions, and non-dyadic ones
      // whose enclosures (adjacent doubles) overlap those of their equals. Never earlier than the
      // last popped time, as in a slab.
      const int d = 1 + static_cast<int>(rng() % 12);
      const int k = static_cast<int>(rng() % static_cast<unsigned>(d + 1));
      Rational u(k, d);
      if (u < last)
        u = last;
      queue.push({SlabTime(u), next, 7});
      oracle.insert({u, next});
      ++next;
    } else {
      REQUIRE(!queue.empty());
      const QueueEntry& e = queue.top();
      REQUIRE(e.version == 7u);
      const Rational earliest = oracle.begin()->first;
      REQUIRE(compare(e.u, SlabTime(earliest)) == 0);
      const auto it = oracle.find({earliest, e.cert});
      REQUIRE(it != oracle.end()); // popped once: its id leaves the oracle
      ties += std::next(oracle.begin()) != oracle.end() && std::next(oracle.begin())->first == earliest;
      oracle.erase(it);
      last = earliest;
      queue.pop();
      ++popped;
    }
    REQUIRE(queue.size() == oracle.size());
  }
  while (!queue.empty()) {
    REQUIRE(compare(queue.top().u, SlabTime(oracle.begin()->first)) == 0);
    REQUIRE(oracle.erase({oracle.begin()->first, queue.top().cert}) == 1);
    queue.pop();
  }
  REQUIRE(oracle.empty());
  // A pop is drawn with probability 1/3 per step: about 6,667 of 20,000 (standard deviation 67; 6,597-6,760
  // in five runs). Times k/d with d <= 12 repeat, so nearly every pop meets an equal time waiting (6,592-
  // 6,731 in the same runs). The bounds only guard against a loop that stopped exercising the queue.
  REQUIRE(popped > 1000);
  REQUIRE(ties > 100); // equal times were met while others waited
  queue.push({SlabTime(Rational(1, 2)), 1, 1});
  queue.clear();
  REQUIRE(queue.empty());
}

TEST_CASE("a time whose enclosure spans many buckets leaves the queue in exact order among the times "
          "inside it",
          "[kinetic][queue]") {
  // u = 1/sqrt(2) = 0.70710..., the root of 2u^2 - 1, isolated only in (0.70, 0.72): twenty buckets of
  // 1/1024. Rationals on either side of it, inside and outside that interval, are queued around it.
  auto root = make_isolated_root([] { return ExactPoly(CGAL::Gmpz(-1), CGAL::Gmpz(0), CGAL::Gmpz(2)); });
  const IntervalPoly u(Interval(0), Interval(1));
  root->enclosure = IntervalPoly(Interval(2)) * u * u + IntervalPoly(Interval(-1));
  root->lo = 0.70;
  root->hi = 0.72;
  root->clear_hi = 0.72;
  root->sign_lo = -1;
  const std::vector<std::pair<Rational, std::uint32_t>> times = {
      {Rational(73, 100), 6},   {Rational(7071, 10000), 3}, {Rational(69, 100), 1},
      {Rational(719, 1000), 5}, {Rational(703, 1000), 2},   {Rational(7072, 10000), 4}};
  EventQueue queue;
  queue.push({SlabTime(std::shared_ptr<IsolatedRoot>(root)), 0, 1});
  for (const auto& [u, id] : times)
    queue.push({SlabTime(u), id, 1});
  REQUIRE(queue.first_violation().empty());
  // 0.69 < 0.703 < 0.7071 < 1/sqrt(2) < 0.7072 < 0.719 < 0.73: the root is id 0, between 3 and 4.
  const std::vector<std::uint32_t> expected = {1, 2, 3, 0, 4, 5, 6};
  std::vector<std::uint32_t> popped;
  while (!queue.empty()) {
    popped.push_back(queue.top().cert);
    queue.pop();
    REQUIRE(queue.first_violation().empty());
  }
  REQUIRE(popped == expected);
}
