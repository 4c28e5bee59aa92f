// Static check against GUDHI: a static alpha complex given as medusa cells (every cell born at the
// rank of its filtration value, all dying together) must have GUDHI's persistence, for the whole
// complex and for the full subcomplex of each vertex type (docs/MATH.md §7.4).
#include "cell_list.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/euler.h"
#include "oracle.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <tuple>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

struct Oracle {
  std::vector<Cell> cells;
  std::map<int, std::vector<Triple>> persistence; // by type, -1 for the whole complex
};

Oracle alpha_oracle(unsigned seed, int n_points, std::vector<int>& types) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TempDir dir("gudhi-alpha");
  {
    std::FILE* points = std::fopen(dir.file("points.txt").c_str(), "w");
    std::FILE* type_file = std::fopen(dir.file("types.txt").c_str(), "w");
    REQUIRE(points);
    REQUIRE(type_file);
    types.clear();
    for (int i = 0; i < n_points; ++i) {
      const double x = unit(rng), y = unit(rng), z = unit(rng);
      std::fprintf(points, "%.17g %.17g %.17g\n", x, y, z);
      types.push_back(1 + static_cast<int>(rng() % 2));
      std::fprintf(type_file, "%d\n", types.back());
    }
    std::fclose(points);
    std::fclose(type_file);
  }
  run(python() + " " + data_path("persistence/alpha_oracle.py") + " " + dir.file("points.txt") + " " +
      dir.file("types.txt") + " " + dir.file("out.txt"));
  std::istringstream in(read_text(dir.file("out.txt")));
  std::vector<std::pair<double, std::vector<kinetic::VertexId>>> simplices;
  Oracle oracle;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "S") {
      std::string value;
      ls >> value;
      std::vector<kinetic::VertexId> vertices;
      for (kinetic::VertexId v; ls >> v;)
        vertices.push_back(v);
      simplices.emplace_back(std::stod(value), vertices);
    } else if (tag == "P") {
      int type = 0, dim = 0;
      std::string b, d;
      ls >> type >> dim >> b >> d;
      oracle.persistence[type].emplace_back(dim, std::stod(b), std::stod(d));
    }
  }
  // Virtual time: batch = rank of the filtration value among the distinct values (equal values are
  // one batch, as equal event times are in the medusa).
  std::vector<double> values;
  for (const auto& s : simplices)
    values.push_back(s.first);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  const auto end = vt(values.size(), 0, values.back() + 1);
  std::vector<CellSpec> specs;
  for (const auto& [value, vertices] : simplices) {
    const auto batch =
        static_cast<std::uint64_t>(std::lower_bound(values.begin(), values.end(), value) - values.begin());
    specs.push_back({vertices, vt(batch, 0, value), end});
  }
  oracle.cells = make_cells(specs);
  for (auto& [type, triples] : oracle.persistence)
    std::sort(triples.begin(), triples.end());
  return oracle;
}

} // namespace

TEST_CASE("The diagram of a static alpha complex equals GUDHI's persistence, also per vertex type") {
  for (unsigned seed : {101u, 202u, 303u}) {
    CAPTURE(seed);
    std::vector<int> types;
    const Oracle oracle = alpha_oracle(seed, 40, types);
    const Filtration whole = make_filtration(oracle.cells, Direction::forward);
    const Diagram d = compute_diagram(oracle.cells, whole);
    CHECK_NOTHROW(check_euler(d, whole));
    REQUIRE(oracle.persistence.count(-1) == 1);
    CHECK(positive_points(d) == oracle.persistence.at(-1));
    for (int type : {1, 2}) {
      CAPTURE(type);
      const Filtration sub = make_type_filtration(oracle.cells, types, type, Direction::forward);
      const Diagram ds = compute_diagram(oracle.cells, sub);
      CHECK_NOTHROW(check_euler(ds, sub));
      CHECK(positive_points(ds) == oracle.persistence.at(type));
    }
  }
}
