#include "appendix_b.h"
#include "cell_ids.h"
#include "medusa/core/error.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/homology.h"
#include "medusa/medusa/medusa.h"
#include "medusa/medusa/medusa_builder.h"
#include "medusa/medusa/signatures.h"
#include "stream.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace medusa;
using namespace medusa::test;

namespace {

Medusa build(const Stream& stream, std::size_t vertices, std::size_t frames) {
  MedusaCollector collector;
  MedusaBuilder builder(collector);
  builder.set_run(RunInfo{}, dummy_input(vertices, frames));
  stream.play(builder);
  REQUIRE(builder.active_cells() == 0);
  return collector.take();
}

std::vector<const Cell*> cells_of(const Medusa& m, std::vector<VertexId> vertices) {
  std::vector<const Cell*> out;
  for (const Cell& c : m.cells)
    if (c.vertices == vertices)
      out.push_back(&c);
  return out;
}

const Cell& only_cell(const Medusa& m, std::vector<VertexId> vertices) {
  auto cells = cells_of(m, vertices);
  INFO("cell " << ::Catch::Detail::stringify(vertices));
  REQUIRE(cells.size() == 1);
  return *cells.front();
}

std::vector<CellId> facet_ids(const Cell& c) { return {c.facets.begin(), c.facets.end()}; }

VirtualTime vt(std::uint32_t batch, std::uint32_t rank) {
  VirtualTime t;
  t.batch = batch;
  t.rank = rank;
  return t;
}

} // namespace

TEST_CASE("the Appendix B flip gives exactly the medusa cells of the table", "[medusa][builder]") {
  const Medusa m = build(appendix_b_stream(), 5, 2);
  std::array<std::size_t, 5> counts{};
  long long chi = 0;
  for (const Cell& c : m.cells) {
    ++counts[static_cast<std::size_t>(c.dim())];
    chi += c.dim() % 2 == 0 ? 1 : -1;
  }
  CHECK(counts == std::array<std::size_t, 5>{5, 10, 10, 5, 1});
  CHECK(chi == 1);

  const VirtualTime t0 = vt(0, 0), t_star = vt(1, 1), t_end = vt(2, 0);
  auto lifetime = [&](std::vector<VertexId> v, VirtualTime b, VirtualTime d) {
    const Cell& c = only_cell(m, v);
    INFO("cell " << ::Catch::Detail::stringify(v));
    CHECK(c.birth == b);
    CHECK(c.death == d);
  };
  for (VertexId v = 0; v < 5; ++v)
    lifetime({v}, t0, t_end);
  for (auto e : std::vector<std::vector<VertexId>>{
           {0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}, {0, 4}, {1, 4}, {2, 4}})
    lifetime(e, t0, t_end);
  for (auto t :
       std::vector<std::vector<VertexId>>{{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 4}, {1, 2, 4}, {0, 2, 4}})
    lifetime(t, t0, t_end);
  for (auto s : std::vector<std::vector<VertexId>>{{0, 1, 2}, {0, 1, 2, 3}, {0, 1, 2, 4}})
    lifetime(s, t0, t_star);
  for (auto s : std::vector<std::vector<VertexId>>{
           {3, 4}, {0, 3, 4}, {1, 3, 4}, {2, 3, 4}, {0, 1, 3, 4}, {1, 2, 3, 4}, {0, 2, 3, 4}})
    lifetime(s, t_star, t_end);
  lifetime({0, 1, 2, 3, 4}, t_star, t_star);

  const Cell& flip = only_cell(m, {0, 1, 2, 3, 4});
  CHECK(flip.kind == CellKind::flip);
  std::vector<CellId> expected{only_cell(m, {1, 2, 3, 4}).id, only_cell(m, {0, 2, 3, 4}).id,
                               only_cell(m, {0, 1, 3, 4}).id, only_cell(m, {0, 1, 2, 4}).id,
                               only_cell(m, {0, 1, 2, 3}).id};
  CHECK(facet_ids(flip) == expected); // facet i omits vertex i
  CHECK(only_cell(m, {0, 1}).kind == CellKind::regular);
}

TEST_CASE("the Appendix B complexes before and after the flip are contractible", "[medusa][builder]") {
  const Medusa m = build(appendix_b_stream(), 5, 2);
  const ComplexIndex index(m);
  const Signature before = signature_of(m, index.after(0));
  CHECK(before.f == std::array<std::size_t, 4>{5, 9, 7, 2});
  CHECK(before.betti == std::array<std::size_t, 4>{1, 0, 0, 0});
  const Signature after = signature_of(m, index.after(1));
  CHECK(after.f == std::array<std::size_t, 4>{5, 10, 9, 3});
  CHECK(after.euler == 1);
  CHECK(after.betti == std::array<std::size_t, 4>{1, 0, 0, 0});
  CHECK(signature_of(m, index.before(1)).f == before.f);
  CHECK(signature_of(m, index.before(2)).f == after.f);
}

