// Command parsing: every verb, case-insensitivity, and a clear Err for every bad input.
#include <catch2/catch.hpp>

#include <set>

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

namespace {
// A line every declaration must accept: each argument at a value its grammar allows.
std::string sample_line(const VerbSpec& v) {
  std::string line(v.name);
  for (std::size_t i = 0; i < v.args.size; ++i) {
    const ArgSpec& a = v.args.items[i];
    switch (a.kind) {
      case ArgKind::Number: line += a.min > -1e9 ? " " + std::to_string(a.min + (a.above_min ? 1 : 0)) : " 1.5"; break;
      case ArgKind::Word: line += " TipRadius"; break;
      case ArgKind::Choice: line += " " + std::string(a.words.substr(0, a.words.find(' '))); break;
      case ArgKind::Sequence: line += " 17"; break;
      case ArgKind::AxisWords:  // a vector letter stands alone before its three numbers
        line += " " + std::string(1, a.words[0]) + (a.vectors.find(a.words[0]) != std::string_view::npos ? " 1 0 0" : "10");
        break;
    }
  }
  return line;
}
}  // namespace

TEST_CASE("every verb in the table parses from its own name and reports that name") {
  for (const auto& v : verb_table()) {
    CHECK(v.name.size() <= 8);
    std::string line = sample_line(v);
    auto r = parse_command(line);
    INFO(line);
    REQUIRE(std::holds_alternative<Command>(r));
    CHECK(verb_name(std::get<Command>(r)) == v.name);
    CHECK(std::get<Command>(r).index() == v.command);
  }
}

