// Exact decimal -> grid integer parsing (docs/MATH.md §1.1, §1.2): never through double.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace medusa::io {

// The number m of decimals of a grid scale S = 10^m. Throws InputError unless S is a power of ten
// (1, 10, ..., 10^18).
int scale_decimals(std::int64_t scale);

// A decimal string x read onto the grid of scale S: X = x * S, exactly or rounded.
struct GridDecimal {
  enum class Problem { none, not_finite, not_decimal, too_many_decimals, out_of_range };
  Problem problem = Problem::none;
  std::int64_t value = 0; // X, when problem == none
  int decimals = 0;       // significant decimals of x (up to 19; 19 stands for more than 18)
  bool rounded = false;   // value is x * S rounded (only with `round`)
  // |x * S - value| in grid units as offset_num / offset_den (0 when exact, at most 1/2 when rounded;
  // exact up to 18 digits beyond the grid, below 10^-18 grid units off beyond that).
  std::int64_t offset_num = 0;
  std::int64_t offset_den = 1;
};

// Reads "[+-]digits[.digits][(e|E)[+-]digits]" (surrounding blanks ignored; the exponent only
// moves the decimal point) as X = x * S exactly (docs/MATH.md §1.2), never through double. A value
// with more significant decimals than S holds is Problem::too_many_decimals, or with `round` the
// nearest grid value, ties to even, with its offset. Trailing zeros are exact and accepted. NaN,
// infinities and anything non-numeric are problems too. Never throws.
GridDecimal read_grid_decimal(std::string_view text, std::int64_t scale, bool round);

// read_grid_decimal without rounding; any problem is an InputError starting with `where` (e.g.
// "cells.csv:12: column xCOM of cell 5").
std::int64_t parse_scaled_decimal(std::string_view text, std::int64_t scale, const std::string& where);

// The problem of `d` read from `text` at scale S, in words ("'1.2345678' has 7 decimals, more ...").
std::string grid_decimal_problem(const GridDecimal& d, std::string_view text, std::int64_t scale);

// Parses a decimal integer "[+-]digits" (surrounding blanks ignored); InputError otherwise.
std::int64_t parse_integer(std::string_view text, const std::string& where);

// Non-throwing core of parse_integer for hot loops: false if `text` is not exactly an int64.
bool try_parse_integer(std::string_view text, std::int64_t& value);

} // namespace medusa::io
