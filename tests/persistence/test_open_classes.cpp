// Loops and cavities split by fate (filled, still open at the end, broke open) and by present at the
// first frame or formed later (docs/MATH.md §7.12), on hand-built medusas whose split is derived on
// paper. Batch 0 is the first frame, batch 10 the end; every cell alive at the end dies at batch 10.
#include "cell_list.h"

#include "medusa/core/error.h"

#include "medusa/persistence/diagram.h"
#include "medusa/persistence/filtration.h"
#include "medusa/persistence/open_classes.h"

#include <catch2/catch.hpp>

#include <map>

using namespace medusa::persistence;
using namespace medusa::persistence::test;

namespace {

constexpr std::uint64_t first_batch = 0, end_batch = 10;

VirtualTime at(std::uint64_t batch) { return vt(batch, 0, static_cast<double>(batch)); }

// A cycle through `v` (in order), every vertex alive throughout, every edge from `born` to `dies`
// except the edge from the last vertex back to the first, which lives from `closes` to `opens`.
void add_cycle(std::vector<CellSpec>& s, const std::vector<medusa::VertexId>& v, std::uint64_t closes,
               std::uint64_t opens) {
  for (medusa::VertexId x : v)
    s.push_back({{x}, at(0), at(end_batch)});
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    s.push_back({{v[i], v[i + 1]}, at(0), at(end_batch)});
  s.push_back({{v.front(), v.back()}, at(closes), at(opens)});
}

// The hollow tetrahedron on `v`: everything from the first frame to the end, except the face without
// v[0], which dies at `opens`.
void add_hollow_tetrahedron(std::vector<CellSpec>& s, const std::vector<medusa::VertexId>& v,
                            std::uint64_t opens) {
  for (medusa::VertexId x : v)
    s.push_back({{x}, at(0), at(end_batch)});
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      s.push_back({{v[i], v[j]}, at(0), at(end_batch)});
  for (std::size_t skip = 0; skip < 4; ++skip) {
    std::vector<medusa::VertexId> face;
    for (std::size_t i = 0; i < 4; ++i)
      if (i != skip)
        face.push_back(v[i]);
    s.push_back({face, at(0), at(skip == 0 ? opens : end_batch)});
  }
}

// The fates of the whole list, or of the cells all of whose vertices have `type`, where the type of
// vertex v is v / 100.
std::array<HoleFates, 3> fates_of(const std::vector<CellSpec>& specs, int type = all_types) {
  const std::vector<medusa::Cell> cells = positional(make_cells(specs));
  std::vector<int> vertex_type(1000);
  for (std::size_t v = 0; v < vertex_type.size(); ++v)
    vertex_type[v] = static_cast<int>(v / 100);
  std::vector<char> member;
  if (type != all_types)
    for (const medusa::Cell& c : cells) {
      bool in = true;
      for (medusa::VertexId v : c.vertices)
        in = in && vertex_type[static_cast<std::size_t>(v)] == type;
      member.push_back(in ? 1 : 0);
    }
  const auto filtration = [&](Direction d) {
    return type == all_types ? make_filtration(cells, d) : make_type_filtration(cells, vertex_type, type, d);
  };
  const Diagram forward = compute_diagram(cells, filtration(Direction::forward));
  const Diagram reverse = compute_diagram(cells, filtration(Direction::reverse));
  return hole_fates(cells, member, forward, reverse, first_batch, end_batch);
}

struct Expected {
  std::size_t filled_initial, filled_formed, still_open_initial, still_open_formed, broken_open_initial,
      broken_open_formed;
};

void check(const HoleFates& h, const Expected& e) {
  CHECK(h.filled_initial == e.filled_initial);
  CHECK(h.filled_formed == e.filled_formed);
  CHECK(h.still_open_initial == e.still_open_initial);
  CHECK(h.still_open_formed == e.still_open_formed);
  CHECK(h.broken_open_initial == e.broken_open_initial);
  CHECK(h.broken_open_formed == e.broken_open_formed);
  CHECK(h.never_filled_initial == e.still_open_initial + e.broken_open_initial);
  CHECK(h.never_filled_formed == e.still_open_formed + e.broken_open_formed);
}

// Two cells u=0, v=1 never touch each other. At the first frame both touch w=2 (edges until batch 2);
// from batch 5 to the end both touch x=3. The loop u-w-v-x exists only in space-time: neither the first
// nor the last frame's complex has it, but their union does.
std::vector<CellSpec> loop_through_time() {
  std::vector<CellSpec> s;
  for (medusa::VertexId x : {0, 1, 2, 3})
    s.push_back({{x}, at(0), at(end_batch)});
  s.push_back({{0, 2}, at(0), at(2)});
  s.push_back({{1, 2}, at(0), at(2)});
  s.push_back({{0, 3}, at(5), at(end_batch)});
  s.push_back({{1, 3}, at(5), at(end_batch)});
  return s;
}

// The square a-b-c-d (10..13) at the first frame; at batch 4 the cell e=14 touches d and a and the
// triangle d-e-a fills the corner; at batch 5 the edge d-a and the triangle leave. The end complex has
// the pentagon a-b-c-d-e, homologous in space-time to the square through the triangle.
std::vector<CellSpec> loop_that_moves() {
  std::vector<CellSpec> s;
  for (medusa::VertexId x : {10, 11, 12, 13})
    s.push_back({{x}, at(0), at(end_batch)});
  s.push_back({{14}, at(4), at(end_batch)});
  s.push_back({{10, 11}, at(0), at(end_batch)});
  s.push_back({{11, 12}, at(0), at(end_batch)});
  s.push_back({{12, 13}, at(0), at(end_batch)});
  s.push_back({{10, 13}, at(0), at(5)});
  s.push_back({{13, 14}, at(4), at(end_batch)});
  s.push_back({{10, 14}, at(4), at(end_batch)});
  s.push_back({{10, 13, 14}, at(4), at(5)});
  return s;
}

} // namespace

