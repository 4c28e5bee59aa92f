#include "medusa/complex/complex_index.h"
#include "medusa/complex/signatures.h"
#include "medusa_fixtures.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

using namespace medusa::complex;
using namespace medusa::test;

namespace {

// GUDHI's exact alpha complex of the points, pruned at rho^2 (GUDHI filtrations are squared radii);
// prints every simplex, then "betti b0 b1 b2 b3" of that complex over Z/2.
constexpr const char* gudhi_script = R"PY(
import sys, gudhi
pts = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
rho2 = float(sys.argv[2])
st = gudhi.AlphaComplex(points=pts, precision='exact').create_simplex_tree()
st.prune_above_filtration(rho2)
for s, f in st.get_simplices():
    print("s", *s)
st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
b = list(st.betti_numbers()) + [0, 0, 0, 0]
print("betti", *b[:4])
)PY";

struct Oracle {
  std::vector<Simplex> complex;
  std::array<std::size_t, 4> betti{};
};

Oracle gudhi_alpha(const std::vector<std::array<int, 3>>& points, double rho2, const std::string& tag) {
  const std::string script = temp_path("alpha-" + tag + ".py");
  const std::string input = temp_path("alpha-" + tag + ".txt");
  std::ofstream(script) << gudhi_script;
  {
    std::ofstream out(input);
    for (const auto& p : points)
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  std::ostringstream cmd;
  cmd << MEDUSA_PYTHON << ' ' << script << ' ' << input << ' ' << rho2;
  FILE* pipe = ::popen(cmd.str().c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string text;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
    text.append(buffer, n);
  REQUIRE(::pclose(pipe) == 0);
  std::remove(script.c_str());
  std::remove(input.c_str());
  Oracle o;
  std::istringstream lines(text);
  std::string line;
  bool has_betti = false;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::string head;
    in >> head;
    if (head == "s") {
      std::vector<VertexId> v;
      VertexId x;
      while (in >> x)
        v.push_back(x);
      o.complex.push_back(Simplex::from_range(v.begin(), v.end()));
    } else if (head == "betti") {
      in >> o.betti[0] >> o.betti[1] >> o.betti[2] >> o.betti[3];
      has_betti = true;
    }
  }
  REQUIRE(has_betti);
  return o;
}

} // namespace

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
      const Oracle o =
          gudhi_alpha(points, rho2, std::to_string(set) + "-" + std::to_string(static_cast<int>(rho2)));
      REQUIRE(!o.complex.empty());
      // K_t fed as the initial complex of a stream that ends at once.
      Stream s;
      s.t0 = event_time(0, 0.0, 0, 0.0, true);
      s.initial = o.complex;
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
