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
  CHECK_THAT(m, Contains("f.csv:3: column xCOM") && Contains("7 decimals, more than the 6 that the grid"));
  CHECK(parse_scaled_decimal("1.2345678", 10000000, "t") == 12345678);
  CHECK(parse_scaled_decimal("2.5", 10, "t") == 25);
  CHECK(parse_scaled_decimal("2", 1, "t") == 2);
}

TEST_CASE("NaN, infinities and text are rejected as decimals", "[io][decimal]") {
  for (const char* bad : {"nan", "NaN", "-inf", "Infinity", "abc", "", "-", ".", "1.2.3", "1,5", "0x10", "1e",
                          "1e+", "e5", "1e3.5", "1e 3", "1.5e-x", "--1", "1ee2"}) {
    CAPTURE(bad);
    const std::string m = io::test::input_error([&] { parse_scaled_decimal(bad, 1000000, "where"); });
    CHECK_THAT(m, Contains("where"));
  }
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("nan", 1000000, "w"); }),
             Contains("not a finite number"));
}

TEST_CASE("An exponent moves the decimal point exactly", "[io][decimal]") {
  const std::int64_t S = 1000000;
  CHECK(parse_scaled_decimal("1e3", S, "t") == 1000000000);
  CHECK(parse_scaled_decimal("1.5e-3", S, "t") == 1500);
  CHECK(parse_scaled_decimal("-2.5E+2", S, "t") == -250000000);
  CHECK(parse_scaled_decimal("1.234567e1", S, "t") == 12345670);
  CHECK(parse_scaled_decimal("123456.7e-5", S, "t") == 1234567);
  CHECK(parse_scaled_decimal("1e-6", S, "t") == 1);
  CHECK(parse_scaled_decimal("0e-999999", S, "t") == 0);
  CHECK(parse_scaled_decimal("0.000e99999999999999999999", S, "t") == 0);
  CHECK(parse_scaled_decimal("4.2e0", S, "t") == 4200000);
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("1e-7", 1000000, "w"); }),
             Contains("7 decimals, more than the 6"));
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("1.5e-30", 1000000, "w"); }),
             Contains("more than 18 decimals"));
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("1e13", 1000000, "w"); }),
             Contains("out of range"));
  CHECK_THAT(io::test::input_error([] { parse_scaled_decimal("1e99999999999999999999", 1000000, "w"); }),
             Contains("out of range"));
}

TEST_CASE("Rounding to the grid goes to the nearest value, ties to even, and gives the offset",
          "[io][decimal]") {
  const std::int64_t S = 1000000;
  struct Case {
    const char* text;
    std::int64_t value, num, den;
  };
  for (const Case& c :
       {Case{"1.2345675", 1234568, 5, 10}, Case{"1.2345665", 1234566, 5, 10},
        Case{"1.23456651", 1234567, 49, 100}, Case{"-1.2345675", -1234568, 5, 10},
        Case{"0.0000004", 0, 4, 10}, Case{"0.00000049999", 0, 49999, 100000}, Case{"0.0000005", 0, 5, 10},
        Case{"0.0000015", 2, 5, 10}, Case{"9.9999996", 10000000, 4, 10}, Case{"2.5e-7", 0, 25, 100},
        Case{"1.5", 1500000, 0, 1}, Case{"7", 7000000, 0, 1}}) {
    CAPTURE(c.text);
    const GridDecimal d = read_grid_decimal(c.text, S, true);
    REQUIRE(d.problem == GridDecimal::Problem::none);
    CHECK(d.value == c.value);
    CHECK(d.rounded == (c.num != 0));
    CHECK(d.offset_num * c.den == c.num * d.offset_den);
  }
  // Far beyond 18 digits the value is still exact; the offset is exact to 10^-18 grid units.
  const GridDecimal far = read_grid_decimal("1.000000499999999999999999999", S, true);
  CHECK(far.value == 1000000);
  CHECK(far.rounded);
  CHECK(far.offset_num == 499999999999999999);
  CHECK(far.offset_den == 1000000000000000000);
  const GridDecimal tiny = read_grid_decimal("3e-40", S, true);
  CHECK(tiny.value == 0);
  CHECK(tiny.rounded);
  CHECK(read_grid_decimal("9223372036854.7758075", S, true).problem == GridDecimal::Problem::out_of_range);
  CHECK(read_grid_decimal("1.2345675", S, false).problem == GridDecimal::Problem::too_many_decimals);
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
