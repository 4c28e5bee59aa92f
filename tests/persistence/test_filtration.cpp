// Forward and reverse filtrations and sub-medusas (docs/MATH.md §7.2-§7.4).
#include "cell_list.h"
#include "medusa/core/error.h"
#include "medusa/persistence/filtration.h"

#include <catch2/catch.hpp>

using namespace medusa;
using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

// Vertices 0, 1, 2; edge 01 born at (1,0); edge 12 at (1,1); edge 02 at (2,0); vertex 2 dies first.
std::vector<Cell> small_complex() {
  return make_cells({
      {{2}, vt(0, 0, 0), vt(3, 0, 3)},    // 1000
      {{0}, vt(0, 0, 0), vt(4, 0, 4)},    // 1007
      {{1}, vt(0, 0, 0), vt(4, 0, 4)},    // 1014
      {{1, 2}, vt(1, 1, 1), vt(2, 5, 2)}, // 1021
      {{0, 1}, vt(1, 0, 1), vt(4, 0, 4)}, // 1028
      {{0, 2}, vt(2, 0, 2), vt(2, 5, 2)}, // 1035
  });
}

std::vector<medusa::CellId> ids_in_order(const std::vector<Cell>& cells, const Filtration& f) {
  std::vector<medusa::CellId> ids;
  for (std::size_t pos : f.cells)
    ids.push_back(cells[pos].id);
  return ids;
}

} // namespace

TEST_CASE("The forward filtration orders cells by birth batch, birth rank, dimension and vertex tuple") {
  const auto cells = small_complex();
  const Filtration f = make_filtration(cells, Direction::forward);
  // Vertices (0,0) by tuple 0,1,2; then 01 (1,0), 12 (1,1), 02 (2,0).
  CHECK(ids_in_order(cells, f) == std::vector<medusa::CellId>{1007, 1014, 1000, 1028, 1021, 1035});
  CHECK(f.dims == std::vector<std::int8_t>{0, 0, 0, 1, 1, 1});
  CHECK(f.columns[3].to_vector() == std::vector<std::int64_t>{0, 1});
  CHECK(f.columns[4].to_vector() == std::vector<std::int64_t>{1, 2});
  CHECK(f.columns[5].to_vector() == std::vector<std::int64_t>{0, 2});
  CHECK(f.cell_type == all_types);
}

TEST_CASE("The reverse filtration orders cells by latest death first, then dimension and vertex tuple") {
  const auto cells = small_complex();
  const Filtration f = make_filtration(cells, Direction::reverse);
  // Deaths: 0,1,01 at (4,0); 2 at (3,0); 12, 02 at (2,5).
  CHECK(ids_in_order(cells, f) == std::vector<medusa::CellId>{1007, 1014, 1028, 1000, 1035, 1021});
  CHECK(f.columns[2].to_vector() == std::vector<std::int64_t>{0, 1});
  CHECK(f.columns[4].to_vector() == std::vector<std::int64_t>{0, 3});
  CHECK(f.columns[5].to_vector() == std::vector<std::int64_t>{1, 3});
}

TEST_CASE("A sub-medusa keeps the cells whose vertices all have the type, re-indexed consecutively") {
  const auto cells = small_complex();
  const std::vector<int> types{1, 2, 1}; // vertices 0 and 2 have type 1
  const Filtration f = make_type_filtration(cells, types, 1, Direction::forward);
  CHECK(ids_in_order(cells, f) == std::vector<medusa::CellId>{1007, 1000, 1035});
  CHECK(f.columns[2].to_vector() == std::vector<std::int64_t>{0, 1});
  CHECK(f.cell_type == 1);
  const Filtration g = make_type_filtration(cells, types, 2, Direction::reverse);
  CHECK(ids_in_order(cells, g) == std::vector<medusa::CellId>{1014});
  CHECK(make_type_filtration(cells, types, 7, Direction::forward).size() == 0);
}

TEST_CASE("A facet that does not precede its coface is an internal error") {
  auto cells = small_complex();
  cells[0].birth = vt(3, 0, 3); // vertex 2 born after its edges 12 and 02
  CHECK_THROWS_AS(make_filtration(cells, Direction::forward), InternalError);
  auto reverse_cells = small_complex();
  reverse_cells[3].death = vt(3, 1, 3); // edge 12 outlives its vertex 2
  CHECK_THROWS_AS(make_filtration(reverse_cells, Direction::reverse), InternalError);
}

