#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/signatures.h"
#include "medusa_fixtures.h"
#include "support/gudhi_oracle.h"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace medusa;
using namespace medusa::test;

TEST_CASE("Betti numbers of K_t agree with GUDHI's alpha complex of static point sets",
          "[medusa][signature][gudhi]") {
  constexpr std::uint64_t seed = 424242;
  CAPTURE(seed);
  std::mt19937_64 rng(seed);
  std::size_t cases = 0, nontrivial = 0;
  for (int set = 0; set < 4; ++set) {
    // Points on a jittered sphere-like shell, so that middle radii give H1 and H2 classes.
    std::vector<std::array<int, 3>> points;
    std::uniform_int_distribution<int> coord(-100, 100);
    while (points.size() < 40) {
      std::array<int, 3> p{coord(rng), coord(rng), coord(rng)};
      const long r2 =
          static_cast<long>(p[0]) * p[0] + static_cast<long>(p[1]) * p[1] + static_cast<long>(p[2]) * p[2];
      if (r2 >= 60 * 60 && r2 <= 100 * 100)
        points.push_back(p);
    }
    for (double rho2 : {150.5, 400.5, 900.5, 1600.5, 2500.5}) {
      CAPTURE(set, rho2);
      std::ostringstream rho2_text;
      rho2_text << rho2;
      const GudhiAlphaComplex o = gudhi_alpha_complex(
          points, rho2_text.str(), std::to_string(set) + "-" + std::to_string(static_cast<int>(rho2)));
      REQUIRE(!o.simplices.empty());
      // K_t fed as the initial complex of a stream that ends at once.
      Stream s;
      s.t0 = event_time(0, 0.0, 0, 0.0, true);
      for (const auto& v : o.simplices)
        s.initial.push_back(Simplex::from_range(v.begin(), v.end()));
      s.t_end = event_time(1, 10.0, 1, 0.0, true);
      const Medusa m = collect(s, points.size(), 2);
      const ComplexIndex index(m);
      const Signature sig = signature_of(m, index.after(0));
      CHECK(sig.betti == o.betti);
      CHECK(static_cast<long long>(sig.betti[0]) - static_cast<long long>(sig.betti[1]) +
                static_cast<long long>(sig.betti[2]) - static_cast<long long>(sig.betti[3]) ==
            sig.euler);
      ++cases;
      if (o.betti[1] > 0 || o.betti[2] > 0)
        ++nontrivial;
    }
  }
  REQUIRE(cases == 20);
  CHECK(nontrivial >= 3);
}

TEST_CASE("signatures per cell type count only the cells all of whose vertices have that type",
          "[medusa][signature]") {
  // Two triangles sharing edge 12: vertices 0,1,2 of type 1 form a filled triangle, 1,2,3 with 3 of
  // type 2; per type 1: a filled triangle; per type 2: one vertex.
  Stream s;
  s.t0 = event_time(0, 0.0, 0, 0.0, true);
  s.initial = closure({Simplex{0, 1, 2}, Simplex{1, 2, 3}});
  s.frames_after_initial = {0};
  Step leave;
  leave.rank = 1;
  leave.left = {Simplex{0, 1, 2}};
  s.batches.push_back({event_time(1, 5.0, 0, 0.5), {leave}, {}});
  s.t_end = event_time(2, 10.0, 1, 0.0, true);
  MedusaCollector collector;
  MedusaBuilder builder(collector);
  builder.set_run(test_run_info(), dummy_input(4, 2, {1, 1, 1, 2}));
  s.play(builder);
  const Medusa m = collector.take();

  const ComplexIndex all(m), type1(m, 1), type2(m, 2);
  const auto whole = signatures_over_time(all);
  const auto t1 = signatures_over_time(type1);
  const auto t2 = signatures_over_time(type2);
  REQUIRE(whole.size() == 3);
  REQUIRE(t1.size() == 3);
  REQUIRE(t2.size() >= 2);
  CHECK(whole[0].signature.f == std::array<std::size_t, 4>{4, 5, 2, 0});
  CHECK(whole[0].frames == std::vector<std::size_t>{0});
  CHECK(whole[2].frames == std::vector<std::size_t>{1});
  CHECK(t1[0].signature.f == std::array<std::size_t, 4>{3, 3, 1, 0});
  CHECK(t1[0].signature.betti == std::array<std::size_t, 4>{1, 0, 0, 0});
  // After the triangle 012 leaves, type 1 holds a hollow triangle: one 1-cycle.
  CHECK(t1[1].signature.f == std::array<std::size_t, 4>{3, 3, 0, 0});
  CHECK(t1[1].signature.betti == std::array<std::size_t, 4>{1, 1, 0, 0});
  CHECK(t1[2].before);
  CHECK(t1[2].signature.betti == std::array<std::size_t, 4>{1, 1, 0, 0});
  CHECK(t2[1].signature.f == std::array<std::size_t, 4>{1, 0, 0, 0});
  CHECK(whole[1].signature.betti == std::array<std::size_t, 4>{1, 1, 0, 0});
  CHECK(whole[1].signature.euler == 0);
}
