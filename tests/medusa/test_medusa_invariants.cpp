// Invariants of the medusa of real CompuCell3D runs built by the kinetic engine: d d = 0 (Z/2),
// nested lifetimes (docs/MATH.md §6.4), Euler characteristics of every K_t and of M (docs/MATH.md §7.5), and
// the Betti numbers of K_t at frames against GUDHI's exact alpha complex of that frame's positions.
#include "cc3d_runs.h"
#include "kinetic_run.h"
#include "medusa/medusa/complex_index.h"
#include "medusa/medusa/signatures.h"
#include "medusa/medusa/store_reader.h"
#include "medusa/persistence/diagram.h"
#include "medusa/persistence/euler.h"
#include "medusa/persistence/filtration.h"
#include "medusa_fixtures.h"
#include "support/gudhi_oracle.h"

#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

using namespace medusa;
using namespace medusa::test;

namespace {

medusa::Medusa medusa_of(const std::string& name, std::size_t frames, const std::string& tag) {
  const kinetic::Trajectories t = read_cc3d(name, frames);
  REQUIRE(t.frames() == frames);
  const std::string store = temp_path(tag + ".h5");
  run_into_store(t, "3", kinetic::squared_radius_from_decimal("3", t.scale), store, 50);
  medusa::Medusa m = medusa::read_store(store);
  std::remove(store.c_str());
  return m;
}

long long alternating(const std::array<std::size_t, 4>& x) {
  return static_cast<long long>(x[0]) - static_cast<long long>(x[1]) + static_cast<long long>(x[2]) -
         static_cast<long long>(x[3]);
}

void check_invariants(const medusa::Medusa& m) {
  REQUIRE(!m.cells.empty());
  std::size_t boundaries = 0, nested = 0;
  for (const medusa::Cell& c : m.cells) {
    // d d c = 0 over Z/2: every face of codimension 2 is reached an even number of times.
    std::map<medusa::CellId, int> parity;
    for (medusa::CellId f : c.facets)
      for (medusa::CellId g : m.cell(f).facets)
        parity[g] ^= 1;
    for (const auto& [g, p] : parity) {
      CAPTURE(c.id, g);
      REQUIRE(p == 0);
    }
    boundaries += c.dim() >= 2;
    // docs/MATH.md §6.4: the lifetime of a facet contains its coface's.
    for (medusa::CellId f : c.facets) {
      const medusa::Cell& facet = m.cell(f);
      CAPTURE(c.id, f);
      REQUIRE(facet.birth <= c.birth);
      REQUIRE(c.death <= facet.death);
      ++nested;
    }
  }
  REQUIRE(boundaries > 0);
  REQUIRE(nested > 0);

  // chi(K_t) = sum (-1)^k beta_k = sum (-1)^k f_k after every batch and at every frame.
  const medusa::ComplexIndex index(m);
  const std::vector<medusa::SignatureSample> samples = medusa::signatures_over_time(index);
  REQUIRE(samples.size() == m.batches.size() + 1);
  for (const medusa::SignatureSample& s : samples) {
    CAPTURE(s.batch, s.before);
    REQUIRE(alternating(s.signature.betti) == s.signature.euler);
    REQUIRE(alternating(s.signature.f) == s.signature.euler);
  }
  for (std::size_t k = 0; k < m.input.frames(); ++k) {
    const medusa::Signature s = medusa::signature_of(m, index.at_frame(k));
    CAPTURE(k);
    REQUIRE(alternating(s.betti) == alternating(s.f));
  }

  // chi(M) = sum (-1)^k #essential_k (docs/MATH.md §7.5), forward and reverse (both compute H(M)).
  long long chi = 0;
  for (const medusa::Cell& c : m.cells)
    chi += c.dim() % 2 == 0 ? 1 : -1;
  for (persistence::Direction d : {persistence::Direction::forward, persistence::Direction::reverse}) {
    const persistence::Filtration f = persistence::make_filtration(m.cells, d);
    const persistence::Diagram diagram = persistence::compute_diagram(m.cells, f);
    CHECK(persistence::euler_characteristic(f) == chi);
    CHECK(persistence::essential_euler_characteristic(diagram) == chi);
    CHECK_NOTHROW(persistence::check_euler(diagram, f));
  }
}

} // namespace

TEST_CASE("the medusa of a real CC3D run satisfies dd = 0, nested lifetimes and the Euler checks",
          "[medusa][kinetic][invariants][cc3d]") {
  check_invariants(medusa_of("nosorting_3d", 6, "invariants-nosorting"));
}

TEST_CASE("the medusa of a CC3D run with divisions and deaths satisfies dd = 0, nested lifetimes and "
          "the Euler checks",
          "[medusa][kinetic][invariants][cc3d]") {
  check_invariants(medusa_of("mitosis_3d", 8, "invariants-mitosis"));
}

TEST_CASE("Betti numbers of K_t at frames of a real CC3D run agree with GUDHI's alpha complex",
          "[medusa][kinetic][gudhi][cc3d]") {
  // Frames 1..3 only: at frame 0 the CC3D centres lie on a lattice (degenerate), where the store's
  // K(t_0+) may differ from GUDHI's static complex; later centres are generic.
  const medusa::Medusa m = medusa_of("nosorting_3d", 5, "gudhi-nosorting");
  const medusa::ComplexIndex index(m);
  const kinetic::SquaredRadius rho2 = kinetic::squared_radius_from_decimal("3", m.input.scale);
  REQUIRE(rho2.den == 1);
  std::size_t compared = 0;
  for (std::size_t k : {1u, 2u, 3u}) {
    CAPTURE(k);
    std::vector<kinetic::GridPoint> points;
    std::vector<kinetic::VertexId> vertex_of_point;
    for (std::size_t v = 0; v < m.input.cells.size(); ++v)
      if (m.input.cells[v].present(k)) {
        points.push_back(m.input.cells[v].at(k));
        vertex_of_point.push_back(static_cast<kinetic::VertexId>(v));
      }
    const GudhiAlphaComplex oracle =
        gudhi_alpha_complex(points, rho2.num.get_str(), "frame" + std::to_string(k));
    const std::vector<medusa::CellId> cells = index.at_frame(k);
    const medusa::Signature s = medusa::signature_of(m, cells);
    CAPTURE(s.f[0], s.f[1], s.f[2], s.f[3]);
    CHECK(s.betti == oracle.betti);
    // The complexes themselves agree too (vertex ids mapped back to trajectories).
    SimplexSet mapped;
    for (const auto& simplex : oracle.simplices) {
      std::vector<kinetic::VertexId> v;
      for (kinetic::VertexId i : simplex)
        v.push_back(vertex_of_point[static_cast<std::size_t>(i)]);
      std::sort(v.begin(), v.end());
      mapped.insert(v);
    }
    CHECK(tuples(m, cells) == mapped);
    ++compared;
  }
  REQUIRE(compared == 3);
}
