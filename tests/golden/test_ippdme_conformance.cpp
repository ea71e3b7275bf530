// I++ DME framing and the error state as inspection software meets them (issue 25, section 2):
// every readable tag acknowledged first, an unreadable one answered on E0000, and programs that
// ask for what the machine lacks (a probe head's angles, R, a scan) run to the end.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "ipp_script.hpp"

namespace imess::golden {
namespace {

std::vector<std::string> conformance_lines(const std::string& script) { return ipp_session_lines(script, "conformance"); }

std::vector<std::string> on_tag(const std::vector<std::string>& lines, const std::string& tag) {
  std::vector<std::string> out;
  for (const auto& l : lines)
    if (l.compare(0, tag.size() + 1, tag + " ") == 0) out.push_back(l);
  return out;
}


}  // namespace

TEST_CASE("I++ DME conformance: a refused line is acknowledged first, then its error and %") {
  const auto lines = conformance_lines(kIppStart +
                                   "2> 00020 PtMeas(X(430), Y(330), Z(80), IJK(0,0,0))\n"
                                   "2> 00021 Frobnicate()\n"
                                   "2> 00022 AbortE()\n"
                                   "2> E0023 GoTo(X(1))\n"
                                   "2> 00024 GoTo(X(1)\n");
  CHECK(on_tag(lines, "00020") ==
        std::vector<std::string>{"00020 &", "00020 ! Error(2, 1010, PtMeas, \"Vector has no norm\")", "00020 %"});
  CHECK(on_tag(lines, "00021") == std::vector<std::string>{"00021 &", "00021 ! Error(3, 0507, Frobnicate, \"Illegal command\")", "00021 %"});
  CHECK(on_tag(lines, "00022") == std::vector<std::string>{"00022 &", "00022 ! Error(2, 0001, AbortE, \"Illegal tag\")", "00022 %"});
  CHECK(on_tag(lines, "E0023") == std::vector<std::string>{"E0023 &", "E0023 ! Error(2, 0001, GoTo, \"Illegal tag\")", "E0023 %"});
  CHECK(on_tag(lines, "00024") == std::vector<std::string>{"00024 &", "00024 ! Error(3, 0008, GoTo, \"Protocol error\")", "00024 %"});
}

TEST_CASE("I++ DME conformance: a refused line behind a running GoTo completes after it") {
  const auto lines = conformance_lines(kIppStart + "2> 00002 GoTo(Z(300))\n= 100 ms\n2> 00003 Get(W())\n= 5000 ms\n");
  const long ack = index_of(lines, "00003 &"), go_to = index_of(lines, "00002 %");
  const long error = index_of(lines, "00003 ! Error(3, 0505, Get, \"Argument not recognized\")"), done = index_of(lines, "00003 %");
  REQUIRE(ack >= 0);
  REQUIRE(go_to >= 0);
  CHECK(ack < go_to);     // acknowledged at once
  CHECK(go_to < error);   // answered in its turn
  CHECK(error < done);
  CHECK(on_tag(lines, "00002") == std::vector<std::string>{"00002 &", "00002 %"});  // the move was not aborted by it
}

TEST_CASE("I++ DME conformance: a line whose tag cannot be read is answered on E0000 only") {
  const auto lines = conformance_lines(kIppStart + "2> 012345 GoTo(X(3.1))\n2> 00002Get(X())\n2> 00003 Get(X())\n");
  CHECK(on_tag(lines, "01234").empty());
  CHECK(on_tag(lines, "00002").empty());
  REQUIRE(on_tag(lines, "E0000").size() == 2);
  CHECK(on_tag(lines, "E0000")[0].rfind("E0000 ! Error(2, 0001, ", 0) == 0);
  CHECK(on_tag(lines, "E0000")[1].rfind("E0000 ! Error(2, 0002, ", 0) == 0);
}

TEST_CASE("I++ DME conformance: Tool.A, Tool.B and R are reported as 0") {
  const auto lines = conformance_lines(kIppStart + "2> 00002 Get(X(), Tool.A(), Tool.B(), R())\n");
  CHECK(on_tag(lines, "00002") ==
        std::vector<std::string>{"00002 &", "00002 # X(430.0000), Tool.A(0.0000), Tool.B(0.0000), R(0.0000)", "00002 %"});
}

// Shaped as the NIST measuring programs DCXpart.prg and simple.prg: a move daemon with the
// head's angles, a report list with R, an unsupported scan and a GoTo with a head angle on the
// way (0501, 0506: no error state) — every command completes, none gets 0514.
TEST_CASE("I++ DME conformance: measuring programs asking for what the machine lacks run to the end") {
  const auto lines = conformance_lines(kIppStart +
                                   "2> E0002 OnMoveReportE(Dis(10.0), X(), Y(), Z(), Tool.A(), Tool.B())\n"
                                   "2> 00003 OnPtMeasReport(X(), Y(), Z(), R())\n"
                                   "2> 00004 GoTo(X(460), Y(350), Z(100))\n= 3000 ms\n"
                                   "2> 00005 GoTo(Z(40))\n= 3000 ms\n"
                                   "2> 00006 ScanOnLine(450, 335, 40, 470, 335, 40, 0, 1, 0, 1)\n"
                                   "2> 00007 GoTo(Z(40), Tool.A(90))\n"
                                   "2> 00008 PtMeas(X(475), Y(350), Z(40), IJK(-1, 0, 0))\n= 3000 ms\n"
                                   "2> 00009 PtMeas(X(460), Y(335), Z(40), IJK(0, 1, 0))\n= 3000 ms\n"
                                   "2> 00010 GoTo(Z(100))\n= 3000 ms\n"
                                   "2> 00011 GetErrStatusE()\n"
                                   "2> 00012 EndSession()\n");
  for (const auto& l : lines) {
    INFO(l);
    CHECK(l.find("0514") == std::string::npos);
  }
  CHECK(index_of(lines, "E0002 # X(430.0000), Y(330.0000), Z(100.0000), Tool.A(0.0000), Tool.B(0.0000)") >= 0);
  CHECK(on_tag(lines, "00006") ==
        std::vector<std::string>{"00006 &", "00006 ! Error(3, 0501, ScanOnLine, \"Unsupported command\")", "00006 %"});
  CHECK(on_tag(lines, "00007") ==
        std::vector<std::string>{"00007 &", "00007 ! Error(3, 0506, GoTo, \"Argument not supported\")", "00007 %"});
  CHECK(on_tag(lines, "00008") == std::vector<std::string>{"00008 &", "00008 # X(475.0000), Y(350.0000), Z(40.0000), R(0.0000)", "00008 %"});
  CHECK(on_tag(lines, "00009").size() == 3);
  CHECK(on_tag(lines, "00010") == std::vector<std::string>{"00010 &", "00010 %"});
  CHECK(on_tag(lines, "00012") == std::vector<std::string>{"00012 &", "00012 %"});
}

}  // namespace imess::golden

