// The binary boundary-matrix export against PHAT's own command-line tool (/usr/bin/phat).
#include "cell_list.h"
#include "medusa/core/error.h"
#include "medusa/persistence/boundary_matrix.h"
#include "oracle.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

// Every face of a 4-simplex on 0..4 and of a triangle 4,5,6, with random births that respect faces
// (a simplex is born at least when its last facet is) and deaths at the end or earlier for cofaces.
std::vector<Cell> random_complex(unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<CellSpec> s;
  add_closure(s, {0, 1, 2, 3, 4}, vt(0, 0, 0), vt(0, 0, 0));
  add_closure(s, {4, 5, 6}, vt(0, 0, 0), vt(0, 0, 0));
  std::sort(s.begin(), s.end(),
            [](const CellSpec& a, const CellSpec& b) { return a.vertices.size() < b.vertices.size(); });
  std::vector<std::uint64_t> birth(s.size()), death(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::uint64_t b = 0, d = 40;
    for (std::size_t j = 0; j < i; ++j)
      if (s[j].vertices.size() + 1 == s[i].vertices.size() &&
          std::includes(s[i].vertices.begin(), s[i].vertices.end(), s[j].vertices.begin(),
                        s[j].vertices.end())) {
        b = std::max(b, birth[j]);
        d = std::min(d, death[j]);
      }
    birth[i] = b + rng() % 3;
    death[i] = std::max(birth[i], d - rng() % 3);
    s[i].birth = vt(birth[i], 0, static_cast<double>(birth[i]));
    s[i].death = vt(death[i], 0, static_cast<double>(death[i]));
  }
  return make_cells(s);
}

std::vector<std::int64_t> read_int64s(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::int64_t> values;
  std::int64_t v;
  while (in.read(reinterpret_cast<char*>(&v), sizeof v))
    values.push_back(v);
  return values;
}

} // namespace

TEST_CASE("The binary matrix holds the column count then dimension, size and entries per column") {
  const auto cells = make_cells(
      {{{0}, vt(0, 0, 0), vt(1, 0, 1)}, {{1}, vt(0, 0, 0), vt(1, 0, 1)}, {{0, 1}, vt(0, 1, 0), vt(1, 0, 1)}});
  TempDir dir("phat-format");
  write_phat_binary(make_filtration(cells, Direction::forward), dir.file("m.bin"));
  CHECK(read_int64s(dir.file("m.bin")) == std::vector<std::int64_t>{3, 0, 0, 0, 0, 1, 2, 0, 1});
  CHECK_FALSE(std::filesystem::exists(dir.file("m.bin.tmp")));
  CHECK_THROWS_AS(write_phat_binary(make_filtration(cells, Direction::forward), dir.file("missing/m.bin")),
                  StoreError);
}

TEST_CASE("The phat command-line tool finds the same pairs as the in-memory reduction") {
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    CAPTURE(seed);
    const auto cells = random_complex(seed);
    for (Direction direction : {Direction::forward, Direction::reverse}) {
      const Filtration f = make_filtration(cells, direction);
      TempDir dir("phat-cli");
      write_phat_binary(f, dir.file("matrix.bin"));
      run("/usr/bin/phat --binary " + dir.file("matrix.bin") + " " + dir.file("pairs.bin") + " > /dev/null");
      const auto from_cli = read_phat_binary_pairs(dir.file("pairs.bin"));
      CHECK(from_cli == reduce(f));
      CHECK(from_cli == (reduce<phat::vector_vector, phat::twist_reduction>(f)));
      CHECK_FALSE(from_cli.empty());
    }
  }
}
