// Every error number the parser produces, on the tag the spec answers it on, and the error
// lines byte-exactly; the tracker's reused tags; no input escapes as an exception.
#include <catch2/catch.hpp>

#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"

using namespace imess::ippdme;

namespace {
constexpr Tag kT1{TagKind::Command, 1};
constexpr Tag kE1{TagKind::Event, 1};

struct ErrCase {
  std::string line;
  ErrorCode code;
  std::optional<Tag> tag;  // nullopt: answered on E0000
};

LineError error_of(std::string_view line) {
  auto r = parse_line(line);
  if (std::holds_alternative<Request>(r)) FAIL("parsed, expected an error: " << line);
  return std::get<LineError>(r);
}

using E = ErrorCode;
const std::vector<ErrCase> kCases{
    // 0007: bytes outside 32..126
    {"00001 Ho\x01me()", E::IllegalCharacter, kT1},
    {"00001 Home()\r", E::IllegalCharacter, kT1},
    {"00001 Ch\xe4ngeTool()", E::IllegalCharacter, kT1},
    {"0\t001 Home()", E::IllegalCharacter, std::nullopt},
    {"000012 Ho\x01me()", E::IllegalCharacter, std::nullopt},  // a six-digit tag is no tag: E0000
    // 0001: tags, reserved tags (E0000), a tag longer than five digits (E0000, never on its
    // first five: issue 25), the wrong queue (on the tag: it can be read)
    {"", E::IllegalTag, std::nullopt},
    {"0001 Home()", E::IllegalTag, std::nullopt},
    {"00000 Home()", E::IllegalTag, std::nullopt},
    {"E0000 AbortE()", E::IllegalTag, std::nullopt},
    {"e0001 AbortE()", E::IllegalTag, std::nullopt},
    {"A0001 Home()", E::IllegalTag, std::nullopt},
    {"E001 AbortE()", E::IllegalTag, std::nullopt},
    {"012345 GoTo(X(3.1))", E::IllegalTag, std::nullopt},
    {"E00012 AbortE()", E::IllegalTag, std::nullopt},
    {"E0001 Home()", E::IllegalTag, kE1},
    {"E0001 GetProp(Tool.Name())", E::IllegalTag, kE1},
    {"00001 AbortE()", E::IllegalTag, kT1},
    {"00001 GetErrStatusE()", E::IllegalTag, kT1},
    {"00001 GetPropE(Tool.Name())", E::IllegalTag, kT1},
    {"00001 SetPropE(Tool.GoToPar.Speed(1))", E::IllegalTag, kT1},
    {"00001 OnMoveReportE(X())", E::IllegalTag, kT1},
    // 0002: column 6 (another byte there leaves the tag unreadable: E0000)
    {"00001Home()", E::NoSpaceAtPos6, std::nullopt},
    {"00001", E::NoSpaceAtPos6, kT1},
    {"E0001_AbortE()", E::NoSpaceAtPos6, std::nullopt},
    // 0008: garbled call, spaces where none may be
    {"00001 ", E::ProtocolError, kT1},
    {"00001  Home()", E::ProtocolError, kT1},
    {"00001 Home() ", E::ProtocolError, kT1},
    {"00001 Home", E::ProtocolError, kT1},
    {"00001 GoTo(X(1)", E::ProtocolError, kT1},
    {"00001 GoTo(X(12345678901234567))", E::ProtocolError, kT1},
    {"00001 GoTo(X(1e1000))", E::ProtocolError, kT1},
    {"00001 ChangeTool(\"Ref)", E::ProtocolError, kT1},
    {"00001 Ho me()", E::ProtocolError, kT1},
    // 0507: unknown method (case matters)
    {"00001 home()", E::IllegalCommand, kT1},
    {"00001 HOME()", E::IllegalCommand, kT1},
    {"00001 Foo(1, 2)", E::IllegalCommand, kT1},
    {"00001 XX.Cmd()", E::IllegalCommand, kT1},
    {"E0001 FooE()", E::IllegalCommand, kE1},
    {"00001 Foo(X(1,)", E::IllegalCommand, kT1},  // wrong arguments of an unknown method
    // 0501: known 1.4 methods not implemented
    {"00001 ScanOnCurve(Closed(0))", E::UnsupportedCommand, kT1},
    {"00001 AlignTool(0, 0, 1, 0)", E::UnsupportedCommand, kT1},
    {"00001 LockAxis(C())", E::UnsupportedCommand, kT1},
    {"00001 ReQualify()", E::UnsupportedCommand, kT1},
    // 0502: argument count and kind
    {"00001 Home(1)", E::IncorrectArguments, kT1},
    {"00001 StartSession(\"x\")", E::IncorrectArguments, kT1},
    {"00001 Get()", E::IncorrectArguments, kT1},
    {"00001 Get(X(1))", E::IncorrectArguments, kT1},
    {"00001 Get(X)", E::IncorrectArguments, kT1},
    {"00001 GoTo()", E::IncorrectArguments, kT1},
    {"00001 GoTo(X())", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(1, 2))", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(\"1\"))", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(1), X(2))", E::IncorrectArguments, kT1},
    {"00001 GoTo(5)", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(1e999))", E::IncorrectArguments, kT1},
    // 0502 too: readable tokens that make no argument list (the NIST server's `GoTo(X(1,)`)
    {"00001 GoTo(X(1,)", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(1 0))", E::IncorrectArguments, kT1},
    {"00001 GoTo(X(1),)", E::IncorrectArguments, kT1},
    // 0502 too: an item asked for twice (issue 25: `Get(X(), X())` was answered twice)
    {"00001 Get(X(), X())", E::IncorrectArguments, kT1},
    {"00001 Get(X(), Y(), Tool.A(), Tool.A())", E::IncorrectArguments, kT1},
    {"00001 OnPtMeasReport(X(), IJK(), IJK())", E::IncorrectArguments, kT1},
    {"E0001 OnMoveReportE(Dis(1), Z(), Z())", E::IncorrectArguments, kE1},
    {"00001 PtMeas()", E::IncorrectArguments, kT1},
    {"00001 PtMeas(IJK(0, 0, 1))", E::IncorrectArguments, kT1},
    {"00001 PtMeas(X(1), IJK(0, 1))", E::IncorrectArguments, kT1},
    {"00001 PtMeas(X(1), IJK(0, 0, 1), IJK(0, 0, 1))", E::IncorrectArguments, kT1},
    {"00001 PtMeas(X(1), IJK(0, A, 1))", E::IncorrectArguments, kT1},
    {"00001 ChangeTool(RefTool)", E::IncorrectArguments, kT1},
    {"00001 ChangeTool()", E::IncorrectArguments, kT1},
    {"00001 FindTool(\"a\", \"b\")", E::IncorrectArguments, kT1},
    {"00001 GetErrorInfo()", E::IncorrectArguments, kT1},
    {"00001 GetErrorInfo(\"0502\")", E::IncorrectArguments, kT1},
    {"00001 StopDaemon(\"E0001\")", E::IncorrectArguments, kT1},
    {"00001 StopDaemon()", E::IncorrectArguments, kT1},
    {"00001 GetProp()", E::IncorrectArguments, kT1},
    {"00001 GetProp(Tool.Name(1))", E::IncorrectArguments, kT1},
    {"00001 GetProp(\"Tool.Name\")", E::IncorrectArguments, kT1},
    {"00001 SetProp()", E::IncorrectArguments, kT1},
    {"00001 SetProp(Tool.GoToPar.Speed())", E::IncorrectArguments, kT1},
    {"00001 SetProp(Tool.GoToPar.Speed(\"fast\"))", E::IncorrectArguments, kT1},
    {"00001 EnumProp(Tool.PtMeasPar)", E::IncorrectArguments, kT1},
    {"00001 EnumAllProp()", E::IncorrectArguments, kT1},
    {"00001 SetCoordSystem()", E::IncorrectArguments, kT1},
    {"00001 SetCoordSystem(PartCsy, PartCsy)", E::IncorrectArguments, kT1},
    {"00001 GetCsyTransformation()", E::IncorrectArguments, kT1},
    {"00001 SetCsyTransformation(PartCsy, 1, 2, 3)", E::IncorrectArguments, kT1},
    {"00001 SetCsyTransformation(PartCsy, 1, 2, 3, 4, 5, X)", E::IncorrectArguments, kT1},
    {"00001 OnPtMeasReport(X(1))", E::IncorrectArguments, kT1},
    {"E0001 OnMoveReportE(Time(1), Time(2), X())", E::IncorrectArguments, kE1},
    {"E0001 OnMoveReportE(Dis(), X())", E::IncorrectArguments, kE1},
    {"E0001 OnMoveReportE(X(3))", E::IncorrectArguments, kE1},
    // 0505: an argument name that does not exist there
    {"00001 Get(W())", E::ArgumentNotRecognized, kT1},
    {"00001 Get(Tool.D())", E::ArgumentNotRecognized, kT1},
    {"00001 GoTo(W(1))", E::ArgumentNotRecognized, kT1},
    {"00001 GoTo(R(1))", E::ArgumentNotRecognized, kT1},
    {"00001 PtMeas(X(1), Tool.A(3))", E::ArgumentNotRecognized, kT1},
    // 0508: report-only items outside a report list
    {"00001 Get(IJK())", E::BadContext, kT1},
    {"00001 Get(X(), ER())", E::BadContext, kT1},
    {"00001 Get(Q())", E::BadContext, kT1},
    {"E0001 OnMoveReportE(Time(1), IJK())", E::BadContext, kE1},
    // 0509: a value outside its domain
    {"00001 SetCoordSystem(WorldCsy)", E::BadArgument, kT1},
    {"00001 SetCoordSystem(partcsy)", E::BadArgument, kT1},
    {"00001 SetCoordSystem(\"PartCsy\")", E::BadArgument, kT1},
    {"00001 SetCoordSystem(JogMoveCsy)", E::BadArgument, kT1},
    {"00001 GetCsyTransformation(MachineCsy)", E::BadArgument, kT1},
    {"00001 SetCsyTransformation(Part, 0, 0, 0, 0, 0, 0)", E::BadArgument, kT1},
    {"00001 GetErrorInfo(12.5)", E::BadArgument, kT1},
    {"00001 GetErrorInfo(10000)", E::BadArgument, kT1},
    {"00001 GetErrorInfo(-1)", E::BadArgument, kT1},
    {"00001 StopDaemon(E0000)", E::BadArgument, kT1},
    {"00001 ChangeTool(\"\")", E::BadArgument, kT1},
    {"E0001 OnMoveReportE(Time(-1), X())", E::BadArgument, kE1},
    // 0510: report lists and property paths
    {"00001 OnPtMeasReport()", E::BadProperty, kT1},
    {"00001 OnPtMeasReport(W())", E::BadProperty, kT1},
    {"00001 OnPtMeasReport(X)", E::BadProperty, kT1},
    {"00001 OnPtMeasReport(X(), 5)", E::BadProperty, kT1},
    {"E0001 OnMoveReportE()", E::BadProperty, kE1},
    {"E0001 OnMoveReportE(Time(1), Dis(2))", E::BadProperty, kE1},
    {"E0001 OnMoveReportE(W())", E::BadProperty, kE1},
    {"00001 GetProp(Speed())", E::BadProperty, kT1},
    {"E0001 GetPropE(Tool.Name(), Speed())", E::BadProperty, kE1},
    {"00001 SetProp(Speed(1))", E::BadProperty, kT1},
    // 0509: a coordinate system's offset beyond ±1e6 mm (issue 26: 1.7e308 stopped messd)
    {"00001 SetCsyTransformation(PartCsy, 1.7e308, 1.7e308, 0, 0, 45, 0)", E::BadArgument, kT1},
    {"00001 SetCsyTransformation(PartCsy, 1e300, 0, 0, 0, 0, 0)", E::BadArgument, kT1},
    {"00001 SetCsyTransformation(MoveableMachineCsy, 0, -1000000.001, 0, 0, 0, 0)", E::BadArgument, kT1},
    {"00001 SetCsyTransformation(SensorCsy, 0, 0, 2e6, 0, 0, 0)", E::BadArgument, kT1},
    // 1007, 1010: values the spec gives their own numbers
    {"00001 SetCsyTransformation(PartCsy, 0, 0, 0, 181, 0, 0)", E::ThetaOutOfRange, kT1},
    {"00001 SetCsyTransformation(PartCsy, 0, 0, 0, -0.1, 0, 0)", E::ThetaOutOfRange, kT1},
    {"00001 PtMeas(X(1), Y(2), Z(3), IJK(0, 0, 0))", E::VectorHasNoNorm, kT1},
    {"00001 PtMeas(X(1), IJK(0.0, -0, 0e5))", E::VectorHasNoNorm, kT1},
};
}  // namespace