namespace imess::golden {

// Issue 25, section 2, 4: a machine fault (the probe pushed past its overtravel by hand: an
// emergency stop) is seen and cleared from I++ — GoTo 1000, GetXtdErrStatus lists it,
// ClearAllErrors resets the machine once the cause is gone, and the next GoTo moves.
TEST_CASE("I++ DME conformance: a machine fault is visible and cleared by ClearAllErrors") {
  const auto lines = conformance_lines(
      "@ config/sim-servo-card.json\n"
      "> HandMv 0 0 -30 100\n= 2000 ms\n"    // into the part past the overtravel: the fault
      "> HandMv 0 0 20 50\n= 1000 ms\n"      // the probe freed by hand: the cause is gone
      "> Release\n"
      "+2 ipp\n2> 00001 StartSession()\n"
      "2> 00002 GoTo(Z(100))\n"
      "2> 00003 GetXtdErrStatus()\n"
      "2> 00004 ClearAllErrors()\n= 100 ms\n"
      "2> 00005 GetXtdErrStatus()\n"
      "2> 00006 GoTo(Z(100))\n= 3000 ms\n");
  CHECK(on_tag(lines, "00002") == std::vector<std::string>{"00002 &", "00002 ! Error(3, 1000, GoTo, \"Machine in error state\")", "00002 %"});
  CHECK(index_of(lines, "00003 ! Error(3, 1000, Machine, \"Machine in error state\")") >= 0);
  CHECK(on_tag(lines, "00004") == std::vector<std::string>{"00004 &", "00004 %"});
  CHECK(index_of(lines, "00005 ! Error(3, 1000, Machine, \"Machine in error state\")") < 0);
  CHECK(on_tag(lines, "00006") == std::vector<std::string>{"00006 &", "00006 %"});
}

}  // namespace imess::golden

namespace imess::golden {

// Issue 25, section 2: SetProp(Tool.GoToPar.Accel(50.0)) is accepted and applied. A 200 mm GoTo
// at 50 mm/s takes about 4.05 s with the machine's 1000 mm/s2, 5 s with 50 mm/s2 (1 s to reach
// the speed, 1 s to stop): after 4.5 s the first has arrived, the second not yet.
TEST_CASE("I++ DME conformance: a lowered GoToPar.Accel slows the session's moves down") {
  auto arrived_after = [](const std::string& set_accel, const std::string& wait) {
    const auto lines = conformance_lines(kIppStart + set_accel + "2> 00003 GoTo(Z(300))\n= " + wait + "\n");
    return index_of(lines, "00003 %") >= 0;
  };
  CHECK(arrived_after("2> 00002 GetDMEVersion()\n", "4500 ms"));
  CHECK_FALSE(arrived_after("2> 00002 SetProp(Tool.GoToPar.Accel(50.0))\n", "4500 ms"));
  CHECK(arrived_after("2> 00002 SetProp(Tool.GoToPar.Accel(50.0))\n", "5500 ms"));
}

}  // namespace imess::golden
