// Every declared command, byte-exact both ways: the canonical line parses to the typed command
// and the typed command formats to the same bytes. Then the forms that parse but are not canonical.
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"

using namespace imess::ippdme;

namespace {
constexpr Tag kT1{TagKind::Command, 1};
constexpr Tag kE7{TagKind::Event, 7};

struct Case {
  std::string line;  // with CR LF
  Tag tag;
  Command command;
};

Axes xyz(double x, double y, double z) {
  Axes a;
  a.x = x;
  a.y = y;
  a.z = z;
  return a;
}

Axes z_only(double z) {
  Axes a;
  a.z = z;
  return a;
}
Axes xy(double x, double y) {
  Axes a;
  a.x = x;
  a.y = y;
  return a;
}

std::vector<Case> cases() {
  Axes goto_all = xyz(10, 20.5, -3);
  goto_all.tool_a = 90;
  goto_all.tool_b = -45;
  goto_all.tool_c = 0.25;
  Axes only_z = z_only(5);
  OnMoveReportE move{0.1, 2, {Item::X, Item::Y, Item::Z, Item::ToolA, Item::R}};
  return {
      {"00001 StartSession()\r\n", kT1, StartSession{}},
      {"00001 EndSession()\r\n", kT1, EndSession{}},
      {"00001 StopDaemon(E0005)\r\n", kT1, StopDaemon{{TagKind::Event, 5}}},
      {"00001 StopAllDaemons()\r\n", kT1, StopAllDaemons{}},
      {"E0007 AbortE()\r\n", kE7, AbortE{}},
      {"00001 GetErrorInfo(502)\r\n", kT1, GetErrorInfo{502}},
      {"00001 ClearAllErrors()\r\n", kT1, ClearAllErrors{}},
      {"00001 GetProp(Tool.PtMeasPar.Speed(), Tool.Name())\r\n", kT1, GetProp{{"Tool.PtMeasPar.Speed", "Tool.Name"}}},
      {"E0007 GetPropE(Tool.GoToPar.Speed.Max())\r\n", kE7, GetPropE{{"Tool.GoToPar.Speed.Max"}}},
      {"00001 SetProp(Tool.PtMeasPar.Speed(100), Tool.GoToPar.Accel(0.5))\r\n", kT1,
       SetProp{{{"Tool.PtMeasPar.Speed", 100}, {"Tool.GoToPar.Accel", 0.5}}}},
      {"E0007 SetPropE(Tool.GoToPar.Speed(250))\r\n", kE7, SetPropE{{{"Tool.GoToPar.Speed", 250}}}},
      {"00001 EnumProp(Tool.PtMeasPar())\r\n", kT1, EnumProp{"Tool.PtMeasPar"}},
      {"00001 EnumAllProp(Tool())\r\n", kT1, EnumAllProp{"Tool"}},
      {"00001 GetDMEVersion()\r\n", kT1, GetDMEVersion{}},
      {"00001 Home()\r\n", kT1, Home{}},
      {"00001 IsHomed()\r\n", kT1, IsHomed{}},
      {"00001 EnableUser()\r\n", kT1, EnableUser{}},
      {"00001 DisableUser()\r\n", kT1, DisableUser{}},
      {"00001 IsUserEnabled()\r\n", kT1, IsUserEnabled{}},
      {"00001 OnPtMeasReport(X(), Y(), Z(), IJK(), ER(), Q(), R(), Tool.A(), Tool.B(), Tool.C())\r\n", kT1,
       OnPtMeasReport{{Item::X, Item::Y, Item::Z, Item::IJK, Item::ER, Item::Q, Item::R, Item::ToolA, Item::ToolB,
                       Item::ToolC}}},
      {"E0007 OnMoveReportE(Time(0.1), Dis(2), X(), Y(), Z(), Tool.A(), R())\r\n", kE7, move},
      {"E0007 OnMoveReportE(X())\r\n", kE7, OnMoveReportE{std::nullopt, std::nullopt, {Item::X}}},
      {"00001 GetMachineClass()\r\n", kT1, GetMachineClass{}},
      {"E0007 GetErrStatusE()\r\n", kE7, GetErrStatusE{}},
      {"00001 GetXtdErrStatus()\r\n", kT1, GetXtdErrStatus{}},
      {"00001 Get(X(), Y(), Z(), Tool.A(), Tool.B(), Tool.C(), R())\r\n", kT1,
       Get{{Item::X, Item::Y, Item::Z, Item::ToolA, Item::ToolB, Item::ToolC, Item::R}}},
      {"00001 GoTo(X(10), Y(20.5), Z(-3), Tool.A(90), Tool.B(-45), Tool.C(0.25))\r\n", kT1, GoTo{goto_all}},
      {"00001 GoTo(Z(5))\r\n", kT1, GoTo{only_z}},
      {"00001 PtMeas(X(1), Y(2), Z(3))\r\n", kT1, PtMeas{xyz(1, 2, 3), std::nullopt}},
      {"00001 PtMeas(X(1), Y(2), Z(3), IJK(0, 0, 1))\r\n", kT1, PtMeas{xyz(1, 2, 3), Vector3{0, 0, 1}}},
      {"00001 PtMeas(Z(-40), IJK(0.7071, -0.7071, 0))\r\n", kT1, PtMeas{z_only(-40), Vector3{0.7071, -0.7071, 0}}},
      {"00001 EnumTools()\r\n", kT1, EnumTools{}},
      {"00001 ChangeTool(\"RefTool\")\r\n", kT1, ChangeTool{"RefTool"}},
      {"00001 SetTool(\"NoTool\")\r\n", kT1, SetTool{"NoTool"}},
      {"00001 FindTool(\"Probe 2\")\r\n", kT1, FindTool{"Probe 2"}},
      {"00001 GetChangeToolAction(\"P1\")\r\n", kT1, GetChangeToolAction{"P1"}},
      {"00001 SetCoordSystem(MachineCsy)\r\n", kT1, SetCoordSystem{CoordSystem::MachineCsy}},
      {"00001 SetCoordSystem(MoveableMachineCsy)\r\n", kT1, SetCoordSystem{CoordSystem::MoveableMachineCsy}},
      {"00001 SetCoordSystem(MultipleArmCsy)\r\n", kT1, SetCoordSystem{CoordSystem::MultipleArmCsy}},
      {"00001 SetCoordSystem(PartCsy)\r\n", kT1, SetCoordSystem{CoordSystem::PartCsy}},
      {"00001 GetCoordSystem()\r\n", kT1, GetCoordSystem{}},
      {"00001 SetCsyTransformation(PartCsy, 5, 6, 7, 0, 0, 0)\r\n", kT1,
       SetCsyTransformation{CsyTarget::PartCsy, {5, 6, 7, 0, 0, 0}}},
      {"00001 SetCsyTransformation(JogDisplayCsy, -1.5, 0, -1e+06, 180, 370, -90)\r\n", kT1,
       SetCsyTransformation{CsyTarget::JogDisplayCsy, {-1.5, 0, -1e6, 180, 370, -90}}},
      {"00001 GetCsyTransformation(PartCsy)\r\n", kT1, GetCsyTransformation{CsyTarget::PartCsy}},
      {"00001 GetCsyTransformation(MoveableMachineCsy)\r\n", kT1, GetCsyTransformation{CsyTarget::MoveableMachineCsy}},
      {"00001 GetCsyTransformation(MultipleArmCsy)\r\n", kT1, GetCsyTransformation{CsyTarget::MultipleArmCsy}},
      {"00001 GetCsyTransformation(JogMoveCsy)\r\n", kT1, GetCsyTransformation{CsyTarget::JogMoveCsy}},
      {"00001 GetCsyTransformation(SensorCsy)\r\n", kT1, GetCsyTransformation{CsyTarget::SensorCsy}},
      // Scanning (test_scan.cpp has their other forms and errors)
      {"00001 OnScanReport(X(), Y(), Z(), IJK(), ER(), Q(), R(), Tool.A(), Tool.B(), Tool.C())\r\n", kT1,
       OnScanReport{{Item::X, Item::Y, Item::Z, Item::IJK, Item::ER, Item::Q, Item::R, Item::ToolA, Item::ToolB,
                     Item::ToolC}}},
      {"00001 ScanOnCircleHint(0.01, 0.001)\r\n", kT1, ScanOnCircleHint{0.01, 0.001}},
      {"00001 ScanOnLineHint(0.5, 0.01)\r\n", kT1, ScanOnLineHint{0.5, 0.01}},
      {"00001 ScanUnknownHint(100)\r\n", kT1, ScanUnknownHint{100}},
      {"00001 ScanUnknownDensity(Dis(1), Angle(10), AngleBaseLength(0.5))\r\n", kT1, ScanUnknownDensity{1, 10, 0.5}},
      {"00001 ScanOnCircle(100, 0, -3, 120, 0, -3, 0, 0, 1, 360, 180, 0.5)\r\n", kT1,
       ScanOnCircle{{100, 0, -3}, {120, 0, -3}, {0, 0, 1}, 360, 180, 0.5}},
      {"00001 ScanOnHelix(460, 350, 0, 475, 350, 10, 0, 0, 1, 720, 180, 2, -5)\r\n", kT1,
       ScanOnHelix{{460, 350, 0}, {475, 350, 10}, {0, 0, 1}, 720, 180, 2, -5}},
      {"00001 ScanOnLine(0, 1, 2, 14, 15, 2, 0, 0, 1, 0.5)\r\n", kT1, ScanOnLine{{0, 1, 2}, {14, 15, 2}, {0, 0, 1}, 0.5}},
      {"00001 ScanInPlaneEndIsSphere(100, 0, 0, 0, 0, 1, -1, 0, 0, 100, 1, 0, 0.2, 100, 100, 1.5, 1, 2, 0, 0, 1)\r\n", kT1,
       ScanInPlaneEndIsSphere{{100, 0, 0}, {0, 0, 1}, Vector3{-1, 0, 0}, {100, 1, 0}, 0.2, {100, 100, 1.5}, 1, 2, {0, 0, 1}}},
      {"00001 ScanInPlaneEndIsPlane(0, 0, 0, 0, 0, 1, 0, 1, 0, 2, 0, 0, 0.5, 9, 0, 0, -1, 0, 0, 1, 0, 0, 1)\r\n", kT1,
       ScanInPlaneEndIsPlane{{0, 0, 0}, {0, 0, 1}, Vector3{0, 1, 0}, {2, 0, 0}, 0.5, {9, 0, 0}, {-1, 0, 0}, 1, {0, 0, 1}}},
      {"00001 ScanInPlaneEndIsCyl(0, 0, 0, 0, 0, 1, 0, 0, 1, 2, 2, 0, 0, 8, 8, 0, 0, 0, 1, 0.7, 3, 0, 0, 1)\r\n", kT1,
       ScanInPlaneEndIsCyl{{0, 0, 0}, {0, 0, 1}, Vector3{0, 0, 1}, {2, 2, 0}, 0, {8, 8, 0}, {0, 0, 1}, 0.7, 3, {0, 0, 1}}},
      {"00001 ScanInCylEndIsSphere(0, 0, 0, 0, 0, 1, 2, 0, 0, 1, 0, 0, 2, 1, 0, 0.8, 0, 2, 7, 4, 1, 0, 1, 0)\r\n", kT1,
       ScanInCylEndIsSphere{{0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {1, 0, 0}, {2, 1, 0}, 0.8, {0, 2, 7}, 4, 1, {0, 1, 0}}},
      {"00001 ScanInCylEndIsPlane(0, 0, 0, 0, 0, 1, 2, 0, 0, 1, 0, 0, 2, -1, 0, 0.9, 0, 2, 7, 0, 0, 1, 1, 0, -1, 0)\r\n", kT1,
       ScanInCylEndIsPlane{{0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {1, 0, 0}, {2, -1, 0}, 0.9, {0, 2, 7}, {0, 0, 1}, 1, {0, -1, 0}}},
  };
}

Request parsed(std::string_view line) {
  auto r = parse_line(line);
  if (auto* e = std::get_if<LineError>(&r)) FAIL("parse error " << number_of(e->code) << " for: " << line);
  return std::get<Request>(r);
}
std::string_view without_crlf(const std::string& s) { return std::string_view(s).substr(0, s.size() - 2); }
}  // namespace

TEST_CASE("ippdme commands: every declared command parses and formats byte-exactly") {
  std::set<std::size_t> seen;
  for (const auto& c : cases()) {
    INFO(c.line);
    auto r = parsed(without_crlf(c.line));
    CHECK(r.tag == c.tag);
    CHECK(r.command.index() == c.command.index());
    CHECK(r.command == c.command);
    CHECK(format_command(c.tag, c.command) == c.line);
    seen.insert(c.command.index());
  }
  CHECK(seen.size() == std::variant_size_v<Command>);  // no command left untested
}

TEST_CASE("ippdme commands: the table declares every Command alternative once, E names on the fast queue") {
  std::set<std::size_t> declared;
  std::set<std::string_view> names;
  for (const auto& spec : command_table()) {
    INFO(spec.name);
    CHECK(names.insert(spec.name).second);
    CHECK(is_name(spec.name));
    CHECK((spec.queue == Queue::Fast) == (spec.name.back() == 'E'));
    CHECK((spec.shape == Shape::NotImplemented) == (spec.command == kNoCommand));
    CHECK((spec.build == nullptr) == (spec.command == kNoCommand));
    if (spec.command != kNoCommand) CHECK(declared.insert(spec.command).second);
    CHECK(find_command(spec.name) == &spec);
  }
  CHECK(declared.size() == std::variant_size_v<Command>);
  CHECK(method_name(Get{{Item::X}}) == "Get");
  CHECK(declaration_of(OnMoveReportE{}).queue == Queue::Fast);
  CHECK(find_command("home") == nullptr);  // case matters
}

TEST_CASE("ippdme commands: optional spaces, any order, numbers in every form") {
  CHECK(parsed("00001 GoTo( Y(2) , X (1.0E00) )").command == Command{GoTo{xy(1, 2)}});
  CHECK(parsed("00001 PtMeas(IJK(0,0,-1),Z(.5),X(-7.),Y(+1))").command == Command{PtMeas{xyz(-7, 1, 0.5), Vector3{0, 0, -1}}});
  Axes x_only;
  x_only.x = 1;
  CHECK(parsed("00001 PtMeas(X(1), IJK(0, 0, 5))").command == Command{PtMeas{x_only, Vector3{0, 0, 5}}});  // normalising is the server's work
  CHECK(parsed("00001 GetErrorInfo(0502)").command == Command{GetErrorInfo{502}});
  CHECK(parsed("00001 GetErrorInfo(5.02E2)").command == Command{GetErrorInfo{502}});
  CHECK(parsed("E0001 OnMoveReportE ( X ( ) , Dis(1), Time(0))").command ==
        Command{OnMoveReportE{0.0, 1.0, {Item::X}}});
  CHECK(parsed("00001 Get(Z(), X())").command == Command{Get{{Item::Z, Item::X}}});  // the order asked
  CHECK(parsed("00001 GetProp(FoundTool.Name(), XX.Vendor.Prop())").command ==
        Command{GetProp{{"FoundTool.Name", "XX.Vendor.Prop"}}});
  CHECK(parsed("99999 Home()").tag == Tag{TagKind::Command, 99999});
  CHECK(parsed("E9999 AbortE()").tag == Tag{TagKind::Event, 9999});
}