TEST_CASE("a flip outside the alpha complex adds no medusa cell", "[medusa][builder]") {
  Stream s = appendix_b_stream();
  s.batches[0].steps[0].flip->in_alpha = false;
  // Without the 4-simplex the five tetrahedra around the flip are a 3-sphere: the builder does not
  // judge that (libkinetic decides in_alpha); it only omits the cell.
  const Medusa m = build(s, 5, 2);
  CHECK(cells_of(m, {0, 1, 2, 3, 4}).empty());
  CHECK(m.cells.size() == 30);
}

TEST_CASE("a simplex that leaves and re-enters K gives two cells", "[medusa][builder]") {
  Stream s;
  s.t0 = event_time(0, 0.0, 0, 0.0, true);
  s.initial = closure({Simplex{0, 1}});
  Step leave;
  leave.rank = 1;
  leave.kind = medusa::kinetic::StepKind::radius;
  leave.left = {Simplex{0, 1}};
  Step enter;
  enter.rank = 1;
  enter.kind = medusa::kinetic::StepKind::radius;
  enter.entered = {Simplex{0, 1}};
  s.batches.push_back({event_time(1, 3.0, 0, 0.3), {leave}, {}});
  s.batches.push_back({event_time(2, 7.0, 0, 0.7), {enter}, {}});
  s.t_end = event_time(3, 10.0, 1, 0.0, true);
  const Medusa m = build(s, 2, 2);
  auto edges = cells_of(m, {0, 1});
  REQUIRE(edges.size() == 2);
  std::sort(edges.begin(), edges.end(), [](const Cell* a, const Cell* b) { return a->birth < b->birth; });
  CHECK(edges[0]->birth == vt(0, 0));
  CHECK(edges[0]->death == vt(1, 1));
  CHECK(edges[1]->birth == vt(2, 1));
  CHECK(edges[1]->death == vt(3, 0));
  CHECK(edges[1]->death.time == 10.0);
  CHECK(edges[0]->id != edges[1]->id);
  CHECK(only_cell(m, {0}).death == vt(3, 0));
}

namespace {

// docs/MATH.md §6.3, the 2D counterexample: x = 0, y = 1, apices q = 2 (0,-3) and s = 3 (0,10), rho = 1.05.
// Inserting p = 4 at (0,-0.2) keeps xy Delaunay but removes it from K while xp, yp enter; deleting p
// later brings xy back.
Stream join_stream() {
  Stream s;
  s.t0 = event_time(0, 0.0, 0, 0.0, true);
  s.initial = {Simplex{0}, Simplex{1}, Simplex{2}, Simplex{3}, Simplex{0, 1}};
  s.frames_after_initial = {0};
  Step insert;
  insert.rank = 1;
  insert.kind = medusa::kinetic::StepKind::insertion;
  insert.vertex = 4;
  insert.entered = {Simplex{4}, Simplex{0, 4}, Simplex{1, 4}};
  insert.left = {Simplex{0, 1}};
  Step remove;
  remove.rank = 1;
  remove.kind = medusa::kinetic::StepKind::deletion;
  remove.vertex = 4;
  remove.entered = {Simplex{0, 1}};
  remove.left = {Simplex{4}, Simplex{0, 4}, Simplex{1, 4}};
  s.batches.push_back({event_time(1, 10.0, 1, 0.0, true), {insert}, {1}});
  s.batches.push_back({event_time(2, 20.0, 2, 0.0, true), {remove}, {2}});
  s.t_end = event_time(3, 30.0, 3, 0.0, true);
  return s;
}

} // namespace

TEST_CASE("an insertion and a deletion give the join cells of docs/MATH.md §6.3", "[medusa][builder]") {
  const Medusa m = build(join_stream(), 5, 4);
  auto joins = cells_of(m, {0, 1, 4});
  REQUIRE(joins.size() == 2);
  std::sort(joins.begin(), joins.end(), [](const Cell* a, const Cell* b) { return a->birth < b->birth; });
  auto xy = cells_of(m, {0, 1});
  REQUIRE(xy.size() == 2);
  std::sort(xy.begin(), xy.end(), [](const Cell* a, const Cell* b) { return a->birth < b->birth; });
  const Cell& xp = only_cell(m, {0, 4});
  const Cell& yp = only_cell(m, {1, 4});

  CHECK(joins[0]->kind == CellKind::join);
  CHECK(joins[0]->birth == vt(1, 1));
  CHECK(joins[0]->death == vt(1, 1));
  CHECK(facet_ids(*joins[0]) == std::vector<CellId>{yp.id, xp.id, xy[0]->id});
  CHECK(joins[1]->kind == CellKind::join);
  CHECK(joins[1]->birth == vt(2, 1));
  CHECK(facet_ids(*joins[1]) == std::vector<CellId>{yp.id, xp.id, xy[1]->id});
  CHECK(xy[0]->death == vt(1, 1));
  CHECK(xy[1]->birth == vt(2, 1));
  CHECK(xp.birth == vt(1, 1));
  CHECK(xp.death == vt(2, 1));
  CHECK(only_cell(m, {4}).birth == vt(1, 1));
  CHECK(m.cells.size() == 11);

  // Without the joins the x-y-p part would carry two spurious 1-cycles; with them M has the homotopy
  // type of three points (x-y-p, q, s).
  ChainComplex all;
  for (const Cell& c : m.cells) {
    all.add(c.dim(), c.facets);
  }
  CHECK(betti_numbers(all) == std::vector<std::size_t>{3, 0, 0});
}