TEST_CASE("ippdme errors: every bad line gets the spec's number on the right tag") {
  std::set<ErrorCode> produced;
  for (const auto& c : kCases) {
    INFO(c.line);
    auto e = error_of(c.line);
    CHECK(number_of(e.code) == number_of(c.code));
    CHECK(e.tag == c.tag);
    CHECK(e.cause.size() <= 64);
    produced.insert(e.code);
  }
  // The numbers the parser can produce; the others are the server's (docs/ippdme.md).
  CHECK(produced == std::set<ErrorCode>{E::IllegalTag, E::NoSpaceAtPos6, E::IllegalCharacter, E::ProtocolError,
                                        E::UnsupportedCommand, E::IncorrectArguments, E::ArgumentNotRecognized,
                                        E::IllegalCommand, E::BadContext, E::BadArgument, E::BadProperty,
                                        E::ThetaOutOfRange, E::VectorHasNoNorm});
}

TEST_CASE("ippdme errors: F3 names the method, or the start of a line without one") {
  CHECK(error_of("00001 GoTo(X(1), X(2))").cause == "GoTo");
  CHECK(error_of("00001 Foo(1)").cause == "Foo");
  CHECK(error_of("00001 GoTo(X(1)").cause == "GoTo");
  CHECK(error_of("E0001 Home()").cause == "Home");
  CHECK(error_of("0001 Home()").cause == "0001 Home()");
  CHECK(error_of("00001 Ho\x01me(\"a\")").cause == "00001 Ho?me(?a?)");
  CHECK(error_of(std::string(200, '0')).cause.size() == 64);
}

