// Betti numbers over Z/2 (libmedusa's homology.h) on complexes whose homology is known on paper, and on
// random complexes against a dense Gaussian elimination of each boundary matrix.
#include "medusa/core/error.h"
#include "medusa/medusa/homology.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <map>
#include <random>
#include <vector>

namespace {

using Face = std::vector<int>;

// Every face of the given simplices, each once, in order of dimension; index of each face.
std::vector<Face> closure(const std::vector<Face>& tops) {
  std::vector<Face> faces;
  for (const Face& t : tops)
    for (unsigned mask = 1; mask < (1u << t.size()); ++mask) {
      Face f;
      for (std::size_t i = 0; i < t.size(); ++i)
        if (mask & (1u << i))
          f.push_back(t[i]);
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end(),
            [](const Face& a, const Face& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

medusa::ChainComplex chain_complex(const std::vector<Face>& faces) {
  std::map<Face, std::size_t> index;
  for (std::size_t i = 0; i < faces.size(); ++i)
    index.emplace(faces[i], i);
  medusa::ChainComplex c;
  for (const Face& f : faces) {
    std::vector<std::size_t> facets;
    if (f.size() > 1)
      for (std::size_t drop = 0; drop < f.size(); ++drop) {
        Face g = f;
        g.erase(g.begin() + static_cast<std::ptrdiff_t>(drop));
        facets.push_back(index.at(g));
      }
    c.add(static_cast<int>(f.size()) - 1, facets);
  }
  return c;
}

std::vector<std::size_t> betti_of(const std::vector<Face>& tops) {
  return medusa::betti_numbers(chain_complex(closure(tops)));
}

// The rank over Z/2 of the boundary matrix from dimension k to k - 1, by dense elimination.
std::size_t dense_rank(const std::vector<Face>& faces, std::size_t k) {
  std::vector<Face> rows, cols;
  for (const Face& f : faces) {
    if (f.size() == k)
      rows.push_back(f);
    if (f.size() == k + 1)
      cols.push_back(f);
  }
  std::vector<std::vector<char>> m(cols.size(), std::vector<char>(rows.size(), 0));
  for (std::size_t c = 0; c < cols.size(); ++c)
    for (std::size_t drop = 0; drop < cols[c].size(); ++drop) {
      Face g = cols[c];
      g.erase(g.begin() + static_cast<std::ptrdiff_t>(drop));
      m[c][static_cast<std::size_t>(std::find(rows.begin(), rows.end(), g) - rows.begin())] = 1;
    }
  std::size_t rank = 0;
  for (std::size_t r = 0; r < rows.size() && rank < cols.size(); ++r) {
    std::size_t p = rank;
    while (p < cols.size() && !m[p][r])
      ++p;
    if (p == cols.size())
      continue;
    std::swap(m[p], m[rank]);
    for (std::size_t c = 0; c < cols.size(); ++c)
      if (c != rank && m[c][r])
        for (std::size_t j = 0; j < rows.size(); ++j)
          m[c][j] ^= m[rank][j];
    ++rank;
  }
  return rank;
}

} // namespace

TEST_CASE("the boundary of a tetrahedron has the homology of a sphere, and the filled one of a point",
          "[homology]") {
  CHECK(betti_of({{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}) == std::vector<std::size_t>{1, 0, 1});
  CHECK(betti_of({{0, 1, 2, 3}}) == std::vector<std::size_t>{1, 0, 0, 0});
  CHECK(betti_of({{0, 1}, {1, 2}, {0, 2}, {5}}) == std::vector<std::size_t>{2, 1});
}

TEST_CASE("the seven-vertex torus has two loops and the six-vertex projective plane one loop and one cavity "
          "over Z/2",
          "[homology]") {
  std::vector<Face> torus;
  for (int i = 0; i < 7; ++i) {
    Face a{i, (i + 1) % 7, (i + 3) % 7}, b{i, (i + 2) % 7, (i + 3) % 7};
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    torus.push_back(a);
    torus.push_back(b);
  }
  CHECK(closure(torus).size() == 7 + 21 + 14);
  CHECK(betti_of(torus) == std::vector<std::size_t>{1, 2, 1});
  const std::vector<Face> rp2{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 1, 5},
                              {1, 2, 4}, {2, 3, 5}, {1, 3, 4}, {1, 3, 5}, {2, 4, 5}};
  CHECK(closure(rp2).size() == 6 + 15 + 10);
  CHECK(betti_of(rp2) == std::vector<std::size_t>{1, 1, 1});
}

TEST_CASE("random complexes have the Betti numbers of a dense elimination of their boundary matrices",
          "[homology]") {
  const unsigned seed = std::random_device{}();
  std::cout << "homology random complexes seed " << seed << '\n';
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 60; ++trial) {
    const int vertices = 5 + static_cast<int>(rng() % 6);
    std::vector<Face> tops;
    const int count = 1 + static_cast<int>(rng() % 14);
    for (int t = 0; t < count; ++t) {
      Face f;
      const std::size_t size = 1 + rng() % 4;
      while (f.size() < size) {
        const int v = static_cast<int>(rng() % static_cast<unsigned>(vertices));
        if (std::find(f.begin(), f.end(), v) == f.end())
          f.push_back(v);
      }
      std::sort(f.begin(), f.end());
      tops.push_back(f);
    }
    const std::vector<Face> faces = closure(tops);
    std::size_t top = 0;
    std::vector<std::size_t> f(5, 0);
    for (const Face& x : faces) {
      ++f[x.size() - 1];
      top = std::max(top, x.size() - 1);
    }
    std::vector<std::size_t> expected(top + 1);
    for (std::size_t k = 0; k <= top; ++k)
      expected[k] = f[k] - (k == 0 ? 0 : dense_rank(faces, k)) - dense_rank(faces, k + 1);
    INFO("seed " << seed << ", trial " << trial);
    CHECK(medusa::betti_numbers(chain_complex(faces)) == expected);
  }
}

TEST_CASE("a poll that throws stops a long computation", "[homology]") {
  std::vector<Face> path;
  for (int v = 0; v < 10000; ++v)
    path.push_back({v, v + 1});
  const medusa::ChainComplex c = chain_complex(closure(path));
  int calls = 0;
  CHECK(medusa::betti_numbers(c, [&] { ++calls; }) == std::vector<std::size_t>{1, 0});
  CHECK(calls >= 2);
  struct Stop {};
  CHECK_THROWS_AS(medusa::betti_numbers(c, [] { throw Stop{}; }), Stop);
}

TEST_CASE("a malformed complex is refused", "[homology]") {
  medusa::ChainComplex c;
  c.add(0, std::vector<std::size_t>{});
  c.add(1, std::vector<std::size_t>{0});
  CHECK_THROWS_AS(medusa::betti_numbers(c), medusa::InternalError);
  medusa::ChainComplex d;
  d.add(0, std::vector<std::size_t>{});
  d.add(1, std::vector<std::size_t>{0, 7});
  CHECK_THROWS_AS(medusa::betti_numbers(d), medusa::InternalError);
  CHECK(medusa::betti_numbers(medusa::ChainComplex{}).empty());
}
