// BatchAgenda (what a batch still has to resolve): Delaunay failures come back in canonical order,
// stale ones dropped, and none once a repair is due; radius failures and touches in the order
// found, with failures found meanwhile kept for the next round; the times of the batch; and its own
// check, which catches a failure held for a retired certificate and anything left between batches.
#include "batch_agenda.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

TEST_CASE("Delaunay failures are taken in canonical order, and stale ones are dropped on the way",
          "[kinetic][agenda]") {
  CertificatePool pool;
  const int a = pool.create(CertKind::delaunay, Simplex{1, 2, 3});
  const int b = pool.create(CertKind::delaunay, Simplex{0, 2, 3});
  const int c = pool.create(CertKind::delaunay, Simplex{0, 1, 3});
  BatchAgenda agenda;
  agenda.fail_delaunay(Simplex{1, 2, 3}, a);
  agenda.fail_delaunay(Simplex{0, 2, 3}, b);
  agenda.fail_delaunay(Simplex{0, 1, 3}, c);
  pool.retire(c); // c went stale without being withdrawn
  std::vector<int> offered;
  auto accept = [&](const Simplex&, int id) {
    offered.push_back(id);
    return id == a;
  };
  const auto taken = agenda.take_first_delaunay(pool, accept);
  REQUIRE(taken);
  CHECK(taken->second == a);
  CHECK(taken->first == Simplex{1, 2, 3});
  CHECK(offered == std::vector<int>{b, a}); // {0 1 3} first, but stale: dropped unoffered
  CHECK(agenda.delaunay_failed(Simplex{0, 2, 3}, b));
  CHECK_FALSE(agenda.delaunay_failed(Simplex{0, 1, 3}, c));
  CHECK_FALSE(agenda.delaunay_failed(Simplex{1, 2, 3}, a));
}

TEST_CASE("no Delaunay failure is taken once the one offered asks for a repair", "[kinetic][agenda]") {
  CertificatePool pool;
  BatchAgenda agenda;
  agenda.fail_delaunay(Simplex{0, 1, 2}, pool.create(CertKind::delaunay, Simplex{0, 1, 2}));
  agenda.fail_delaunay(Simplex{0, 1, 3}, pool.create(CertKind::delaunay, Simplex{0, 1, 3}));
  int offered = 0;
  const auto taken = agenda.take_first_delaunay(pool, [&](const Simplex&, int) {
    ++offered;
    agenda.request_repair();
    return false;
  });
  CHECK_FALSE(taken);
  CHECK(offered == 1);
  CHECK(agenda.repair_due());
  agenda.start_repair();
  CHECK_FALSE(agenda.repair_due());
  CHECK(agenda.has_delaunay());
}

TEST_CASE(
    "radius failures are taken in firing order, and those found while resolving them wait for the next round",
    "[kinetic][agenda]") {
  BatchAgenda agenda;
  agenda.fail_radius(7, 1);
  agenda.fail_radius(3, 2);
  std::vector<BatchAgenda::Entry> round{{99, 9}};
  agenda.take_radius(round);
  CHECK(round == std::vector<BatchAgenda::Entry>{{7, 1}, {3, 2}});
  CHECK_FALSE(agenda.has_radius());
  agenda.fail_radius(5, 4);
  CHECK(round.size() == 2); // a failure found meanwhile is not in the round being resolved
  agenda.take_radius(round);
  CHECK(round == std::vector<BatchAgenda::Entry>{{5, 4}});
  agenda.touch(1, 1);
  agenda.hull_touch(2, 1);
  std::vector<BatchAgenda::Entry> touches, hull;
  agenda.take_touches(touches);
  agenda.take_hull_touches(hull);
  CHECK(touches == std::vector<BatchAgenda::Entry>{{1, 1}});
  CHECK(hull == std::vector<BatchAgenda::Entry>{{2, 1}});
}

TEST_CASE("the agenda holds the time each certificate of the batch fired at until the batch ends",
          "[kinetic][agenda]") {
  BatchAgenda agenda;
  CHECK(agenda.fired_time(4) == nullptr);
  agenda.fired(4, SlabTime(Rational(1, 3)));
  agenda.fired(4, SlabTime(Rational(1, 2)));
  REQUIRE(agenda.fired_time(4) != nullptr);
  CHECK(agenda.fired_time(4)->rational() == Rational(1, 2));
  agenda.end_batch();
  CHECK(agenda.fired_time(4) == nullptr);
}

TEST_CASE("the agenda's check catches a failure held for a retired certificate", "[kinetic][agenda]") {
  CertificatePool pool;
  const int id = pool.create(CertKind::delaunay, Simplex{0, 1, 2});
  BatchAgenda agenda;
  agenda.fail_delaunay(Simplex{0, 1, 2}, id);
  CHECK(agenda.first_violation(pool, false).empty());
  agenda.fail_delaunay(Simplex{0, 1, 3}, id); // not its facet
  CHECK_FALSE(agenda.first_violation(pool, false).empty());
  agenda.withdraw_delaunay(Simplex{0, 1, 3}, id);
  pool.retire(id);
  CHECK_FALSE(agenda.first_violation(pool, false).empty());
  agenda.withdraw_all_delaunay();
  CHECK(agenda.first_violation(pool, false).empty());
}

TEST_CASE("between batches the agenda's check requires that nothing is left", "[kinetic][agenda]") {
  CertificatePool pool;
  const int id = pool.create(CertKind::delaunay, Simplex{0, 1, 2});
  BatchAgenda agenda;
  CHECK(agenda.first_violation(pool, true).empty());
  agenda.fail_delaunay(Simplex{0, 1, 2}, id); // live: only the between-batches rule is broken
  CHECK(agenda.first_violation(pool, false).empty());
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  agenda.withdraw_delaunay(Simplex{0, 1, 2}, id);
  CHECK(agenda.first_violation(pool, true).empty());
  agenda.fail_radius(0, 0);
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  CHECK(agenda.first_violation(pool, false).empty());
  agenda.drop_radius();
  agenda.touch(0, 0);
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  std::vector<BatchAgenda::Entry> touches;
  agenda.take_touches(touches);
  agenda.hull_touch(0, 0);
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  agenda.take_hull_touches(touches);
  CHECK(agenda.first_violation(pool, true).empty());
  agenda.request_repair();
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  agenda.start_repair();
  agenda.fired(0, SlabTime());
  CHECK_FALSE(agenda.first_violation(pool, true).empty());
  agenda.end_batch();
  CHECK(agenda.first_violation(pool, true).empty());
}