TEST_CASE("A loop present at the first frame that stays to the end is still open and initial") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 0, end_batch);
  check(fates_of(s)[1], {0, 0, 1, 0, 0, 0});
}

TEST_CASE("A loop present at the first frame that loses an edge broke open and is initial") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 0, 5);
  check(fates_of(s)[1], {0, 0, 0, 0, 1, 0});
}

TEST_CASE("A loop that closes during the run and stays to the end is still open and formed later") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 3, end_batch);
  check(fates_of(s)[1], {0, 0, 0, 1, 0, 0});
}

TEST_CASE("A loop that closes during the run and loses an edge again broke open and formed later") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 3, 6);
  check(fates_of(s)[1], {0, 0, 0, 0, 0, 1});
}

TEST_CASE("A loop made of the first frame's and the end's contacts broke open and formed later") {
  // The image of H1 of (first frame's cells) + (end's cells) in H1(M) is zero; H1 of their union is
  // not, so the rank from the union would wrongly call it still open.
  check(fates_of(loop_through_time())[1], {0, 0, 0, 0, 0, 1});
}

TEST_CASE("A loop of the first frame that moves onto other cells by the end is still open and initial") {
  check(fates_of(loop_that_moves())[1], {0, 0, 1, 0, 0, 0});
}

TEST_CASE("Cavities present at the first frame are still open or broke open") {
  std::vector<CellSpec> s;
  add_hollow_tetrahedron(s, {0, 1, 2, 3}, end_batch);
  add_hollow_tetrahedron(s, {10, 11, 12, 13}, 5);
  const auto f = fates_of(s);
  check(f[2], {0, 0, 1, 0, 1, 0});
  check(f[1], {0, 0, 0, 0, 0, 0});
}

