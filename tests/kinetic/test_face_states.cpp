// FaceStates (the alpha-complex state of the simplices of Del) checks its own invariants against the
// triangulation: on the augmented triangulation of one tetrahedron (one triangle in the plane) whose
// every simplex is short and in K, the counts worked out by hand pass, and each way of breaking them
// is named.
#include "cell_triangulation.h"
#include "face_states.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace medusa::kinetic;
using namespace medusa::kinetic::detail;

namespace {

template <int D> CellTriangulation<D> augmented(const Simplex& top) {
  std::vector<typename CellTriangulation<D>::NewTop> tops{{top, 1}};
  for (std::size_t i = 0; i < top.size(); ++i)
    tops.push_back({top.facet(i).with(infinite_vertex), 0});
  CellTriangulation<D> cells;
  cells.assign(tops);
  return cells;
}

struct Fixture {
  CellTriangulation<2> planar;
  CellTriangulation<3> spatial;
  FaceStates faces;
  std::vector<char> alive;

  // The top simplex `top` and the infinite vertex over each of its facets; every finite simplex
  // short and in K, so that only the top simplex is on the frontier (it holds certificate 0).
  explicit Fixture(const Simplex& top) : alive(top.size(), 1) {
    if (top.size() == 3)
      planar = augmented<2>(top);
    else
      spatial = augmented<3>(top);
    const std::size_t n = top.size();
    for_each_face(top, [&](const Simplex& s) {
      if (s.size() == 1)
        return;
      Face& f = *faces.add(s).first;
      f.is_short = f.in_k = true;
      // By hand: a k-simplex of one top simplex of n vertices has n - k - 1 finite cofaces (the other
      // vertices), all short and in K. It lies in the top simplex, and in the infinite simplex over
      // each facet of the top simplex that contains it: those leaving out a vertex outside s.
      f.short_cofaces = f.k_cofaces = static_cast<int>(n - s.size());
      f.tops = 1 + static_cast<int>(n - s.size());
      f.cert = s.size() == n ? 0 : -1;
    });
  }
  std::string violation() const {
    return alive.size() == 3 ? faces.first_violation(planar, alive) : faces.first_violation(spatial, alive);
  }
};

bool names(const std::string& violation, const char* what) {
  return violation.find(what) != std::string::npos;
}

} // namespace

TEST_CASE("the face states' own check accepts counts worked out by hand and names each way of breaking them",
          "[kinetic][faces]") {
  for (const Simplex& top : {Simplex{0, 1, 2}, Simplex{0, 1, 2, 3}}) {
    CAPTURE(top.size());
    REQUIRE(Fixture(top).violation().empty());
    {
      Fixture x(top);
      x.faces.at(Simplex{0, 1}).short_cofaces -= 1;
      REQUIRE(names(x.violation(), "wrong counts of short cofaces"));
    }
    {
      Fixture x(top);
      x.faces.at(Simplex{0, 1}).tops += 1;
      REQUIRE(names(x.violation(), "wrong count of top simplices"));
    }
    {
      Fixture x(top);
      // The edge leaves K while the simplices over it stay: its cofaces' counts are untouched.
      x.faces.at(Simplex{0, 1}).in_k = false;
      REQUIRE(names(x.violation(), "not a complex"));
    }
    {
      Fixture x(top);
      x.alive[2] = 0;
      REQUIRE(names(x.violation(), "not a complex"));
    }
    {
      Fixture x(top);
      x.faces.at(top).cert = -1;
      REQUIRE(names(x.violation(), "on the frontier without a radius certificate"));
    }
    {
      Fixture x(top);
      x.faces.at(Simplex{0, 1}).cert = 7;
      REQUIRE(names(x.violation(), "outside the frontier"));
    }
    {
      Fixture x(top);
      x.faces.add(Simplex{5, 6});
      REQUIRE(names(x.violation(), "not in Del is still recorded"));
    }
    {
      Fixture x(top);
      x.faces.erase(Simplex{0, 2});
      REQUIRE(names(x.violation(), "not recorded"));
    }
  }
}

TEST_CASE("a vertex is in K while its cell lives and is always short, and a simplex not recorded is neither",
          "[kinetic][faces]") {
  Fixture x(Simplex{0, 1, 2});
  REQUIRE(x.faces.in_k(Simplex{1}, x.alive));
  REQUIRE(x.faces.is_short(Simplex{1}));
  x.alive[1] = 0;
  REQUIRE_FALSE(x.faces.in_k(Simplex{1}, x.alive));
  REQUIRE(x.faces.is_short(Simplex{1}));
  REQUIRE(x.faces.in_k(Simplex{0, 1}, x.alive));
  x.faces.at(Simplex{0, 1}).in_k = false;
  x.faces.at(Simplex{0, 1}).is_short = false;
  REQUIRE_FALSE(x.faces.in_k(Simplex{0, 1}, x.alive));
  REQUIRE_FALSE(x.faces.is_short(Simplex{0, 1}));
  REQUIRE_FALSE(x.faces.in_k(Simplex{0, 5}, x.alive));
  REQUIRE_FALSE(x.faces.is_short(Simplex{0, 5}));
}

TEST_CASE("a face's packed fields hold max_face_tops top simplices and twice as many cofaces") {
  // face.h: mid-change, a coface count counts cofaces of the old and of the new triangulation, at most
  // 2 max_face_tops; the fields share one word and must not spill into each other.
  Face f;
  REQUIRE(f.tops == 0);
  REQUIRE(f.short_cofaces == 0);
  REQUIRE(f.k_cofaces == 0);
  REQUIRE_FALSE(f.is_short);
  REQUIRE_FALSE(f.in_k);
  f.is_short = f.in_k = true;
  f.tops = static_cast<unsigned>(max_face_tops);
  f.short_cofaces = 2 * max_face_tops;
  f.k_cofaces = -2 * max_face_tops;
  f.cert = 7;
  f.cell = 9;
  REQUIRE(f.is_short);
  REQUIRE(f.in_k);
  REQUIRE(f.tops == static_cast<unsigned>(max_face_tops));
  REQUIRE(f.short_cofaces == 2 * max_face_tops);
  REQUIRE(f.k_cofaces == -2 * max_face_tops);
  f.short_cofaces += -1;
  f.k_cofaces += 1;
  REQUIRE(f.short_cofaces == 2 * max_face_tops - 1);
  REQUIRE(f.k_cofaces == -2 * max_face_tops + 1);
  REQUIRE(f.cert == 7);
  REQUIRE(f.cell == 9);
}
