// Framing: CR LF ends a line; lone CR/LF and bytes outside 32..126 make it illegal (0007).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "imess/ippdme/line_framer.hpp"

using namespace imess::ippdme;

namespace {
struct Got {
  std::string text;
  LineFault fault;
};
std::vector<Got> frame(std::string_view bytes, std::size_t max = kMaxLineLength, std::size_t chunk = 1000000) {
  LineFramer f(max);
  std::vector<Got> out;
  for (std::size_t at = 0; at < bytes.size(); at += chunk)
    f.feed(bytes.substr(at, chunk), [&](const FramedLine& l) { out.push_back({std::string(l.text), l.fault}); });
  return out;
}
}  // namespace

TEST_CASE("ippdme framer: CR LF ends a line, at any read boundary") {
  for (std::size_t chunk : {1u, 2u, 3u, 7u, 1000u}) {
    auto lines = frame("00001 StartSession()\r\n00002 Home()\r\n000", kMaxLineLength, chunk);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0].text == "00001 StartSession()");
    CHECK(lines[0].fault == LineFault::None);
    CHECK(lines[1].text == "00002 Home()");
  }
  LineFramer f;
  f.feed("00003 Ho", [](const FramedLine&) { FAIL("no line yet"); });
  CHECK(f.pending() == 8);
}

TEST_CASE("ippdme framer: a lone LF ends the line but makes it illegal") {
  auto lines = frame("00001 Home()\n00002 Home()\r\n");
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].fault == LineFault::IllegalCharacter);
  CHECK(lines[0].text == "00001 Home()");
  CHECK(lines[1].fault == LineFault::None);
}

TEST_CASE("ippdme framer: a CR in mid-line, LF CR order, control and 8-bit bytes are illegal") {
  auto lines = frame("00001 Ho\rme()\r\n00002 Home()\n\r\n00003 H\tome()\r\n00004 H\xe9me()\r\n00005 \x7f\r\n");
  REQUIRE(lines.size() == 6);
  CHECK(lines[0].fault == LineFault::IllegalCharacter);
  CHECK(lines[0].text == "00001 Ho\rme()");
  CHECK(lines[1].fault == LineFault::IllegalCharacter);  // "\n" without CR
  CHECK(lines[2].fault == LineFault::None);              // the "\r\n" after it: an empty line
  CHECK(lines[2].text.empty());
  CHECK(lines[3].fault == LineFault::IllegalCharacter);
  CHECK(lines[4].fault == LineFault::IllegalCharacter);
  CHECK(lines[5].fault == LineFault::IllegalCharacter);
}

TEST_CASE("ippdme framer: lines are capped, the rest is dropped and the next line is clean") {
  std::string longline(100, 'A');
  auto lines = frame(longline + "\r\n00001 Home()\r\n", 40);
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].fault == LineFault::TooLong);
  CHECK(lines[0].text.size() == 40);
  CHECK(lines[1].fault == LineFault::None);
  CHECK(frame(std::string(kMaxLineLength, 'A') + "\r\n")[0].fault == LineFault::None);
  CHECK(frame(std::string(kMaxLineLength + 1, 'A') + "\r\n")[0].fault == LineFault::TooLong);
}
