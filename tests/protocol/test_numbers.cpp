// Wire numbers: strict parse, %.3f output with no negative zero.
#include <catch2/catch.hpp>

#include "imess/protocol/numbers.hpp"

using namespace imess::protocol;

TEST_CASE("parse_number accepts decimal forms and rejects the rest") {
  CHECK(parse_number("12") == 12.0);
  CHECK(parse_number("-0.5") == -0.5);
  CHECK(parse_number(".25") == 0.25);
  CHECK(parse_number("+3") == 3.0);
  CHECK(parse_number("1e3") == 1000.0);
  CHECK_FALSE(parse_number(""));
  CHECK_FALSE(parse_number("abc"));
  CHECK_FALSE(parse_number("1.5x"));
  CHECK_FALSE(parse_number("nan"));
  CHECK_FALSE(parse_number("inf"));
  CHECK_FALSE(parse_number("1e999"));
  CHECK_FALSE(parse_number("--1"));
}

TEST_CASE("append_mm prints three decimals like the 1996 daemon") {
  std::string s;
  append_mm(s, 12.3456);
  CHECK(s == "12.346");
  s.clear();
  append_mm(s, -0.0001);
  CHECK(s == "0.000");
  s.clear();
  append_mm(s, -1.5);
  CHECK(s == "-1.500");
}

TEST_CASE("a number too small to represent reads as zero, one too large is refused") {
  CHECK(parse_number("1e-400") == 0.0);
  CHECK(parse_number("-1e-400") == 0.0);
  CHECK(parse_number("+0.00001e-320") == 0.0);
  CHECK(parse_number("123.456e-99999999999999") == 0.0);
  CHECK(parse_number("0.0000000000000000001e-310") == 0.0);
  CHECK_FALSE(parse_number("1e400"));
  CHECK_FALSE(parse_number("-1e400"));
  CHECK_FALSE(parse_number("0.001e312"));
  CHECK_FALSE(parse_number("12345678901234567890e300"));
  CHECK_FALSE(parse_number("1e99999999999999"));
  CHECK_FALSE(parse_number("1e-400x"));
  CHECK(parse_number("1e-300") == 1e-300);  // small but representable: kept as it is
}

TEST_CASE("a leading plus takes one plain number, never a second sign") {
  CHECK_FALSE(parse_number("+"));
  CHECK_FALSE(parse_number("+-1"));
  CHECK_FALSE(parse_number("++1"));
}

TEST_CASE("append_fixed prints the asked decimals and never a negative zero") {
  std::string s;
  append_fixed(s, -0.00004, 4);
  CHECK(s == "0.0000");
  s.clear();
  append_fixed(s, -1.5, 6);
  CHECK(s == "-1.500000");
  CHECK(parse_sequence_number("0") == std::optional<std::uint64_t>(0));
  CHECK_FALSE(parse_sequence_number("+1"));
  CHECK_FALSE(parse_sequence_number(""));
}

// Issue 26, 2: a 64-byte buffer cut 1e300 (301 digits before the point) to 63 characters.
TEST_CASE("append_fixed never cuts a number short, however large") {
  for (double v : {1e300, -1.7e308, 123456789012345678.0, 1e63}) {
    std::string s = "x ";
    append_fixed(s, v, 4);
    INFO(s);
    REQUIRE(s.size() > 7);
    CHECK(s.compare(s.size() - 5, 5, ".0000") == 0);
    CHECK(parse_number(std::string_view(s).substr(2)) == std::optional<double>(v));
  }
  std::string small;
  append_fixed(small, 430.25, 9);
  CHECK(small == "430.250000000");
}
