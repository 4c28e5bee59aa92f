// Random medusas with arbitrary lifetimes against GUDHI: the forward diagram is the persistence of
// the birth-time filtration, the reverse diagram that of -death (docs/MATH.md §7.3: reverse = sublevel
// sets of -t). Diagram values do not depend on how ties inside a batch are ordered, so the pairs of
// positive length must agree exactly.
#include "cell_list.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/euler.h"
#include "oracle.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <map>
#include <random>
#include <tuple>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

// Closure of random simplices on 8 vertices; each simplex gets a lifetime inside those of its facets
// (virtual times with several ranks per batch); a simplex whose facets never coexist is left out,
// with its cofaces.
std::vector<Cell> random_medusa(unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<CellSpec> shape;
  for (int k = 0; k < 7; ++k) {
    std::vector<kinetic::VertexId> vertices;
    const std::size_t size = 2 + rng() % 4;
    while (vertices.size() < size) {
      const kinetic::VertexId v = static_cast<kinetic::VertexId>(rng() % 8);
      if (std::find(vertices.begin(), vertices.end(), v) == vertices.end())
        vertices.push_back(v);
    }
    std::sort(vertices.begin(), vertices.end());
    add_closure(shape, vertices, vt(0, 0, 0), vt(0, 0, 0));
  }
  std::stable_sort(shape.begin(), shape.end(), [](const CellSpec& a, const CellSpec& b) {
    return a.vertices.size() < b.vertices.size();
  });
  auto later = [&](VirtualTime t) {
    if (rng() % 2 == 0)
      return vt(t.batch, t.rank + static_cast<std::uint32_t>(rng() % 2), static_cast<double>(t.batch));
    const std::uint64_t batch = t.batch + 1 + rng() % 3;
    return vt(batch, static_cast<std::uint32_t>(rng() % 3), static_cast<double>(batch));
  };
  auto earlier = [&](VirtualTime t) {
    if (rng() % 2 == 0 || t.batch < 4)
      return vt(t.batch, t.rank - static_cast<std::uint32_t>(t.rank > 0 ? rng() % 2 : 0),
                static_cast<double>(t.batch));
    const std::uint64_t batch = t.batch - 1 - rng() % 3;
    return vt(batch, static_cast<std::uint32_t>(rng() % 3), static_cast<double>(batch));
  };
  std::vector<CellSpec> specs;
  for (CellSpec s : shape) {
    if (s.vertices.size() == 1) {
      s.birth = rng() % 3 == 0 ? later(vt(0, 0, 0)) : vt(0, 0, 0);
      s.death = rng() % 3 == 0 ? earlier(vt(40, 0, 40)) : vt(40, 0, 40);
    } else {
      VirtualTime birth = vt(0, 0, 0), death = vt(40, 0, 40);
      std::size_t found = 0;
      for (const CellSpec& f : specs)
        if (f.vertices.size() + 1 == s.vertices.size() &&
            std::includes(s.vertices.begin(), s.vertices.end(), f.vertices.begin(), f.vertices.end())) {
          ++found;
          birth = std::max(birth, f.birth);
          death = std::min(death, f.death);
        }
      if (found != s.vertices.size() || death < birth)
        continue;
      s.birth = rng() % 2 ? later(birth) : birth;
      s.death = rng() % 2 ? earlier(death) : death;
      if (death < s.birth || s.death < birth || s.death < s.birth) {
        s.birth = birth;
        s.death = death;
      }
    }
    specs.push_back(s);
  }
  return make_cells(specs);
}

std::vector<Triple> gudhi_persistence(const std::vector<Cell>& cells, const Filtration& f, double sign) {
  TempDir dir("gudhi-random");
  {
    std::FILE* out = std::fopen(dir.file("simplices.txt").c_str(), "w");
    REQUIRE(out);
    for (std::size_t pos : f.cells) {
      const Cell& c = cells[pos];
      std::fprintf(out, "%.17g", sign * (f.direction == Direction::forward ? c.birth.time : c.death.time));
      for (auto v : c.vertices)
        std::fprintf(out, " %d", v);
      std::fprintf(out, "\n");
    }
    std::fclose(out);
  }
  run(python() + " " + data_path("persistence/simplex_tree_oracle.py") + " " + dir.file("simplices.txt") +
      " " + dir.file("out.txt"));
  std::vector<Triple> result;
  std::istringstream in(read_text(dir.file("out.txt")));
  for (std::string dim, b, d; in >> dim >> b >> d;)
    result.emplace_back(std::stoi(dim), sign * std::stod(b), sign * std::stod(d));
  std::sort(result.begin(), result.end());
  return result;
}

} // namespace

TEST_CASE("Forward and reverse diagrams of random medusas equal GUDHI's persistence of birth and -death") {
  std::size_t nontrivial = 0;
  for (unsigned seed = 500; seed < 512; ++seed) {
    CAPTURE(seed);
    const auto cells = random_medusa(seed);
    const Filtration forward = make_filtration(cells, Direction::forward);
    const Filtration reverse = make_filtration(cells, Direction::reverse);
    const Diagram df = compute_diagram(cells, forward);
    const Diagram dr = compute_diagram(cells, reverse);
    CHECK_NOTHROW(check_euler(df, forward));
    CHECK_NOTHROW(check_euler(dr, reverse));
    CHECK(positive_points(df) == gudhi_persistence(cells, forward, 1.0));
    CHECK(positive_points(dr) == gudhi_persistence(cells, reverse, -1.0));
    nontrivial += positive_points(df).size() > 1;
  }
  CHECK(nontrivial > 6);
}
