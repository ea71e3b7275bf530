// Command parsing: every verb, case-insensitivity, and a clear Err for every bad input.
#include <catch2/catch.hpp>

#include "imess/protocol/numbers.hpp"
#include "imess/protocol/verbs.hpp"

using namespace imess::protocol;

namespace {
template <class T>
T parsed(std::string_view line) {
  auto r = parse_command(line);
  REQUIRE(std::holds_alternative<Command>(r));
  auto& c = std::get<Command>(r);
  REQUIRE(std::holds_alternative<T>(c));
  return std::get<T>(c);
}
ParseError failed(std::string_view line) {
  auto r = parse_command(line);
  REQUIRE(std::holds_alternative<ParseError>(r));
  return std::get<ParseError>(r);
}
}  // namespace

TEST_CASE("the 1996 verbs parse as the 1996 panel sends them") {
  auto s = parsed<StartMv>("StartMv 0 0 -20");
  CHECK(s.percent == Xyz{0, 0, -20});
  CHECK(parsed<StartMv>("StartMv 100 -2 0.5").percent == Xyz{100, -2, 0.5});
  parsed<StopMv>("StopMv");
  parsed<ForcePt>("ForcePt");
}

TEST_CASE("verbs are case-insensitive and blanks are flexible") {
  CHECK(parsed<StartMv>("  startmv\t1  2 3 ").percent == Xyz{1, 2, 3});
  parsed<StopMv>("STOPMV");
  CHECK(parsed<GoTo>("goto 1 2 3 40").speed == 40.0);
  CHECK_FALSE(parsed<GoTo>("GoTo 1 2 3").speed.has_value());
}

TEST_CASE("every verb in the table parses from its own name and reports that name") {
  for (const auto& v : verb_table()) {
    CHECK(v.name.size() <= 8);
    std::string line(v.name);
    if (v.args.rfind("vx", 0) == 0 || v.args.rfind("x ", 0) == 0 || v.args.rfind("dx", 0) == 0) line += " 1 2 3";
    else if (v.args == "name value") line += " TipRadius 2";
    else if (v.args == "from-seq") line += " 17";
    else if (v.args == "ms") line += " 250";
    auto r = parse_command(line);
    INFO(line);
    REQUIRE(std::holds_alternative<Command>(r));
    CHECK(verb_name(std::get<Command>(r)) == v.name);
  }
}

TEST_CASE("Take, Release and Watch: control verbs and their bounds") {
  CHECK_FALSE(parsed<Take>("Take").force);
  CHECK(parsed<Take>("take FORCE").force);
  CHECK(std::get<ParseError>(parse_command("Take now")).code == ErrorCode::BadValue);
  CHECK(std::get<ParseError>(parse_command("Take force now")).code == ErrorCode::BadArguments);
  CHECK(std::holds_alternative<Command>(parse_command("Release")));
  CHECK(parsed<Watch>("Watch 250").ms == 250);
  CHECK(parsed<Watch>("Watch 0").ms == 0);
  CHECK(parsed<Watch>("Watch 50").ms == kWatchMinMs);
  CHECK(parsed<Watch>("Watch 60000").ms == kWatchMaxMs);
  for (auto bad : {"Watch 49", "Watch 60001", "Watch -5", "Watch 100.5"}) {
    INFO(bad);
    auto e = std::get<ParseError>(parse_command(bad));
    CHECK(e.code == ErrorCode::BadValue);
    CHECK(e.text.find("50 to 60000") != std::string::npos);
  }
}

TEST_CASE("parameters and names are kept as typed") {
  auto s = parsed<Set>("Set TipRadius 2.5");
  CHECK(s.name == "TipRadius");
  CHECK(s.value == "2.5");
  CHECK(parsed<Get>("Get").name.empty());
  CHECK(parsed<Hello>("Hello messjog").client == "messjog");
}

TEST_CASE("bad input gets the right error code and a text that helps") {
  auto e = failed("Jump 1 2 3");
  CHECK(e.code == ErrorCode::UnknownCommand);
  CHECK(e.text.find("Help") != std::string::npos);

  e = failed("StartMv 1 2");
  CHECK(e.code == ErrorCode::BadArguments);
  CHECK(e.text.find("StartMv vx vy vz") != std::string::npos);

  e = failed("StartMv 1 two 3");
  CHECK(e.code == ErrorCode::BadNumber);
  CHECK(e.text.find("'two'") != std::string::npos);

  CHECK(failed("StartMv 0 0 150").code == ErrorCode::BadValue);
  CHECK(failed("GoTo 1 2 3 -5").code == ErrorCode::BadValue);
  CHECK(failed("StopMv now").code == ErrorCode::BadArguments);
  CHECK(failed("Status\x01").code == ErrorCode::BadCharacter);
  CHECK(failed("St\xc3\xa4tus").code == ErrorCode::BadCharacter);
}

TEST_CASE("blank lines are recognised so callers can skip them") {
  CHECK(is_blank(""));
  CHECK(is_blank(" \t "));
  CHECK_FALSE(is_blank(" x"));
}

TEST_CASE("help lines name usage and meaning") {
  auto line = help_line(verb_table()[0]);
  CHECK(line.rfind("Help StartMv vx vy vz - ", 0) == 0);
}

TEST_CASE("Replay takes one whole sequence number") {
  auto r = parse_command("replay 17");
  REQUIRE(std::holds_alternative<Command>(r));
  CHECK(std::get<Replay>(std::get<Command>(r)).from == 17);
  CHECK(std::get<Replay>(std::get<Command>(parse_command("Replay 0"))).from == 0);
  CHECK(std::get<Replay>(std::get<Command>(parse_command("Replay 9007199254740991"))).from == kMaxSequenceNumber);
  for (const char* bad : {"Replay -1", "Replay 1.5", "Replay x", "Replay 9007199254740992", "Replay 1e3"}) {
    INFO(bad);
    auto e = parse_command(bad);
    REQUIRE(std::holds_alternative<ParseError>(e));
    CHECK(std::get<ParseError>(e).code == ErrorCode::BadValue);
    CHECK(std::get<ParseError>(e).text.find("whole number from 0") != std::string::npos);
  }
  auto none = parse_command("Replay");
  REQUIRE(std::holds_alternative<ParseError>(none));
  CHECK(std::get<ParseError>(none).code == ErrorCode::BadArguments);
}
