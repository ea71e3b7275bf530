// LineFramer: LF/CRLF/CR NUL, telnet negotiation and its bounds, control bytes kept for
// Err 104, overlong lines, chunk boundaries.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "imess/protocol/line_framer.hpp"
#include "imess/protocol/verbs.hpp"

using imess::protocol::LineFramer;

namespace {
struct Collected {
  std::vector<std::string> lines;
  std::vector<bool> overlong;
};
Collected feed_all(LineFramer& f, const std::vector<std::string>& chunks) {
  Collected c;
  for (auto& chunk : chunks)
    f.feed(chunk, [&](const imess::protocol::FramedLine& l) {
      c.lines.emplace_back(l.text);
      c.overlong.push_back(l.overlong);
    });
  return c;
}
}  // namespace

TEST_CASE("LF and CRLF both end a line and CR is never part of it") {
  LineFramer f;
  auto c = feed_all(f, {"StopMv\nForcePt\r\nStatus\r\n"});
  REQUIRE(c.lines == std::vector<std::string>{"StopMv", "ForcePt", "Status"});
}

TEST_CASE("a line split across reads is joined") {
  LineFramer f;
  auto c = feed_all(f, {"Star", "tMv 0 0", " -20\r", "\n"});
  REQUIRE(c.lines == std::vector<std::string>{"StartMv 0 0 -20"});
  REQUIRE(f.pending() == 0);
}

TEST_CASE("telnet IAC negotiation is stripped, also when split") {
  LineFramer f;
  // IAC DO ECHO, IAC WILL SGA, IAC SB NAWS 0 80 0 24 IAC SE, IAC IP
  const std::string neg = std::string("\xff\xfd\x01\xff\xfb\x03\xff\xfa\x1f", 9) + std::string("\x00\x50\x00\x18\xff\xf0\xff\xf4", 8);
  auto c = feed_all(f, {neg.substr(0, 5), neg.substr(5) + "Sta", "tus\r\n"});
  REQUIRE(c.lines == std::vector<std::string>{"Status"});
}

TEST_CASE("telnet CR NUL ends a line, also when an LF follows it") {
  LineFramer f;
  auto c = feed_all(f, {std::string("Help\r\0\n", 7), std::string("Status\r\0", 8), "Hello\r", "\n"});
  REQUIRE(c.lines == std::vector<std::string>{"Help", "Status", "Hello"});
}

TEST_CASE("an LF ends the line even right after an IAC") {
  LineFramer f;
  auto c = feed_all(f, {"Status\xff\nHello\n"});
  REQUIRE(c.lines.size() == 2);
  REQUIRE(c.lines[0] == "Status\xff");  // the cut-short telnet command stays: Err 104
  REQUIRE(c.lines[1] == "Hello");
  for (const char* cut : {"\xff\xfb\n", "\xff\xfa\n", "\xff\xfa\x18\xff\n"}) {
    auto d = feed_all(f, {std::string("Status") + cut + "StopMv\n"});
    REQUIRE(d.lines == std::vector<std::string>{"Status\xff", "StopMv"});
  }
}

TEST_CASE("a subnegotiation without IAC SE is abandoned after 64 bytes") {
  LineFramer f;
  std::string sub = "\xff\xfa\x18" + std::string(imess::protocol::kMaxSubnegotiation - 1, 'x');
  auto c = feed_all(f, {sub, "StopMv\n", "Status\n"});  // the 65th byte ends the subnegotiation
  REQUIRE(c.lines.size() == 2);
  REQUIRE(c.lines[0] == "\xfftopMv");  // the IAC marks the line; the 65th byte was still skipped
  REQUIRE(c.lines[1] == "Status");
  // One that fits is stripped whole, and an LF inside one ends the line.
  auto d = feed_all(f, {"\xff\xfa\x18" + std::string(60, 'y') + "\xff\xf0Status\n", "\xff\xfa\x18zz", "\nHelp\n"});
  REQUIRE(d.lines == std::vector<std::string>{"Status", "\xff", "Help"});
}

TEST_CASE("a CR or NUL inside a line stays in it, so the parser refuses the line") {
  LineFramer f;
  auto c = feed_all(f, {std::string("Sta\0tus\n", 8), "Stop\rMv\n", "Help\r\r\n"});
  REQUIRE(c.lines == std::vector<std::string>{std::string("Sta\0tus", 7), "Stop\rMv", "Help\r"});
}

TEST_CASE("an overlong line is reported once, truncated, and the next line is clean") {
  LineFramer f(10);
  auto c = feed_all(f, {std::string(25, 'a') + "\nStopMv\n"});
  REQUIRE(c.lines.size() == 2);
  REQUIRE(c.overlong[0]);
  REQUIRE(c.lines[0] == std::string(10, 'a'));
  REQUIRE_FALSE(c.overlong[1]);
  REQUIRE(c.lines[1] == "StopMv");
}

TEST_CASE("a line exactly at the limit is accepted") {
  LineFramer f(10);
  auto c = feed_all(f, {std::string(10, 'b') + "\n"});
  REQUIRE_FALSE(c.overlong[0]);
}

TEST_CASE("every line holding a stray CR, NUL or telnet remnant is answered Err 104") {
  LineFramer f;
  auto c = feed_all(f, {std::string("StopMv\0\n", 8), "StopMv\rx\n", "StopMv\xff\n", "\xff\xfa\x18\nStopMv\r\n"});
  REQUIRE(c.lines.size() == 5);
  for (std::size_t i = 0; i < 4; ++i) {
    auto parsed = imess::protocol::parse_command(c.lines[i]);
    auto* err = std::get_if<imess::protocol::ParseError>(&parsed);
    REQUIRE(err);
    CHECK(err->code == imess::protocol::ErrorCode::BadCharacter);
  }
  CHECK(std::holds_alternative<imess::protocol::Command>(imess::protocol::parse_command(c.lines[4])));
}
