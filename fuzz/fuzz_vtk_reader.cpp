// Fuzzes medusa::io::read_vtk_snapshot with arbitrary bytes as a CompuCell3D lattice snapshot (legacy
// VTK STRUCTURED_POINTS, ASCII or BINARY, plain or gzip). InputError is the expected answer to
// garbage; a crash, a sanitizer report, a hang or an allocation beyond -rss_limit_mb is a finding.
#include "fuzz_input_file.h"
#include "medusa/core/error.h"
#include "medusa/io/vtk_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = medusa::fuzz::write_input(data, size, "-Step_000.vtk");
  try {
    medusa::io::read_vtk_snapshot(path, 1000);
  } catch (const medusa::Error&) {
  }
  return 0;
}