TEST_CASE("frames map to the state after their frame batch and the last frame to K(t_end-)",
          "[medusa][builder][query]") {
  const Medusa m = build(join_stream(), 5, 4);
  const ComplexIndex index(m);
  REQUIRE(m.frames.size() == 3);
  CHECK(index.frame_batch(0) == 0);
  CHECK(index.frame_batch(1) == 1);
  CHECK(index.frame_batch(2) == 2);
  CHECK(index.frame_batch(3) == 3);
  CHECK(signature_of(m, index.at_frame(0)).f == std::array<std::size_t, 4>{4, 1, 0, 0});
  CHECK(signature_of(m, index.at_frame(1)).f == std::array<std::size_t, 4>{5, 2, 0, 0});
  CHECK(signature_of(m, index.at_frame(2)).f == std::array<std::size_t, 4>{4, 1, 0, 0});
  CHECK(signature_of(m, index.at_frame(3)).f == std::array<std::size_t, 4>{4, 1, 0, 0});
  CHECK(index.at_time(15.0) == index.after(1));
  CHECK(index.at_time(30.0) == index.before(3));
  CHECK_THROWS_AS(index.at_frame(4), medusa::InputError);
  const auto samples = signatures_over_time(index);
  REQUIRE(samples.size() == 4);
  CHECK(samples[1].frames == std::vector<std::size_t>{1});
  CHECK(samples[3].before);
  CHECK(samples[3].frames == std::vector<std::size_t>{3});
  CHECK(samples[1].signature.betti == std::array<std::size_t, 4>{3, 0, 0, 0});
}

TEST_CASE("an inconsistent stream is reported as an internal error", "[medusa][builder]") {
  MedusaCollector collector;
  MedusaBuilder builder(collector);
  // An edge whose vertex is not in K.
  CHECK_THROWS_AS(builder.initial(event_time(0, 0.0), {Simplex{0}, Simplex{0, 1}}), medusa::InternalError);

  MedusaBuilder second(collector);
  second.initial(event_time(0, 0.0), closure({Simplex{0, 1}}));
  Step bad;
  bad.rank = 1;
  bad.left = {Simplex{0}}; // leaves while edge 01 stays
  CHECK_THROWS_AS(second.batch(event_time(1, 1.0), {bad}), medusa::InternalError);

  MedusaBuilder third(collector);
  third.initial(event_time(0, 0.0), closure({Simplex{0, 1}}));
  CHECK_THROWS_AS(third.finish(event_time(0, 1.0)), medusa::InternalError);
}

TEST_CASE("a run with more batches than a virtual time holds is refused as input", "[medusa][builder]") {
  MedusaCollector collector;
  MedusaBuilder builder(collector);
  builder.initial(event_time(0, 0.0), closure({Simplex{0, 1}}));
  Step leave;
  leave.rank = 1;
  leave.kind = medusa::kinetic::StepKind::radius;
  leave.left = {Simplex{0, 1}};
  builder.batch(event_time(max_batch, 1.0), {leave});
  CHECK_THROWS_AS(builder.finish(event_time(max_batch + 1, 2.0)), medusa::InputError);

  MedusaCollector kept;
  MedusaBuilder last(kept);
  last.initial(event_time(0, 0.0), closure({Simplex{0, 1}}));
  last.finish(event_time(max_batch, 2.0));
  CHECK(last.active_cells() == 0);
  const Medusa m = kept.take();
  REQUIRE(m.cells.size() == 3);
  CHECK(m.cells.back().death.batch == max_batch);
}

TEST_CASE("cell ids are refused past the 2^32 a cell's facet list holds", "[medusa][builder]") {
  CellId next = max_cell_count - 1;
  CHECK(take_cell_id(next) == UINT32_MAX);
  CHECK(next == max_cell_count);
  CHECK_THROWS_AS(take_cell_id(next), medusa::InputError);
  CHECK(next == max_cell_count);
}
