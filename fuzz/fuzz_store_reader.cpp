// Fuzzes medusa::complex::read_store with arbitrary bytes as an HDF5 store. StoreError is the
// expected answer to a corrupt file; a crash or sanitizer report in medusa's reader is a finding.
// See README.md for what is known about crashes inside libhdf5 itself.
#include "fuzz_input_file.h"
#include "medusa/complex/store_reader.h"
#include "medusa/kinetic/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = medusa::fuzz::write_input(data, size, "-store.h5");
  try {
    medusa::complex::read_store(path);
  } catch (const medusa::Error&) {
  }
  return 0;
}
