#include "medusa/io/decimal.h"

#include "medusa/core/error.h"
#include "medusa/io/excerpt.h"

#include <algorithm>
#include <cctype>
#include <limits>

namespace medusa::io {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

bool is_non_finite(std::string_view s) {
  if (!s.empty() && (s.front() == '+' || s.front() == '-'))
    s.remove_prefix(1);
  return equals_ignoring_case(s, "nan") || equals_ignoring_case(s, "inf") ||
         equals_ignoring_case(s, "infinity");
}

// value = value * 10 + digit without overflow; false on overflow.
bool push_digit(std::int64_t& value, char digit) {
  const std::int64_t d = digit - '0';
  if (value > (std::numeric_limits<std::int64_t>::max() - d) / 10)
    return false;
  value = value * 10 + d;
  return true;
}

} // namespace

int scale_decimals(std::int64_t scale) {
  int m = 0;
  std::int64_t s = scale;
  while (s > 1 && s % 10 == 0) {
    s /= 10;
    ++m;
  }
  if (scale <= 0 || s != 1)
    throw InputError("grid scale must be a power of ten (1, 10, ..., 10^18), got " + std::to_string(scale));
  return m;
}

bool try_parse_integer(std::string_view s, std::int64_t& value) {
  s = trim(s);
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  if (s.empty())
    return false;
  std::int64_t v = 0;
  for (char c : s)
    if (c < '0' || c > '9' || !push_digit(v, c))
      return false;
  value = negative ? -v : v;
  return true;
}

std::int64_t parse_integer(std::string_view text, const std::string& where) {
  std::int64_t v = 0;
  if (!try_parse_integer(text, v)) {
    if (is_non_finite(trim(text)))
      throw InputError(where + ": '" + excerpt(trim(text)) + "' is not a finite number");
    throw InputError(where + ": '" + excerpt(trim(text)) + "' is not an integer");
  }
  return v;
}

GridDecimal read_grid_decimal(std::string_view text, std::int64_t scale, bool round) {
  using Problem = GridDecimal::Problem;
  const int m = scale_decimals(scale);
  GridDecimal d;
  const auto problem = [&d](Problem p) {
    d.problem = p;
    return d;
  };
  std::string_view s = trim(text);
  if (is_non_finite(s))
    return problem(Problem::not_finite);
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  // An exponent only moves the decimal point (docs/MATH.md §1.2): "1.5e-3" is the decimal 0.0015.
  std::int64_t exponent = 0;
  if (const std::size_t e = s.find_first_of("eE"); e != std::string_view::npos) {
    std::string_view exponent_text = s.substr(e + 1);
    bool exponent_negative = false;
    if (!exponent_text.empty() && (exponent_text.front() == '+' || exponent_text.front() == '-')) {
      exponent_negative = exponent_text.front() == '-';
      exponent_text.remove_prefix(1);
    }
    if (exponent_text.empty())
      return problem(Problem::not_decimal);
    for (char c : exponent_text) {
      if (c < '0' || c > '9')
        return problem(Problem::not_decimal);
      if (exponent < 100000) // larger exponents fail below as out of range or as too many decimals
        exponent = exponent * 10 + (c - '0');
    }
    exponent = exponent_negative ? -exponent : exponent;
    s = s.substr(0, e);
  }
  const std::size_t dot = s.find('.');
  const std::string_view int_part = s.substr(0, dot);
  const std::string_view frac_part = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  if (int_part.empty() && frac_part.empty())
    return problem(Problem::not_decimal);
  for (std::string_view part : {int_part, frac_part})
    for (char c : part)
      if (c < '0' || c > '9')
        return problem(Problem::not_decimal);
  // The significant digits d_1..d_k (no leading or trailing zeros) and the point p with
  // x = 0.d_1..d_k * 10^p, so that X = d_1..d_k * 10^(p + m - k).
  std::string digits;
  digits.reserve(int_part.size() + frac_part.size());
  digits.append(int_part).append(frac_part);
  const std::size_t first = digits.find_first_not_of('0');
  if (first == std::string::npos)
    return d;
  digits.erase(0, first);
  digits.erase(digits.find_last_not_of('0') + 1);
  const std::int64_t k = static_cast<std::int64_t>(digits.size());
  const std::int64_t point =
      static_cast<std::int64_t>(int_part.size()) - static_cast<std::int64_t>(first) + exponent;
  d.decimals = static_cast<int>(std::clamp<std::int64_t>(k - point, 0, 19));
  if (d.decimals > m && !round)
    return problem(Problem::too_many_decimals);
  // The grid value's digits are the first p + m; the rest, r, is the fraction of a grid unit dropped.
  const std::int64_t whole = point + m;
  if (whole > 19)
    return problem(Problem::out_of_range);
  std::int64_t value = 0;
  for (std::int64_t i = 0; i < whole; ++i)
    if (!push_digit(value, i < k ? digits[static_cast<std::size_t>(i)] : '0'))
      return problem(Problem::out_of_range);
  if (whole < k) {
    // r = 0.(-whole zeros when whole < 0) d_{whole+1}..d_k, never 0 (d_k is not 0).
    const std::int64_t lead = std::max<std::int64_t>(0, -whole);
    const std::string_view rest =
        std::string_view(digits).substr(static_cast<std::size_t>(std::max<std::int64_t>(0, whole)));
    const bool up =
        lead == 0 && (rest.front() > '5' || (rest.front() == '5' && (rest.size() > 1 || value % 2 == 1)));
    // The offset from the first 18 digits of r (exact when r has no more).
    std::int64_t num = 0, den = 1;
    for (std::int64_t i = 0; i < 18; ++i) {
      const std::int64_t j = i - lead;
      num = num * 10 + (j >= 0 && j < static_cast<std::int64_t>(rest.size())
                            ? rest[static_cast<std::size_t>(j)] - '0'
                            : 0);
      den *= 10;
      if (j + 1 >= static_cast<std::int64_t>(rest.size()))
        break;
    }
    if (up) {
      if (value == std::numeric_limits<std::int64_t>::max())
        return problem(Problem::out_of_range);
      ++value;
      num = den - num;
    }
    d.rounded = true;
    d.offset_num = num;
    d.offset_den = den;
  }
  d.value = negative ? -value : value;
  return d;
}

std::string grid_decimal_problem(const GridDecimal& d, std::string_view text, std::int64_t scale) {
  using Problem = GridDecimal::Problem;
  const std::string quoted = "'" + excerpt(trim(text)) + "'";
  switch (d.problem) {
  case Problem::not_finite: return quoted + " is not a finite number";
  case Problem::not_decimal: return quoted + " is not a decimal number";
  case Problem::too_many_decimals:
    return quoted + " has " + (d.decimals > 18 ? "more than 18" : std::to_string(d.decimals)) +
           " decimals, more than the " + std::to_string(scale_decimals(scale)) + " that the grid (10^-" +
           std::to_string(scale_decimals(scale)) + " lattice units) holds exactly";
  case Problem::out_of_range: return quoted + " is out of range for the grid scale " + std::to_string(scale);
  case Problem::none: break;
  }
  return quoted + " is a decimal number";
}

std::int64_t parse_scaled_decimal(std::string_view text, std::int64_t scale, const std::string& where) {
  const GridDecimal d = read_grid_decimal(text, scale, false);
  if (d.problem != GridDecimal::Problem::none)
    throw InputError(where + ": " + grid_decimal_problem(d, text, scale));
  return d.value;
}

} // namespace medusa::io
