// The readers take paths, not buffers, so each fuzz input is written to a private temporary file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace medusa::fuzz {

// Writes `data` to a file in the temporary directory whose name ends with `suffix` (the readers
// choose nothing by extension except the VTK step name, so the suffix only keeps files recognisable)
// and returns its path. The same path is reused for every input of one process.
const std::string& write_input(const std::uint8_t* data, std::size_t size, const std::string& suffix);

} // namespace medusa::fuzz