TEST_CASE("ippdme errors: framed faults, an overlong line is a protocol error") {
  CHECK(number_of(std::get<LineError>(parse_framed({"00001 Home()", LineFault::IllegalCharacter})).code) == 7);
  auto e = std::get<LineError>(parse_framed({"00004 Home()", LineFault::TooLong}));
  CHECK(e.code == E::ProtocolError);
  CHECK(e.tag == Tag{TagKind::Command, 4});
  CHECK(std::holds_alternative<Request>(parse_framed({"00001 Home()", LineFault::None})));
  CHECK_FALSE(std::get<LineError>(parse_framed({"x", LineFault::IllegalCharacter})).tag);
}

TEST_CASE("ippdme errors: a reused tag is answered with 0001 on E0000") {
  TagTracker open;
  auto r = std::get<Request>(parse_line("00005 GoTo(X(500))"));
  REQUIRE(open.try_open(r.tag));
  auto again = std::get<Request>(parse_line("00005 Home()"));
  CHECK_FALSE(open.try_open(again.tag));
  CHECK(format_error(kServerTag, E::IllegalTag, "Home") == "E0000 ! Error(2, 0001, Home, \"Illegal tag\")\r\n");
  // A parse error on an open tag goes to E0000 too; on a free tag to that tag.
  auto bad = error_of("00005 Home(1)");
  CHECK(answer_tag(bad, open) == kServerTag);
  CHECK(format_error(bad, open) == "E0000 ! Error(3, 0502, Home, \"Incorrect arguments\")\r\n");
  open.close(r.tag);
  CHECK(format_error(bad, open) == "00005 ! Error(3, 0502, Home, \"Incorrect arguments\")\r\n");
  // The wrong queue: the tag can be read, so the error goes on it (after its Ack, the server's).
  CHECK(format_error(error_of("E0003 Home()"), open) == "E0003 ! Error(2, 0001, Home, \"Illegal tag\")\r\n");
}