TEST_CASE("Every fate together adds up, whole medusa and per type") {
  std::vector<CellSpec> s;
  add_cycle(s, {100, 101, 102, 103}, 0, end_batch); // type 1: still open, initial
  add_cycle(s, {110, 111, 112, 113}, 0, 5);         // type 1: broke open, initial
  add_cycle(s, {200, 201, 202, 203}, 3, end_batch); // type 2: still open, formed later
  add_cycle(s, {210, 211, 212, 213}, 3, 6);         // type 2: broke open, formed later
  // Type 3: a triangle at the first frame filled at batch 4, and the two loops above.
  add_closure(s, {300, 301, 302}, at(0), at(end_batch));
  s.back().birth = at(4);
  for (CellSpec c : loop_through_time()) {
    for (medusa::VertexId& v : c.vertices)
      v += 310;
    s.push_back(c);
  }
  for (CellSpec c : loop_that_moves()) {
    for (medusa::VertexId& v : c.vertices)
      v += 320;
    s.push_back(c);
  }
  add_hollow_tetrahedron(s, {400, 401, 402, 403}, 7); // type 4: a cavity that broke open
  const auto whole = fates_of(s);
  check(whole[1], {1, 0, 2, 1, 1, 2});
  check(whole[2], {0, 0, 0, 0, 1, 0});
  check(fates_of(s, 1)[1], {0, 0, 1, 0, 1, 0});
  check(fates_of(s, 2)[1], {0, 0, 0, 1, 0, 1});
  check(fates_of(s, 3)[1], {1, 0, 1, 0, 0, 1});
  check(fates_of(s, 4)[2], {0, 0, 0, 0, 1, 0});
}

TEST_CASE("When the first frame is the last every open loop is an initial one") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 0, end_batch);
  for (CellSpec& c : s)
    c.death = at(0);
  const std::vector<medusa::Cell> cells = positional(make_cells(s));
  const Diagram forward = compute_diagram(cells, make_filtration(cells, Direction::forward));
  const Diagram reverse = compute_diagram(cells, make_filtration(cells, Direction::reverse));
  check(hole_fates(cells, {}, forward, reverse, 0, 0)[1], {0, 0, 1, 0, 0, 0});
}

TEST_CASE("Cells not closed under facets are an internal error") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 0, end_batch);
  const std::vector<medusa::Cell> cells = positional(make_cells(s));
  std::vector<char> member(cells.size(), 1);
  member[0] = 0; // a vertex left out, its edges kept
  CHECK_THROWS_AS(end_classes_beyond_first(cells, member, first_batch, end_batch), medusa::InternalError);
}

TEST_CASE("Fates from ranks reduced before the diagrams equal those reduced with them, and wrong ranks are "
          "refused") {
  std::vector<CellSpec> s;
  add_cycle(s, {0, 1, 2, 3}, 0, end_batch); // still open, initial
  add_cycle(s, {4, 5, 6, 7}, 3, end_batch); // still open, formed later
  const std::vector<medusa::Cell> cells = positional(make_cells(s));
  const std::array<std::size_t, 3> beyond = end_classes_beyond_first(cells, {}, first_batch, end_batch);
  CHECK(beyond == std::array<std::size_t, 3>{0, 1, 0});
  const Diagram forward = compute_diagram(cells, make_filtration(cells, Direction::forward));
  const Diagram reverse = compute_diagram(cells, make_filtration(cells, Direction::reverse));
  const auto fates = hole_fates(forward, reverse, first_batch, end_batch, beyond);
  check(fates[1], {0, 0, 1, 1, 0, 0});
  const auto with_reduction = hole_fates(cells, {}, forward, reverse, first_batch, end_batch);
  CHECK(with_reduction[1].still_open_formed == fates[1].still_open_formed);
  CHECK(with_reduction[1].still_open_initial == fates[1].still_open_initial);
  // Both loops carried to the end and formed later is more than the one formed later.
  CHECK_THROWS_AS(hole_fates(forward, reverse, first_batch, end_batch, {0, 2, 0}), medusa::InternalError);
  CHECK_THROWS_AS(hole_fates(reverse, forward, first_batch, end_batch, beyond), medusa::InternalError);
}
