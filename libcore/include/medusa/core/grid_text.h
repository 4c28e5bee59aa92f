// A grid coordinate as the decimal it stands for (docs/MATH.md §1.1), for messages that name a position.
#pragma once

#include <cstdint>
#include <string>

namespace medusa {

// X / S as a decimal ("27.5", "-0.000001"): S is a power of ten (docs/MATH.md §1.1).
inline std::string grid_coordinate_text(std::int64_t x, std::int64_t scale) {
  const bool negative = x < 0;
  const std::uint64_t v = negative ? 0 - static_cast<std::uint64_t>(x) : static_cast<std::uint64_t>(x);
  const std::uint64_t s = static_cast<std::uint64_t>(scale);
  std::string fraction = std::to_string(v % s + s).substr(1); // v % s with leading zeros
  while (!fraction.empty() && fraction.back() == '0')
    fraction.pop_back();
  return (negative ? "-" : "") + std::to_string(v / s) + (fraction.empty() ? "" : "." + fraction);
}

} // namespace medusa
