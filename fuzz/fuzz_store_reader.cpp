// Fuzzes medusa::read_store with arbitrary bytes as an HDF5 store. StoreError is the
// expected answer to a corrupt file; a crash or sanitizer report in medusa's reader is a finding.
// See README.md for what is known about crashes inside libhdf5 itself.
#include "fuzz_input_file.h"
#include "medusa/core/error.h"
#include "medusa/medusa/store_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = medusa::fuzz::write_input(data, size, "-store.h5");
  try {
    medusa::read_store(path);
  } catch (const medusa::Error&) {
  }
  return 0;
}
