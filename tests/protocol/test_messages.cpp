// Daemon -> client lines: exact 1996 bytes, and the client-side parser.
#include <catch2/catch.hpp>

#include "imess/protocol/messages.hpp"

using namespace imess::protocol;

TEST_CASE("CurrCor and MeasPt are byte-exact 1996 lines") {
  CHECK(format_curr_cor({1, -2.5, 300.1234}) == "CurrCor 1.000 -2.500 300.123\n");
  CHECK(format_meas_pt({0, 0, 0}) == "MeasPt 0.000 0.000 0.000\n");
}

TEST_CASE("replies start with Ok or Err") {
  CHECK(format_ok("StopMv") == "Ok StopMv\n");
  CHECK(format_ok("Get", "TipRadius 2.000") == "Ok Get TipRadius 2.000\n");
  CHECK(format_err(ErrorCode::TipTouched, "tip is touched") == "Err 200 tip is touched\n");
}

TEST_CASE("parse_message reads back what the daemon writes") {
  auto m = parse_message(format_meas_pt({1.5, 2, -3}));
  REQUIRE(std::holds_alternative<MeasPtMsg>(m));
  CHECK(std::get<MeasPtMsg>(m).p == Xyz{1.5, 2, -3});

  m = parse_message("Err 103 line too long\r\n");
  REQUIRE(std::holds_alternative<ErrMsg>(m));
  CHECK(std::get<ErrMsg>(m).code == 103);
  CHECK(std::get<ErrMsg>(m).text == "line too long");

  m = parse_message("Ok Get SpeedLevel 0.800");
  REQUIRE(std::holds_alternative<OkMsg>(m));
  CHECK(std::get<OkMsg>(m).args == std::vector<std::string>{"SpeedLevel", "0.800"});

  m = parse_message("Warn TipNotFree could not free the tip");
  REQUIRE(std::holds_alternative<WarnMsg>(m));
  CHECK(std::get<WarnMsg>(m).text == "could not free the tip");

  CHECK(std::holds_alternative<OtherMsg>(parse_message("CurrCor 1 2")));
  CHECK(std::holds_alternative<OtherMsg>(parse_message("Whatever else")));
}

TEST_CASE("every error code has a name and a meaning") {
  for (const auto& e : error_table()) {
    CHECK_FALSE(e.name.empty());
    CHECK_FALSE(e.meaning.empty());
    CHECK(&error_info(e.code) == &e);
  }
}
