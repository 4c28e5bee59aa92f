// Prints the library's version and what a store holds, through the installed headers and libraries.
#include "medusa/core/error.h"
#include "medusa/core/version.h"
#include "medusa/medusa/store_reader.h"

#include <iostream>

int main(int argc, char** argv) {
  std::cout << "medusa " << medusa::version << "\n";
  if (argc < 2)
    return 0;
  try {
    const medusa::Medusa m = medusa::read_store(argv[1]);
    std::cout << "store version " << m.run.software_version << ", " << m.input.cells.size()
              << " trajectories, " << m.cells.size() << " medusa cells\n";
  } catch (const medusa::Error& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
