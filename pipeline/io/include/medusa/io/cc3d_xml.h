// The few facts medusa needs from a CompuCell3D CC3DML file (Simulation/*.xml): lattice size,
// boundary conditions and type names. Not a general XML parser: it looks for the Potts tags.
#pragma once

#include "medusa/core/error.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace medusa::io {

struct Cc3dSimulation {
  std::string path;
  std::array<std::int64_t, 3> dimensions{}; // <Dimensions x= y= z=/>
  std::array<bool, 3> periodic{};           // <Boundary_x>Periodic</Boundary_x> etc.
  std::vector<std::string> type_names;      // <CellType TypeName= TypeId=/>, index = type id
  std::int64_t steps = 0;                   // <Steps>N</Steps>: MCS 0 to N - 1 (0 if absent)
};

// A CC3DML file without <Dimensions>: not the simulation's lattice description (another XML).
class NotASimulation : public InputError {
public:
  using InputError::InputError;
};

// Throws NotASimulation if the file has no <Dimensions x= y= z=/>, and InputError naming the file if
// it cannot be read or ends before </Potts> and </CompuCell3D> (cut off).
Cc3dSimulation read_cc3d_xml(const std::string& path);

// "x", "x,y", ... for the periodic axes; empty if none.
std::string periodic_axes(const Cc3dSimulation& sim);

} // namespace medusa::io
