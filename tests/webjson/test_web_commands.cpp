// Browser -> messd: every JSON command is the one line it stands for, and the line protocol's
// own parser reads that line as the command meant; what is no command is refused saying why.
#include <catch2/catch.hpp>

#include "imess/protocol/verbs.hpp"
#include "imess/webjson/web_json.hpp"

using namespace imess;

namespace {
std::vector<std::string> lines_of(std::string_view message) {
  auto r = webjson::command_lines(message);
  if (auto* refusal = std::get_if<webjson::Refusal>(&r)) FAIL("refused: " << refusal->text);
  return std::get<std::vector<std::string>>(r);
}

webjson::Refusal refusal_of(std::string_view message) {
  auto r = webjson::command_lines(message);
  REQUIRE(std::holds_alternative<webjson::Refusal>(r));
  return std::get<webjson::Refusal>(r);
}
}  // namespace

TEST_CASE("web commands: every verb of the table as {\"cmd\":…} is its line, read by the line parser as that verb") {
  for (const auto& verb : protocol::verb_table()) {
    const std::string name(verb.name);
    const auto lines = lines_of(R"({"cmd":")" + name + R"("})");
    REQUIRE(lines == std::vector<std::string>{name});
    auto parsed = protocol::parse_command(lines[0]);
    // Without arguments a verb parses, or is refused for its arguments (never as unknown).
    if (auto* e = std::get_if<protocol::ParseError>(&parsed)) {
      INFO(name << ": " << e->text);
      CHECK(e->code != protocol::ErrorCode::UnknownCommand);
    } else {
      CHECK(protocol::verb_name(std::get<protocol::Command>(parsed)) == name);
    }
  }
}

TEST_CASE("web commands: arguments become words, numbers in their shortest exact form") {
  struct Case {
    const char* message;
    const char* line;
  };
  const Case cases[] = {
      {R"({"cmd":"StartMv","args":[0,0,-20]})", "StartMv 0 0 -20"},
      {R"({"cmd":"StartMv","args":[0.5,-2.25,1e2]})", "StartMv 0.5 -2.25 100"},
      {R"({"cmd":"GoTo","args":[460,350,120,25.5]})", "GoTo 460 350 120 25.5"},
      {R"({"cmd":"MoveTo","args":[1,"X400","Y300","F50"]})", "MoveTo 1 X400 Y300 F50"},
      {R"({"cmd":"Watch","args":[500]})", "Watch 500"},
      {R"({"cmd":"Load","args":["bore-inspection.ngc"]})", "Load bore-inspection.ngc"},
      {R"({"cmd":"Hello","args":["web"]})", "Hello web"},
      {R"({"cmd":"Set","args":["ReportHz",20]})", "Set ReportHz 20"},
      {R"({"cmd":"Replay","args":[1]})", "Replay 1"},
      {R"({"cmd":"Take","args":["force"]})", "Take force"},
  };
  for (const auto& c : cases) {
    INFO(c.message);
    const auto lines = lines_of(c.message);
    REQUIRE(lines == std::vector<std::string>{c.line});
    CHECK(std::holds_alternative<protocol::Command>(protocol::parse_command(lines[0])));
  }
}

TEST_CASE("web commands: the keep-alive is the blank line, a typed line goes as it is, an upload ends with its dot") {
  CHECK(lines_of(R"({"cmd":""})") == std::vector<std::string>{""});
  CHECK(lines_of(R"({"line":"GoTo 1 2 3"})") == std::vector<std::string>{"GoTo 1 2 3"});
  CHECK(lines_of(R"({"line":"GoTo\t1 2 3"})") == std::vector<std::string>{"GoTo\t1 2 3"});  // a tab, as 1066 takes it
  CHECK(lines_of(R"({"cmd":"Upload","args":["p.ngc"],"lines":["G0 X1","M2"]})") ==
        std::vector<std::string>{"Upload p.ngc", "G0 X1", "M2", "."});
}

TEST_CASE("web commands: what is no command is refused with the line protocol's code, saying what is accepted") {
  struct Case {
    const char* message;
    int code;
    const char* says;
  };
  const Case cases[] = {
      {"StartMv 0 0 -20", 101, "not a JSON command"},
      {"[1,2]", 101, "not a JSON object"},
      {R"({"cmd":"StartMv","cmd":"StopMv"})", 101, "appears twice"},
      {R"({"verb":"StopMv"})", 101, "unknown key \"verb\""},
      {R"({})", 101, "neither"},
      {R"({"cmd":"StopMv","line":"StopMv"})", 101, "both"},
      {R"({"cmd":"Stop Mv"})", 101, "one word"},
      {R"({"cmd":7})", 101, "not a string"},
      {R"({"cmd":"GoTo","args":"1 2 3"})", 101, "not a list"},
      {R"({"cmd":"GoTo","args":[1,2,[3]]})", 101, "nests objects and arrays deeper"},
      {R"({"cmd":"GoTo","args":[1,2,null]})", 101, "neither a number nor a string"},
      {R"({"cmd":"Load","args":["a b"]})", 101, "space"},
      {R"({"cmd":"Load","args":[""]})", 101, "empty"},
      {R"({"line":"StopMv\nFree"})", 104, "control"},
      {R"({"cmd":"Hello","args":["x\r"]})", 104, "control"},
      {R"({"cmd":"Hello","args":["x\ty"]})", 104, "control"},
      {R"({"line":"caf\u00e9"})", 104, "non-ASCII"},
      {R"({"cmd":"","args":[]})", 101, "keep-alive"},
      {R"({"cmd":"Load","lines":["G0"]})", 101, "only with"},
      {R"({"cmd":"Upload","args":["p"],"lines":["G0","."]})", 101, "end the upload early"},
  };
  for (const auto& c : cases) {
    INFO(c.message);
    const auto r = refusal_of(c.message);
    CHECK(r.code == c.code);
    CHECK_THAT(r.text, Catch::Contains(c.says));
    CHECK_THAT(r.text, Catch::Contains("accepted: {\"cmd\":VERB"));
  }
  const std::string long_line = R"({"line":")" + std::string(201, 'x') + R"("})";
  CHECK(refusal_of(long_line).code == 103);
}