TEST_CASE("every typed command has exactly one declaration, optional arguments trail") {
  for (std::size_t i = 0; i < std::variant_size_v<Command>; ++i) {
    int declared = 0;
    for (const auto& v : verb_table()) declared += v.command == i ? 1 : 0;
    INFO("Command alternative " << i);
    CHECK(declared == 1);
  }
  for (const auto& v : verb_table()) {
    INFO(v.name);
    bool optional_seen = false;
    for (std::size_t i = 0; i < v.args.size; ++i) {
      CHECK((v.args.items[i].optional || !optional_seen));
      optional_seen = optional_seen || v.args.items[i].optional;
      if (v.args.items[i].kind == ArgKind::AxisWords) CHECK(i + 1 == v.args.size);  // takes the rest
    }
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

TEST_CASE("error texts made from the declarations are the ones clients have seen since 0.1") {
  const std::pair<const char*, const char*> cases[] = {
      {"StartMv 0 0 150", "StartMv speeds are percent of MaxSpeed, -100 to 100"},
      {"GoTo 1 2 3 0", "GoTo speed must be greater than 0 mm/s"},
      {"HandMv 1 2 3 -1", "HandMv speed must be greater than 0 mm/s"},
      {"Replay x", "Replay takes a hit sequence number, a whole number from 0 to 9007199254740991, got 'x'"},
      {"Take now", "Take takes nothing or the word 'force', got 'now'; usage: Take [force]"},
      {"Watch 100.5", "Watch takes whole milliseconds from 50 to 60000, or 0 to switch it off"},
      {"StartMv 10 20", "StartMv takes 'vx vy vz', got 2; usage: StartMv vx vy vz"},
      {"StopMv now", "StopMv takes no arguments, got 1; usage: StopMv"},
      {"StartMv 150 two 3", "'two' is not a number; usage: StartMv vx vy vz (decimal numbers, e.g. -12.5)"},
      {"Jog 1", "unknown command 'Jog'; Help lists the commands"},
  };
  for (auto [line, text] : cases) {
    INFO(line);
    CHECK(failed(line).text == text);
  }
}

TEST_CASE("the grammar carries axis words for verbs like MoveTo 7 X10 C90 F20") {
  // A declaration as a future MoveTo would have it; the generic parser checks it.
  static const VerbSpec move_to{"MoveTo",
                                args(sequence("id", "MoveTo takes a move number, got '{got}'"),
                                     axis_words("words", "XYZABCF", "MoveTo takes words X Y Z A B C F with a number each, got '{got}'")),
                                "test only", false, Access::Controlling, command_index<Quit>(), [](const Args& a) -> Command {
                                  Xyz p;  // fold the words into a command that exists, to look at them
                                  for (auto w : a.axis_words) (w.letter == 'X' ? p.x : w.letter == 'C' ? p.y : p.z) = w.value;
                                  return GoTo{p, a.at[0].sequence == 7 ? std::optional<double>(7) : std::nullopt};
                                }};
  CHECK(usage(move_to) == "MoveTo id words");
  auto parse = [&](std::string_view line) { return parse_with(move_to, line); };
  auto ok = parse("MoveTo 7 X10 c90 F20");
  REQUIRE(std::holds_alternative<Command>(ok));
  auto g = std::get<GoTo>(std::get<Command>(ok));
  CHECK(g.target == Xyz{10, 90, 20});
  CHECK(g.speed == 7.0);
  auto e = std::get<ParseError>(parse("MoveTo 7 X10 Q3"));
  CHECK(e.code == ErrorCode::BadValue);
  CHECK(e.text == "MoveTo takes words X Y Z A B C F with a number each, got 'Q3'");
  CHECK(std::get<ParseError>(parse("MoveTo 7 X10 X11")).code == ErrorCode::BadValue);  // each letter once
  CHECK(std::get<ParseError>(parse("MoveTo 7 Xten")).code == ErrorCode::BadNumber);
  CHECK(std::get<ParseError>(parse("MoveTo 7")).code == ErrorCode::BadArguments);   // at least one word
}

TEST_CASE("Version takes no arguments") {
  parsed<Version>("version");
  CHECK(failed("Version 2").text == "Version takes no arguments, got 1; usage: Version");
}

TEST_CASE("ArcTo: end, centre offsets I J K, the plane's normal N i j k, turns P, feed") {
  auto a = parsed<ArcTo>("ArcTo 7 ccw X1 Y2 Z3 I4 J5 K6 N 0 -0.5 1e0 P3 F20");
  CHECK(a.id == 7);
  CHECK(a.ccw);
  CHECK(a.words.x == 1.0);
  CHECK(a.words.k == 6.0);
  REQUIRE(a.words.n.has_value());
  CHECK(*a.words.n == std::array<double, 3>{0, -0.5, 1});
  CHECK(a.words.p == 3.0);
  CHECK(a.words.f == 20.0);
  auto b = parsed<ArcTo>("ArcTo 8 CW N 1 0 0 X5");  // N anywhere among the words
  CHECK_FALSE(b.ccw);
  CHECK(*b.words.n == std::array<double, 3>{1, 0, 0});
  CHECK(b.words.x == 5.0);
  CHECK_FALSE(parsed<ArcTo>("ArcTo 9 CW X5 I2").words.n.has_value());
  const std::string usage = "usage: ArcTo id dir X.. Y.. Z.. I.. J.. K.. N i j k P.. F..";
  CHECK(failed("ArcTo 1 CW X5 N 0 1").text == "ArcTo takes N alone followed by three numbers (N i j k), got 'N'; " + usage);
  CHECK(failed("ArcTo 1 CW X5 N 0 1").code == ErrorCode::BadArguments);
  CHECK(failed("ArcTo 1 CW N1 0 0").text == "ArcTo takes N alone followed by three numbers (N i j k), got 'N1'; " + usage);
  CHECK(failed("ArcTo 1 CW N 1 0 0 N 0 0 1").code == ErrorCode::BadValue);  // once
  CHECK(failed("ArcTo 1 CW N 1 zero 0").code == ErrorCode::BadNumber);
  CHECK(failed("ArcTo 1 CW X5 Q1").text ==
        "ArcTo takes words X Y Z (end), I J K (centre offset from the start), N i j k (plane normal), P (turns), F, "
        "each once, got 'Q1'; " + usage);
  CHECK(failed("ArcTo 1 up X5").text ==
        "ArcTo turns CW or CCW (seen from the tip of the plane's normal), got 'up'; " + usage);
}

TEST_CASE("Stats alone is since the start, Reset Interval Hist are the measuring interval") {
  using Form = Stats::Form;
  CHECK(parsed<Stats>("Stats").form == Form::SinceStart);
  CHECK(parsed<Stats>("Stats Reset").form == Form::Reset);
  CHECK(parsed<Stats>("stats interval").form == Form::Interval);
  CHECK(parsed<Stats>("Stats HIST").form == Form::Hist);
  const auto bad = failed("Stats Clear");
  CHECK(bad.code == ErrorCode::BadValue);
  CHECK(bad.text == "Stats takes nothing, Reset, Interval or Hist, got 'Clear'; usage: Stats [form]");
  CHECK(failed("Stats Reset now").code == ErrorCode::BadArguments);
}

TEST_CASE("the verbs that move the machine say so in their declaration (Access::Moving)") {
  // The list the daemon kept by hand before (refused while a program runs); now read from the table.
  const std::set<std::string_view> moving{"StartMv", "GoTo",  "Home",  "Free",  "Reset",  "HandMv", "ForcePt",
                                          "MoveTo",  "ArcTo", "Dwell", "Probe", "SetOut", "JogAx", "ScanLine", "ScanCirc"};
  for (const auto& v : verb_table()) {
    INFO(v.name);
    CHECK((v.access == Access::Moving) == moving.contains(v.name));
  }
  CHECK(moves_machine(GoTo{}));
  CHECK(moves_machine(Probe{}));
  CHECK_FALSE(moves_machine(Set{}));
  CHECK_FALSE(moves_machine(StopMv{}));
}
