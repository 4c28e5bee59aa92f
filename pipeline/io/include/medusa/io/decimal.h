// Exact decimal -> grid integer parsing (docs/MATH.md §1.1, §1.2): never through double.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace medusa::io {

// The number m of decimals of a grid scale S = 10^m. Throws InputError unless S is a power of ten
// (1, 10, ..., 10^18).
int scale_decimals(std::int64_t scale);

// Parses a decimal string "[+-]digits[.digits]" into X = x * S exactly (docs/MATH.md §1.2):
// X = sign * (int_part * 10^m + frac_part padded right to m digits). A value with more than m
// significant decimals is an InputError (never rounded); trailing zeros beyond m are exact and
// accepted. NaN, infinities, exponent notation and anything non-numeric are InputErrors. Surrounding
// blanks are ignored. `where` (e.g. "cells.csv:12: column xCOM of cell 5") starts every message.
std::int64_t parse_scaled_decimal(std::string_view text, std::int64_t scale, const std::string& where);

// Parses a decimal integer "[+-]digits" (surrounding blanks ignored); InputError otherwise.
std::int64_t parse_integer(std::string_view text, const std::string& where);

// Non-throwing core of parse_integer for hot loops: false if `text` is not exactly an int64.
bool try_parse_integer(std::string_view text, std::int64_t& value);

} // namespace medusa::io
