// The fate of an essential class's ring of cells (pipeline/cli/ring_fate.cpp) on a medusa of four
// edges whose lifetimes are set by hand: whole at the end, broken open at the first death after the
// class is born, or never whole at one time when an edge left before the class was born.
#include "ring_fate.h"

#include <catch2/catch.hpp>

using medusa::cli::ring_fate;
using medusa::cli::RingFate;

namespace {

medusa::VirtualTime at(std::uint32_t batch, double time) { return {batch, 0, time}; }

// A square 0-1-2-3 of edge cells with the given deaths, born at batches 1..4 (times 10..40); the run
// ends at batch 100 (time 1000).
medusa::Medusa square(const std::vector<medusa::VirtualTime>& deaths) {
  medusa::Medusa m;
  m.end = at(100, 1000);
  const std::vector<std::pair<medusa::VertexId, medusa::VertexId>> edges = {{0, 1}, {1, 2}, {2, 3}, {0, 3}};
  for (std::size_t k = 0; k < edges.size(); ++k) {
    medusa::Cell c;
    c.id = k;
    c.vertices = {edges[k].first, edges[k].second};
    c.birth = at(static_cast<std::uint32_t>(k + 1), 10.0 * static_cast<double>(k + 1));
    c.death = deaths[k];
    m.cells.push_back(c);
  }
  return m;
}

const std::vector<medusa::CellId> ring = {0, 1, 2, 3};

const medusa::VirtualTime end_of_run = at(100, 1000);
const medusa::VirtualTime born = at(4, 40); // the last edge closes the square

RingFate fate_of(const std::vector<medusa::VirtualTime>& deaths) {
  const medusa::Medusa m = square(deaths);
  return ring_fate(m, medusa::persistence::CellLists::List(ring), born);
}

} // namespace

TEST_CASE("A ring whose cells all live to the end is whole at the end") {
  CHECK(fate_of({end_of_run, end_of_run, end_of_run, end_of_run}).state == RingFate::State::whole_at_end);
}

TEST_CASE("A ring broke open when the first of its cells left after the class was born") {
  const RingFate f = fate_of({end_of_run, at(70, 700), at(50, 500), end_of_run});
  CHECK(f.state == RingFate::State::broke);
  CHECK(f.broke_at == 500);
}

TEST_CASE("A ring with a cell that left before the class was born was never whole at one time") {
  // Edge 0-1 left at batch 3, before the square closed at batch 4: a loop in space-time.
  CHECK(fate_of({at(3, 30), end_of_run, end_of_run, end_of_run}).state == RingFate::State::never_whole);
}

TEST_CASE("Essential classes rank by how long their ring stayed whole: whole at the end, then the "
          "later break, then never whole, with clusters first") {
  using medusa::cli::essential_order;
  const medusa::Medusa whole = square({end_of_run, end_of_run, end_of_run, end_of_run});
  const medusa::Medusa late = square({end_of_run, at(70, 700), at(60, 600), end_of_run});
  const medusa::Medusa early = square({end_of_run, at(70, 700), at(50, 500), end_of_run});
  const medusa::Medusa never = square({at(3, 30), end_of_run, end_of_run, end_of_run});
  const auto order = [](const medusa::Medusa& m, int dim) {
    // The class is born at time 40 with the square's last edge, cell 3.
    return essential_order(m, dim, medusa::persistence::CellLists::List(ring), 3, 40);
  };
  CHECK(order(late, 1) == 600 - 40);
  CHECK(order(early, 1) == 500 - 40);
  CHECK(order(whole, 1) > order(late, 1));
  CHECK(order(late, 1) > order(early, 1));
  CHECK(order(early, 1) > order(never, 1));
  CHECK(order(never, 0) ==
        order(whole, 1)); // a cluster never joined ranks with whole rings, whatever its cells
}
