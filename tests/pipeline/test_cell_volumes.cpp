#include "io_test_support.h"
#include "medusa/io/cell_volumes.h"

#include <cmath>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

TEST_CASE("The median cell volume runs over every cell and frame", "[io][volumes]") {
  CHECK(median_cell_volume({{125, 120}, {130}}) == 125.0);
  CHECK(median_cell_volume({{1, 2}, {3, 10}}) == 2.5);
  CHECK_THAT(io::test::input_error([] { median_cell_volume({}); }), Contains("no cell volumes"));
}

TEST_CASE("The equivalent radius is that of the ball or disc of the same volume", "[io][volumes]") {
  const double pi = std::acos(-1.0);
  // (4/3) pi r^3 = V  and  pi r^2 = V, checked on exact inputs.
  CHECK(equivalent_radius(4.0 / 3.0 * pi * 27.0, 3) == Approx(3.0));
  CHECK(equivalent_radius(pi * 4.0, 2) == Approx(2.0));
  CHECK(equivalent_radius(125, 3) ==
        Approx(std::cbrt(3.0 * 125.0 / (4.0 * pi)))); // a CC3D cell of 5^3 voxels
  CHECK_THAT(io::test::input_error([] { equivalent_radius(1, 4); }), Contains("dimension"));
}
