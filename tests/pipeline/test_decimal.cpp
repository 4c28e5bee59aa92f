#include "io_test_support.h"
#include "medusa/io/decimal.h"

using namespace medusa;
using namespace medusa::io;
using Catch::Matchers::Contains;

TEST_CASE("Decimal strings become grid integers exactly at scale 10^6", "[io][decimal]") {
  const std::int64_t S = 1000000;
  CHECK(parse_scaled_decimal("37.000000", S, "t") == 37000000);
  CHECK(parse_scaled_decimal("0.000001", S, "t") == 1);
  CHECK(parse_scaled_decimal("-0.000001", S, "t") == -1);
  CHECK(parse_scaled_decimal("-12.5", S, "t") == -12500000);
  CHECK(parse_scaled_decimal("+3", S, "t") == 3000000);
  CHECK(parse_scaled_decimal(".25", S, "t") == 250000);
  CHECK(parse_scaled_decimal("7.", S, "t") == 7000000);
  CHECK(parse_scaled_decimal(" 49.970370 ", S, "t") == 49970370);
  // A double would turn 0.1 + 0.2 style values into near misses; the decimal route cannot.
  CHECK(parse_scaled_decimal("29.300000", S, "t") == 29300000);
  CHECK(parse_scaled_decimal("9007199254.740993", S, "t") == 9007199254740993);
}

TEST_CASE("Trailing zeros beyond the scale are exact and accepted", "[io][decimal]") {
  CHECK(parse_scaled_decimal("1.50000000", 1000000, "t") == 1500000);
}

TEST_CASE("More decimals than the scale holds is an error unless the scale is raised", "[io][decimal]") {
  const std::string m =
      io::test::input_error([] { parse_scaled_decimal("1.2345678", 1000000, "f.csv:3: column xCOM"); });
  CHECK_THAT(m, Contains("f.csv:3: column xCOM") && Contains("7 decimals") && Contains("10^7"));
  CHECK(parse_scaled_decimal("1.2345678", 10000000, "t") == 12345678);
  CHECK(parse_scaled_decimal("2.5", 10, "t") == 25);
  CHECK(parse_scaled_decimal("2", 1, "t") == 2);
}

TEST_CASE("NaN, infinities, exponents and text are rejected as decimals", "[io][decimal]") {
  for (const char* bad :
       {"nan", "NaN", "-inf", "Infinity", "1e3", "abc", "", "-", ".", "1.2.3", "1,5", "0x10"}) {
    CAPTURE(bad);
    const std::string m = io::test::input_error([&] { parse_scaled_decimal(bad, 1000000, "where"); });
    CHECK_THAT(m, Contains("where"));
  }
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("nan", 1000000, "w"); }),
             Contains("not a finite number"));
}

TEST_CASE("Values beyond 64 bits at the grid scale are rejected", "[io][decimal]") {
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("9223372036854.775808", 1000000, "w"); }),
             Contains("out of range"));
  CHECK(parse_scaled_decimal("9223372036854.775807", 1000000, "w") == INT64_MAX);
}

TEST_CASE("Only powers of ten are grid scales", "[io][decimal]") {
  CHECK(scale_decimals(1) == 0);
  CHECK(scale_decimals(1000000) == 6);
  CHECK_THAT(io::test::input_error([] { scale_decimals(1024); }), Contains("power of ten"));
  CHECK_THAT(io::test::input_error([] { scale_decimals(0); }), Contains("power of ten"));
}

TEST_CASE("Integers parse exactly and reject anything else", "[io][decimal]") {
  CHECK(parse_integer("  -42 ", "w") == -42);
  CHECK(parse_integer("216000", "w") == 216000);
  for (const char* bad : {"4.0", "x", "", "99999999999999999999", "inf"}) {
    CAPTURE(bad);
    CHECK_THAT(io::test::input_error([&] { parse_integer(bad, "file:7"); }), Contains("file:7"));
  }
}
