// GUDHI's exact alpha complex of a static point set (via /usr/bin/python3), the oracle for K_t of
// the medusa tests: the simplices of the alpha complex pruned at rho^2 (GUDHI filtrations are
// squared radii) and its Betti numbers over Z/2 (docs/MATH.md §7.5).
#pragma once

#include "command_output.h"
#include "temp_files.h"

#include "medusa/kinetic/simplex.h"

#include <catch2/catch.hpp>

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace medusa::test {

struct GudhiAlphaComplex {
  std::array<std::size_t, 4> betti{};
  std::vector<std::vector<kinetic::VertexId>> simplices; // vertices are indices into the point list
};

constexpr const char* gudhi_alpha_script = R"PY(
import sys, gudhi
pts = [list(map(float, l.split())) for l in open(sys.argv[1]) if l.strip()]
st = gudhi.AlphaComplex(points=pts, precision='exact').create_simplex_tree()
st.prune_above_filtration(float(sys.argv[2]))
st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
b = list(st.betti_numbers()) + [0, 0, 0, 0]
print("betti", *b[:4])
for s, f in st.get_simplices():
    print("s", *s)
)PY";

// `points`: integer coordinates (x, y, z), exact as doubles below 2^53, so GUDHI sees the exact
// positions; `rho2`: the squared radius as decimal text; `tag` names the temporary files.
template <class Point>
GudhiAlphaComplex gudhi_alpha_complex(const std::vector<Point>& points, const std::string& rho2,
                                      const std::string& tag) {
  const std::string script = temp_path("gudhi-" + tag + ".py");
  const std::string input = temp_path("gudhi-" + tag + ".txt");
  RemoveFiles cleanup{{script, input}};
  std::ofstream(script) << gudhi_alpha_script;
  {
    std::ofstream out(input);
    for (const auto& p : points)
      out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  const std::string text =
      command_output(std::string(MEDUSA_PYTHON) + " " + script + " " + input + " " + rho2);
  GudhiAlphaComplex result;
  std::istringstream lines(text);
  std::string line;
  bool has_betti = false;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::string head;
    in >> head;
    if (head == "betti") {
      in >> result.betti[0] >> result.betti[1] >> result.betti[2] >> result.betti[3];
      has_betti = true;
    } else if (head == "s") {
      std::vector<kinetic::VertexId> v;
      for (kinetic::VertexId x; in >> x;)
        v.push_back(x);
      result.simplices.push_back(std::move(v));
    }
  }
  REQUIRE(has_betti);
  return result;
}

} // namespace medusa::test