TEST_CASE("ippdme errors: the error lines byte-exactly, both F3 styles") {
  CHECK(format_error({TagKind::Command, 3}, E::MachineLimitEncountered, "GoTo") ==
        "00003 ! Error(3, 2500, GoTo, \"Machine limit encountered [Move Out Of Limits]\")\r\n");
  CHECK(format_error({TagKind::Command, 51}, E::TransactionAborted, "GoTo") ==
        "00051 ! Error(2, 0006, GoTo, \"Transaction aborted (Use ClearAllErrors To Continue)\")\r\n");
  CHECK(format_error({TagKind::Command, 3}, E::MachineLimitEncountered, "GoTo", CauseStyle::Quoted) ==
        "00003 ! Error(3, 2500, \"GoTo\", \"Machine limit encountered [Move Out Of Limits]\")\r\n");
  CHECK(format_error(kServerTag, E::EmergencyStop, "EStop") == "E0000 ! Error(3, 0500, EStop, \"Emergency stop\")\r\n");
  CHECK(format_error(kServerTag, E::IllegalTag, "0001 Home()") ==
        "E0000 ! Error(2, 0001, \"0001 Home()\", \"Illegal tag\")\r\n");
  CHECK(format_error(kServerTag, E::IllegalCharacter, "a\"b") ==
        "E0000 ! Error(3, 0007, \"a'b\", \"Illegal character\")\r\n");
  CHECK(format_error({TagKind::Command, 9}, E::ArgumentOutOfRange, "SetProp") ==
        "00009 ! Error(1, 0504, SetProp, \"Argument out of range\")\r\n");
  CHECK(format_error({TagKind::Command, 9}, E::ControllerCommunicationsFailure, "Home") ==
        "00009 ! Error(9, 0503, Home, \"Controller communications failure\")\r\n");
  CHECK(format_error({TagKind::Command, 9}, E::BufferFull, "GoTo") == "00009 ! Error(0, 0000, GoTo, \"Buffer full\")\r\n");
}

