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

TEST_CASE("Hit carries seq, id, point, direction, radius and time, and parses back") {
  HitMsg h{17, 0, {430, 330, 80}, {0, 0, -1}, 2, 1234.5678901};
  CHECK(format_hit(h) == "Hit 17 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 1234.567890\n");
  auto m = parse_message(format_hit(h));
  REQUIRE(std::holds_alternative<HitMsg>(m));
  auto back = std::get<HitMsg>(m);
  CHECK(back.seq == 17);
  CHECK(back.p == Xyz{430, 330, 80});
  CHECK(back.dir == Xyz{0, 0, -1});
  CHECK(back.radius == 2);
  CHECK(back.time == Approx(1234.56789).margin(1e-6));
  // A ForcePt point: no direction, no radius; negative zeros print unsigned.
  HitMsg forced{18, 0, {-0.00001, 1.23456, 0}, {-0.0, 0, 0}, 0, 2};
  CHECK(format_hit(forced) == "Hit 18 0 0.0000 1.2346 0.0000 0.000000 0.000000 0.000000 0.0000 2.000000\n");
  // Large sequence numbers stay exact.
  CHECK(std::get<HitMsg>(parse_message("Hit 9007199254740991 5 1 2 3 0 0 1 2 0.5")).seq == 9007199254740991ULL);
  CHECK(std::get<HitMsg>(parse_message("Hit 9007199254740991 5 1 2 3 0 0 1 2 0.5")).id == 5);
  // Anything malformed is a line to ignore, never a half-read hit.
  CHECK(std::holds_alternative<OtherMsg>(parse_message("Hit 1 0 1 2 3 0 0 1 2")));
  CHECK(std::holds_alternative<OtherMsg>(parse_message("Hit -1 0 1 2 3 0 0 1 2 0.5")));
  CHECK(std::holds_alternative<OtherMsg>(parse_message("Hit 1 0 1 2 x 0 0 1 2 0.5")));
}

TEST_CASE("a scanning point is a Scan line of the Hit's words, and parses back as one") {
  HitMsg s{19, 7, {445, 350, 30}, {-1, 0, 0}, 2, 12.0005, true};
  CHECK(format_hit(s) == "Scan 19 7 445.0000 350.0000 30.0000 -1.000000 0.000000 0.000000 2.0000 12.000500\n");
  const auto m = parse_message(format_hit(s));
  REQUIRE(std::holds_alternative<HitMsg>(m));
  CHECK(std::get<HitMsg>(m) == s);
  CHECK_FALSE(std::get<HitMsg>(parse_message("Hit 19 7 445 350 30 -1 0 0 2 12.0005")).scan);
  CHECK(std::holds_alternative<OtherMsg>(parse_message("Scan 19 7 445 350 30 -1 0 0 2")));
}
