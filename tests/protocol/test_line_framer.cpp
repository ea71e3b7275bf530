// LineFramer: LF/CRLF, telnet negotiation, overlong lines, chunk boundaries.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "imess/protocol/line_framer.hpp"

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

TEST_CASE("telnet CR NUL is a line end without a byte") {
  LineFramer f;
  auto c = feed_all(f, {std::string("Help\r\0\n", 7)});
  REQUIRE(c.lines == std::vector<std::string>{"Help"});
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
