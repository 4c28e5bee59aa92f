// Fuzzes medusa::io::read_csv with arbitrary bytes as a CompuCell3D centre CSV (plain or gzip: zlib's
// gzopen reads both, so gzip headers in the corpus reach the decompressor too). InputError is the
// expected answer to garbage; a crash, a sanitizer report or a hang is a finding. Each input is read
// twice: refusing centres beyond the grid, and rounding them (--round-csv).
#include "fuzz_input_file.h"
#include "medusa/core/error.h"
#include "medusa/io/csv_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = medusa::fuzz::write_input(data, size, "-cells.csv");
  for (const bool round : {false, true}) {
    medusa::io::CsvOptions options;
    options.round = round;
    try {
      medusa::io::read_csv(path, options);
    } catch (const medusa::Error&) {
    }
  }
  return 0;
}
