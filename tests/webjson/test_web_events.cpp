// messd -> browser: every event type's line as a JSON event with its fields by name, and the
// fields alone print the very same line again; what fits no row travels as "Data", whole.
#include <catch2/catch.hpp>

#include <set>

#include "imess/webjson/web_json.hpp"

using namespace imess;
using nlohmann::json;

namespace {
json event(std::string_view line) { return json::parse(webjson::event_text(line)); }
}  // namespace

TEST_CASE("web events: each event type's fields by name, and back to the same line") {
  struct Case {
    const char* line;
    const char* fields;  // the event without "line"
  };
  const Case cases[] = {
      {"CurrCor 430.000 330.000 100.000", R"({"type":"CurrCor","x":430.0,"y":330.0,"z":100.0})"},
      {"AxPos X250.000 Y120.000 C-30.000 U20.000 V-40.000",
       R"({"type":"AxPos","axes":["X","Y","C","U","V"],"pos":[250.0,120.0,-30.0,20.0,-40.0]})"},
      {"Hit 1 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 12.345678",
       R"({"type":"Hit","seq":1,"id":0,"x":430.0,"y":330.0,"z":80.0,"i":0.0,"j":0.0,"k":-1.0,"r":2.0,"t":12.345678})"},
      {"Scan 2 5 474.9826 349.2786 60.0000 0.998845 -0.048041 0.000000 2.0000 52824.743884",
       R"({"type":"Scan","seq":2,"id":5,"x":474.9826,"y":349.2786,"z":60.0,"i":0.998845,"j":-0.048041,"k":0.0,"r":2.0,"t":52824.743884})"},
      {"MeasPt 430.000 330.000 80.000", R"({"type":"MeasPt","x":430.0,"y":330.0,"z":80.0})"},
      {"PartPt 7 cube 1.5000 2.0000 80.0000 0.000000 0.000000 -1.000000",
       R"({"type":"PartPt","seq":7,"frame":"cube","x":1.5,"y":2.0,"z":80.0,"i":0.0,"j":0.0,"k":-1.0})"},
      {"State jog", R"({"type":"State","state":"jog"})"},
      {"Limit Z neg", R"({"type":"Limit","axis":"Z","side":"neg"})"},
      {"Warn UnexpectedHit the probe touched during a move", R"({"type":"Warn","name":"UnexpectedHit","text":"the probe touched during a move"})"},
      {"Fault CommLost no answer from the card", R"({"type":"Fault","name":"CommLost","text":"no answer from the card"})"},
      {"Homed", R"({"type":"Homed"})"},
      {"Control web 192.168.1.20", R"({"type":"Control","name":"web","host":"192.168.1.20"})"},
      {"Control none", R"({"type":"Control","name":null,"host":null})"},
      {"Done 4", R"({"type":"Done","id":4})"},
      {"Failed 4 Stopped StopMv", R"({"type":"Failed","id":4,"reason":"Stopped","text":"StopMv"})"},
      {"Block bore-inspection.ngc 12 5/20", R"({"type":"Block","name":"bore-inspection.ngc","src_line":12,"block":5,"blocks":20})"},
      {"ProgPause part.ngc 30 M6 T2", R"({"type":"ProgPause","name":"part.ngc","src_line":30,"reason":"M6 T2"})"},
      {"ProgEnd bore-inspection.ngc ok 41 end", R"({"type":"ProgEnd","name":"bore-inspection.ngc","result":"ok","src_line":41,"text":"end"})"},
      {"Frame machine", R"({"type":"Frame","name":"machine"})"},
      {"Qualified TipRadius 2.0010 Offset 0.0010 -0.0020 0.0000 Form 0.0004",
       R"({"type":"Qualified","tip_radius":2.001,"dx":0.001,"dy":-0.002,"dz":0.0,"form":0.0004})"},
      {"Inspected cube-1996 12 1 fail", R"({"type":"Inspected","part":"cube-1996","in":12,"out":1,"result":"fail"})"},
      {"Ok StartMv", R"({"type":"Ok","verb":"StartMv","args":[]})"},
      {"Ok Replay 3 17", R"({"type":"Ok","verb":"Replay","args":["3","17"]})"},
      {"Err 209 the machine is controlled by jog at 127.0.0.1 (client 2)",
       R"j({"type":"Err","code":209,"text":"the machine is controlled by jog at 127.0.0.1 (client 2)"})j"},
  };
  std::set<std::string> covered;
  for (const auto& c : cases) {
    INFO(c.line);
    json e = event(c.line);
    CHECK(e["line"] == c.line);
    e.erase("line");
    CHECK(e == json::parse(c.fields));
    CHECK(webjson::event_line(e) == c.line);
    covered.insert(e["type"].get<std::string>());
  }
  for (auto type : webjson::event_types()) CHECK(covered.count(std::string(type)) == 1);
}

TEST_CASE("web events: data lines and lines that fit no row are Data, verb and text, nothing lost") {
  struct Case {
    const char* line;
    const char* verb;
    const char* text;
  };
  const Case cases[] = {
      {"Help StartMv vx vy vz - Jog", "Help", "StartMv vx vy vz - Jog"},
      {"Replay Lost 5 5 damaged or missing in the journal", "Replay", "Lost 5 5 damaged or missing in the journal"},
      {"CurrCor 430.0 330.000 100.000", "CurrCor", "430.0 330.000 100.000"},  // not messd's three decimals
      {"CurrCor 1.000 2.000", "CurrCor", "1.000 2.000"},
      {"Done -4", "Done", "-4"},
      {"Homed now", "Homed", "now"},
      {"State", "State", ""},
      {"Block p.ngc 3 5of20", "Block", "p.ngc 3 5of20"},
      {"Hit 1 0 nan 0 0 0 0 0 0 0", "Hit", "1 0 nan 0 0 0 0 0 0 0"},
  };
  for (const auto& c : cases) {
    INFO(c.line);
    json e = event(c.line);
    CHECK(e["type"] == "Data");
    CHECK(e["verb"] == c.verb);
    CHECK(e["text"] == c.text);
    CHECK(e["line"] == c.line);
  }
}

TEST_CASE("web events: bytes that are not UTF-8 still give one valid JSON message, as Data") {
  const std::string line = "Warn Odd \xff\xfe bytes";
  json e;
  REQUIRE_NOTHROW(e = json::parse(webjson::event_text(line)));
  CHECK(e["type"] == "Data");
  // A line with a byte messd never writes fits no row (fuzz_web_message found "Ok \xb3…").
  CHECK(json::parse(webjson::event_text(std::string("Ok Replay\0 17", 14)))["type"] == "Data");
}
