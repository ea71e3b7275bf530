// A second table of verb declarations (what a second line protocol would declare) is parsed
// by the same generic parser, with its own names, grammar and refusals, and leaves the
// MESSD table untouched.
#include <catch2/catch.hpp>

#include <array>

#include "imess/protocol/verbs.hpp"

using namespace imess::protocol;

namespace {

// A toy second protocol: other names for two motion commands and one with its own range.
const std::array kToyVerbs{
    VerbSpec{"AbortE", args(), "stop all motion", false, Access::Stop, command_index<StopMv>(),
             [](const Args&) -> Command { return StopMv{}; }},
    VerbSpec{"MoveTo",
             args(number("x", -500, 500, "MoveTo x must be {min} to {max} mm, got {got}"), number("y", -500, 500, ""),
                  number("z", -500, 500, ""), optional(above_min(number("speed", 0, 50, "speed must be above {min}, at most {max}")))),
             "straight move", false, Access::Controlling, command_index<GoTo>(),
             [](const Args& a) -> Command {
               return GoTo{{a.number(0), a.number(1), a.number(2)},
                           a.has(3) ? std::optional<double>(a.number(3)) : std::nullopt};
             }},
};

template <class T>
T toy_parsed(std::string_view line) {
  auto r = parse_command(line, kToyVerbs);
  REQUIRE(std::holds_alternative<Command>(r));
  REQUIRE(std::holds_alternative<T>(std::get<Command>(r)));
  return std::get<T>(std::get<Command>(r));
}
ParseError toy_failed(std::string_view line) {
  auto r = parse_command(line, kToyVerbs);
  REQUIRE(std::holds_alternative<ParseError>(r));
  return std::get<ParseError>(r);
}

}  // namespace

TEST_CASE("a second verb table is parsed by the generic parser with its own grammar") {
  toy_parsed<StopMv>("aborte");
  auto g = toy_parsed<GoTo>("MoveTo 1 -2 3.5 20");
  CHECK(g.target == Xyz{1, -2, 3.5});
  CHECK(g.speed == 20.0);
  CHECK_FALSE(toy_parsed<GoTo>("MoveTo 1 2 3").speed.has_value());

  auto range = toy_failed("MoveTo 600 0 0");
  CHECK(range.code == ErrorCode::BadValue);
  CHECK(range.text == "MoveTo x must be -500 to 500 mm, got 600");
  auto count = toy_failed("MoveTo 1 2");
  CHECK(count.code == ErrorCode::BadArguments);
  CHECK(count.text == "MoveTo takes 'x y z [speed]', got 2; usage: MoveTo x y z [speed]");
  CHECK(toy_failed("MoveTo 1 2 3 0").text == "speed must be above 0, at most 50");
  CHECK(toy_failed("MoveTo 1 2 3 abc").code == ErrorCode::BadNumber);
  CHECK(toy_failed("AbortE\x01").code == ErrorCode::BadCharacter);
}

TEST_CASE("the tables do not see each other's verbs") {
  auto unknown = toy_failed("StopMv");  // a MESSD verb, not in the toy table
  CHECK(unknown.code == ErrorCode::UnknownCommand);
  CHECK(unknown.text.find("'StopMv'") != std::string::npos);
  auto r = parse_command("AbortE");  // the toy verb, not in the MESSD table
  REQUIRE(std::holds_alternative<ParseError>(r));
  CHECK(std::get<ParseError>(r).code == ErrorCode::UnknownCommand);
  CHECK(std::holds_alternative<Command>(parse_command("GoTo 1 2 3")));
  CHECK(help_line(kToyVerbs[1]) == "Help MoveTo x y z [speed] - straight move");
}
