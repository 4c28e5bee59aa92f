#include "io_test_support.h"
#include "medusa/io/cc3d_xml.h"

#include <fstream>

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

TEST_CASE("The CC3DML of a real periodic run gives its lattice, periodic axes and type names", "[io][xml]") {
  const Cc3dSimulation sim = read_cc3d_xml(io::test::data("cc3d/periodic_3d/Simulation/periodic_3d.xml"));
  CHECK(sim.dimensions == std::array<std::int64_t, 3>{50, 50, 40});
  CHECK(sim.periodic == std::array<bool, 3>{true, true, false});
  CHECK(periodic_axes(sim) == "x,y");
  CHECK(sim.type_names == std::vector<std::string>{"Medium", "Condensing", "NonCondensing"});
  const Cc3dSimulation flat = read_cc3d_xml(io::test::data("cc3d/sorting_2d/Simulation/sorting_2d.xml"));
  CHECK(flat.dimensions == std::array<std::int64_t, 3>{100, 100, 1});
  CHECK(periodic_axes(flat).empty());
  CHECK(sim.steps == 2001);
  CHECK(flat.steps == 10000);
}

TEST_CASE("Commented-out CC3DML tags are ignored and a missing Dimensions is refused", "[io][xml]") {
  io::test::TempDir dir;
  std::ofstream(dir.file("a.xml"))
      << "<CompuCell3D><Potts><!-- <Boundary_x>Periodic</Boundary_x> -->\n"
         "<Dimensions  z='3' x=\"7\"  y = \"5\" />\n<Boundary_z> Periodic </Boundary_z>"
         "</Potts></CompuCell3D>\n";
  const Cc3dSimulation sim = read_cc3d_xml(dir.file("a.xml"));
  CHECK(sim.dimensions == std::array<std::int64_t, 3>{7, 5, 3});
  CHECK(periodic_axes(sim) == "z");
  std::ofstream(dir.file("b.xml")) << "<CompuCell3D><Potts></Potts></CompuCell3D>\n";
  CHECK_THAT(io::test::input_error([&] { read_cc3d_xml(dir.file("b.xml")); }),
             Contains("b.xml") && Contains("Dimensions"));
}

TEST_CASE("A CC3DML file cut off before the end of Potts is refused, not read as open boundaries",
          "[io][xml]") {
  io::test::TempDir dir;
  const std::string whole = "<CompuCell3D>\n<Potts>\n<Dimensions x=\"50\" y=\"50\" z=\"40\"/>\n"
                            "<Boundary_x>Periodic</Boundary_x>\n</Potts>\n</CompuCell3D>\n";
  std::ofstream(dir.file("whole.xml")) << whole;
  CHECK(periodic_axes(read_cc3d_xml(dir.file("whole.xml"))) == "x");
  // Cut just before <Boundary_x>: its periodic boundary would otherwise vanish.
  std::ofstream(dir.file("cut.xml")) << whole.substr(0, whole.find("<Boundary_x>"));
  CHECK_THAT(io::test::input_error([&] { read_cc3d_xml(dir.file("cut.xml")); }),
             Contains("cut.xml") && Contains("boundary conditions cannot be read"));
}
