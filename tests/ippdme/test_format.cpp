// Response lines byte-exactly (&, #, !, %; E0000 events) and the digest's transcripts (§3, §6).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"

using namespace imess::ippdme;

TEST_CASE("ippdme responses: ack and done carry nothing after the mark, data after one space") {
  CHECK(format_ack({TagKind::Command, 1}) == "00001 &\r\n");
  CHECK(format_done({TagKind::Command, 1}) == "00001 %\r\n");
  CHECK(format_ack({TagKind::Event, 52}) == "E0052 &\r\n");
  CHECK(format_done({TagKind::Event, 52}) == "E0052 %\r\n");
  CHECK(format_data({TagKind::Command, 2}, "IsHomed(1)") == "00002 # IsHomed(1)\r\n");
  CHECK(format_data({TagKind::Command, 2}, {Value::call("X", {Value::of_fixed(150, 4)}),
                                            Value::call("Y", {Value::of_fixed(80, 4)}),
                                            Value::call("Z", {Value::of_fixed(-20, 4)})}) ==
        "00002 # X(150.0000), Y(80.0000), Z(-20.0000)\r\n");
}

TEST_CASE("ippdme responses: the data payloads of the §7 table") {
  const Tag t{TagKind::Command, 10};
  CHECK(format_data(t, {Value::call("DMEVersion", {Value::of_string("1.4")})}) == "00010 # DMEVersion(\"1.4\")\r\n");
  CHECK(format_data(t, {Value::call("GetMachineClass", {Value::of_word("CartCMM")})}) ==
        "00010 # GetMachineClass(CartCMM)\r\n");
  CHECK(format_data(t, {Value::call("ErrStatus", {Value::of_integer(0)})}) == "00010 # ErrStatus(0)\r\n");
  CHECK(format_data(t, {Value::of_string("Speed"), Value::of_string("Number")}) == "00010 # \"Speed\", \"Number\"\r\n");
  CHECK(format_data(t, {Value::call("Tool.PtMeasPar.Speed", {Value::of_number(100)}),
                        Value::call("Tool.Name", {Value::of_string("P1")})}) ==
        "00010 # Tool.PtMeasPar.Speed(100), Tool.Name(\"P1\")\r\n");
  CHECK(format_data(t, {Value::call("ChangeToolAction", {Value::of_word("Switch"), Value::call("X", {Value::of_integer(0)}),
                                                         Value::call("Y", {Value::of_integer(0)}),
                                                         Value::call("Z", {Value::of_integer(0)})})}) ==
        "00010 # ChangeToolAction(Switch, X(0), Y(0), Z(0))\r\n");
  CHECK(format_data(t, {Value::call("CoordSystem", {Value::of_word("PartCsy")})}) == "00010 # CoordSystem(PartCsy)\r\n");
  CHECK(format_data(t, {Value::of_string(error_info(ErrorCode::IncorrectArguments).text)}) ==
        "00010 # \"Incorrect arguments\"\r\n");
}

TEST_CASE("ippdme responses: server events on E0000") {
  CHECK(format_data(kServerTag, {Value::call("PtMeas", {Value::call("X", {Value::of_fixed(212.4031, 4)}),
                                                        Value::call("Y", {Value::of_fixed(55.0102, 4)}),
                                                        Value::call("Z", {Value::of_fixed(-31.9987, 4)}),
                                                        Value::call("IJK", {Value::of_number(0), Value::of_number(0),
                                                                            Value::of_number(1)})})}) ==
        "E0000 # PtMeas(X(212.4031), Y(55.0102), Z(-31.9987), IJK(0, 0, 1))\r\n");
  CHECK(format_data(kServerTag, {Value::call("KeyPress", {Value::of_string("F1")})}) == "E0000 # KeyPress(\"F1\")\r\n");
}

TEST_CASE("ippdme responses: the digest's §3 transcript, client lines parsed, server lines formatted") {
  const std::vector<std::string> client{"00001 StartSession()\r\n", "00002 Get(X(), Y(), Z())\r\n",
                                        "00003 GoTo(X(9999))\r\n", "00004 ClearAllErrors()\r\n"};
  std::string server;
  TagTracker open;
  LineFramer framer;
  std::string all;
  for (const auto& l : client) all += l;
  framer.feed(all, [&](const FramedLine& line) {
    auto r = parse_framed(line);
    REQUIRE(std::holds_alternative<Request>(r));
    const auto& req = std::get<Request>(r);
    REQUIRE(open.try_open(req.tag));
    server += format_ack(req.tag);
    if (std::holds_alternative<Get>(req.command))
      server += format_data(req.tag, {Value::call("X", {Value::of_fixed(150, 4)}), Value::call("Y", {Value::of_fixed(80, 4)}),
                                      Value::call("Z", {Value::of_fixed(-20, 4)})});
    if (std::holds_alternative<GoTo>(req.command))
      server += format_error(req.tag, ErrorCode::MachineLimitEncountered, method_name(req.command));
    server += format_done(req.tag);
    open.close(req.tag);
  });
  CHECK(server ==
        "00001 &\r\n00001 %\r\n"
        "00002 &\r\n00002 # X(150.0000), Y(80.0000), Z(-20.0000)\r\n00002 %\r\n"
        "00003 &\r\n00003 ! Error(3, 2500, GoTo, \"Machine limit encountered [Move Out Of Limits]\")\r\n00003 %\r\n"
        "00004 &\r\n00004 %\r\n");
  CHECK(open.open_count() == 0);
}

TEST_CASE("ippdme responses: a data payload never holds CR or LF or bytes outside 32..126") {
  std::string s = format_data({TagKind::Command, 1}, {Value::of_string("a\r\nb\x01\xff")});
  CHECK(s == "00001 # \"a''b''\"\r\n");
}

// Issue 26, 2: a fixed-point value the I++ grammar cannot hold (more than 16 digits) is written
// in its shortest exact form instead of being cut to 63 characters.
TEST_CASE("ippdme responses: a fixed-point value beyond 16 digits is written whole, readable back") {
  for (double v : {1e300, -2.5e20, 123456789012.5}) {
    const Value x = Value::of_fixed(v, 4);
    INFO(x.text);
    auto parsed = parse_line("00001 SetProp(Tool.PtMeasPar.Speed(" + x.text + "))");
    REQUIRE(std::holds_alternative<Request>(parsed));
    CHECK(std::get<SetProp>(std::get<Request>(parsed).command).settings.at(0).value == v);
  }
  CHECK(Value::of_fixed(430.25, 4).text == "430.2500");
  CHECK(Value::of_fixed(-999999.5, 4).text == "-999999.5000");
}