TEST_CASE("ippdme errors: the table holds the spec's numbers, severities and texts, in order") {
  int previous = -1;
  for (const auto& e : error_table()) {
    INFO(number_of(e.code));
    CHECK(number_of(e.code) > previous);
    previous = number_of(e.code);
    CHECK(&error_info(e.code) == &e);
    CHECK(find_error(number_of(e.code)) == &e);
    const int s = severity_number(e.severity);
    CHECK((s == 0 || s == 1 || s == 2 || s == 3 || s == 9));
    char number[8];
    std::snprintf(number, sizeof number, "%04d", number_of(e.code));
    CHECK(format_error({TagKind::Command, 1}, e.code, "M") ==
          "00001 ! Error(" + std::to_string(s) + ", " + number + ", M, \"" + std::string(e.text) + "\")\r\n");
  }
  CHECK(error_table().size() == 36);
  CHECK(find_error(3) == nullptr);
  CHECK(find_error(1002) == nullptr);
  CHECK(error_info(E::IllegalCharacter).severity == Severity::OperatorError);
  CHECK(error_info(E::NoDaemonsAreActive).severity == Severity::Warning);
  CHECK(error_info(E::UseClearAllErrorsToContinue).text == "Use ClearAllErrors to continue");
}

// Issue 25: a refusal (the line was not executed for what it says: its tag, characters,
// syntax or arguments, an optional command the server lacks, a daemon not there or already
// there) is no error state; what the machine failed to do is, and so is every other error of
// severity 2 or more. A query's errors never are.
TEST_CASE("ippdme errors: which errors put a session into the error state") {
  const std::set<E> refusals{E::IllegalTag,        E::NoSpaceAtPos6,    E::IllegalCharacter,      E::ProtocolError,
                             E::UnsupportedCommand, E::IncorrectArguments, E::ArgumentNotRecognized, E::ArgumentNotSupported,
                             E::IllegalCommand,    E::BadContext,        E::BadArgument,           E::BadProperty,
                             E::DaemonDoesNotExist, E::DaemonAlreadyExists, E::ThetaOutOfRange,    E::VectorHasNoNorm};
  for (const auto& e : error_table()) {
    INFO(number_of(e.code));
    CHECK(is_refusal(e.code) == (refusals.count(e.code) == 1));
    CHECK(enters_error_state(e.code) == (!refusals.count(e.code) && e.severity >= Severity::Error));
    CHECK_FALSE(enters_error_state(e.code, "GetProp"));
    CHECK(enters_error_state(e.code, "GoTo") == enters_error_state(e.code));
  }
  for (E e : {E::UnsupportedCommand, E::IncorrectArguments, E::IllegalCommand, E::ProtocolError, E::VectorHasNoNorm,
              E::ArgumentOutOfRange, E::NoDaemonsAreActive})
    CHECK_FALSE(enters_error_state(e));
  for (E e : {E::MachineLimitEncountered, E::MachineInErrorState, E::SurfaceNotFound, E::IllegalTouch, E::TransactionAborted,
              E::ToolNotFound, E::ErrorProcessingMethod})
    CHECK(enters_error_state(e));
  CHECK_FALSE(enters_error_state(E::ToolNotFound, "FindTool"));
  CHECK(enters_error_state(E::ToolNotFound, "ChangeTool"));
  CHECK_FALSE(enters_error_state(E::ToolNotDefined, "EnumProp"));
  CHECK(enters_error_state(E::ToolNotDefined, "SetProp"));
}