TEST_CASE("A facet with the wrong vertices or a wrong facet count is an internal error") {
  auto cells = small_complex();
  cells[5].facets = {1007, 1014}; // 02 naming vertex 1
  CHECK_THROWS_AS(make_filtration(cells, Direction::forward), InternalError);
  auto short_cells = small_complex();
  short_cells[5].facets = {1007};
  CHECK_THROWS_AS(make_filtration(short_cells, Direction::forward), InternalError);
}

TEST_CASE("An unknown facet id, a duplicate cell id or a vertex outside the type table is an input error") {
  auto unknown = small_complex();
  unknown[4].facets[0] = 99;
  CHECK_THROWS_AS(make_filtration(unknown, Direction::forward), InputError);
  auto duplicate = small_complex();
  duplicate[1].id = duplicate[0].id;
  CHECK_THROWS_AS(make_filtration(duplicate, Direction::forward), InputError);
  CHECK_THROWS_AS(make_type_filtration(small_complex(), {1, 1}, 1, Direction::forward), InputError);
}

TEST_CASE("Cells whose ids are their positions give the same filtration as arbitrary ids") {
  // The store's numbering (ids 0..N-1 in order) takes the lookup without a hash table.
  const auto cells = small_complex();
  auto renumbered = cells;
  for (Cell& c : renumbered) {
    c.id = (c.id - 1000) / 7;
    for (std::uint32_t& facet : c.facets)
      facet = (facet - 1000) / 7;
  }
  for (Direction direction : {Direction::forward, Direction::reverse}) {
    const Filtration f = make_filtration(cells, direction), g = make_filtration(renumbered, direction);
    CHECK(g.cells == f.cells);
    CHECK(g.dims == f.dims);
    CHECK(g.columns == f.columns);
  }
  renumbered[4].facets[0] = 99;
  CHECK_THROWS_AS(make_filtration(renumbered, Direction::forward), InputError);
}

TEST_CASE("Boundary columns read back as they were appended, empty columns included") {
  BoundaryColumns columns;
  columns.reserve(4, 5);
  const std::vector<std::vector<std::int64_t>> appended{{}, {0, 3}, {}, {1, 2, 4}};
  for (const auto& column : appended)
    columns.push_back(column);
  REQUIRE(columns.size() == appended.size());
  CHECK(columns.entries() == 5);
  for (std::size_t j = 0; j < appended.size(); ++j) {
    CHECK(columns[j].to_vector() == appended[j]);
    CHECK(columns[j].size() == appended[j].size());
    CHECK(columns[j].empty() == appended[j].empty());
  }
  CHECK(columns[3][1] == 2);
  CHECK(columns[3].back() == 4);
  BoundaryColumns other;
  for (const auto& column : {appended[0], appended[1], appended[2]})
    other.push_back(column);
  CHECK_FALSE(other == columns);
  other.push_back(appended[3]);
  CHECK(other == columns);
}

TEST_CASE("A filtration has one boundary column per cell, each of its cell's facet count") {
  const auto cells = small_complex();
  for (Direction direction : {Direction::forward, Direction::reverse}) {
    const Filtration f = make_filtration(cells, direction);
    REQUIRE(f.columns.size() == f.size());
    for (std::size_t j = 0; j < f.size(); ++j)
      CHECK(f.columns[j].size() == cells[f.cells[j]].facets.size());
  }
}

TEST_CASE("Boundary columns hold the largest filtration index and refuse what is none") {
  BoundaryColumns columns;
  const auto largest = static_cast<std::int64_t>(max_filtration_size) - 1;
  columns.push_back({0, largest});
  CHECK(columns[0].back() == largest);
  CHECK_THROWS_AS(columns.push_back({-1}), InternalError);
  CHECK_THROWS_AS(columns.push_back({largest + 1}), InternalError);
  CHECK_THROWS_AS(columns.push_back({std::int64_t{1} << 32}), InternalError);
  CHECK_THROWS_AS(columns.push_back({3, -1}), InternalError);
  CHECK(columns.size() == 1);
  CHECK(columns.entries() == 2);
}

TEST_CASE("A filtration over more cells than 32-bit indices number is refused as input") {
  CHECK_NOTHROW(check_filtration_size(max_filtration_size, max_filtration_size));
  CHECK_THROWS_AS(check_filtration_size(max_filtration_size + 1, 10), InputError);
  CHECK_THROWS_AS(check_filtration_size(10, max_filtration_size + 1), InputError);
  CHECK(max_filtration_size + 1 == UINT32_MAX); // the largest value stays free to mark "no cell"
}
