#include "medusa/io/decimal.h"

#include "medusa/core/error.h"
#include "medusa/io/excerpt.h"

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

std::int64_t parse_scaled_decimal(std::string_view text, std::int64_t scale, const std::string& where) {
  const int m = scale_decimals(scale);
  const std::string_view s0 = trim(text);
  std::string_view s = s0;
  const auto fail = [&](const std::string& why) {
    return InputError(where + ": '" + excerpt(s0) + "' " + why);
  };
  if (is_non_finite(s))
    throw fail("is not a finite number");
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  const std::size_t dot = s.find('.');
  const std::string_view int_part = s.substr(0, dot);
  const std::string_view frac_part = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  if (int_part.empty() && frac_part.empty())
    throw fail("is not a decimal number");
  for (std::string_view part : {int_part, frac_part})
    for (char c : part)
      if (c < '0' || c > '9')
        throw fail("is not a decimal number");
  std::size_t significant = frac_part.size();
  while (significant > 0 && frac_part[significant - 1] == '0')
    --significant;
  if (significant > static_cast<std::size_t>(m))
    throw fail("has " + std::to_string(significant) + " decimals, more than the grid scale " +
               std::to_string(scale) + " represents exactly (raise the scale to 10^" +
               std::to_string(significant) + ")");
  std::int64_t value = 0;
  for (char c : int_part)
    if (!push_digit(value, c))
      throw fail("is out of range for the grid scale " + std::to_string(scale));
  for (int i = 0; i < m; ++i)
    if (!push_digit(value, static_cast<std::size_t>(i) < frac_part.size() ? frac_part[i] : '0'))
      throw fail("is out of range for the grid scale " + std::to_string(scale));
  return negative ? -value : value;
}

} // namespace medusa::io
