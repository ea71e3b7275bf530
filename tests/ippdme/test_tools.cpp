// ToolBox: the tools and their properties as GetProp / SetProp / EnumProp address them
// (IPPDME.md §10): Min/Max/Act/Def, clamping with 0504, reset on a tool change, FoundTool,
// NoTool and UnDefTool, and the configured names refused.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "imess/ippdme/syntax.hpp"
#include "imess/ippdme/tools.hpp"

using namespace imess::ippdme;

namespace {
ToolSpec tool(std::string name, double radius, double speed_def) {
  ToolSpec t;
  t.name = std::move(name);
  t.radius = radius;
  for (auto& r : t.params) r = {1, 100, 10};
  t.params[static_cast<int>(Param::PtMeasSpeed)] = {0.5, 20, speed_def};
  return t;
}
std::string text(const PropertyResult& r) { return r.value ? format_value(*r.value) : "error " + std::to_string(number_of(*r.error)); }
}  // namespace

TEST_CASE("tools: GetProp reads Act (bare or .Act), Min, Max and Def of the active tool, the name as a string") {
  ToolBox box({tool("RefTool", 2, 5), tool("Star1", 1.5, 3)});
  CHECK(text(box.get("Tool.PtMeasPar.Speed")) == "Tool.PtMeasPar.Speed(5)");
  CHECK(text(box.get("Tool.PtMeasPar.Speed.Act")) == "Tool.PtMeasPar.Speed.Act(5)");
  CHECK(text(box.get("Tool.PtMeasPar.Speed.Min")) == "Tool.PtMeasPar.Speed.Min(0.5)");
  CHECK(text(box.get("Tool.PtMeasPar.Speed.Max")) == "Tool.PtMeasPar.Speed.Max(20)");
  CHECK(text(box.get("Tool.GoToPar.Accel.Def")) == "Tool.GoToPar.Accel.Def(10)");
  CHECK(text(box.get("Tool.Name")) == "Tool.Name(\"RefTool\")");
  CHECK(box.names() == std::vector<std::string>{"RefTool", "Star1", "NoTool"});
}

TEST_CASE("tools: SetProp keeps Act within Min and Max (0504 when clamped) and only Act is settable") {
  ToolBox box({tool("RefTool", 2, 5)});
  auto r = box.set("Tool.PtMeasPar.Speed", 7);
  CHECK_FALSE(r.error);
  CHECK(box.act(Param::PtMeasSpeed) == 7);
  r = box.set("Tool.PtMeasPar.Speed.Act", 50);
  CHECK(r.clamped);
  CHECK(r.error == ErrorCode::ArgumentOutOfRange);
  CHECK(box.act(Param::PtMeasSpeed) == 20);
  r = box.set("Tool.PtMeasPar.Speed", -3);
  CHECK(box.act(Param::PtMeasSpeed) == 0.5);
  // A property that exists but is read only: a bad argument (0509); a name that is no
  // property: a bad property (0510).
  CHECK(box.set("Tool.PtMeasPar.Speed.Max", 30).error == ErrorCode::BadArgument);
  CHECK(box.set("Tool.GoToPar.Accel.Def", 30).error == ErrorCode::BadArgument);
  CHECK(box.set("Tool.Name", 1).error == ErrorCode::BadArgument);
  CHECK(box.set("Tool.PtMeasPar.Speed.Top", 3).error == ErrorCode::BadProperty);
  CHECK(box.set("FoundTool.PtMeasPar.Speed", 3).error == ErrorCode::ToolNotDefined);  // nothing found yet
  CHECK(box.set("Tool.PtMeasPar.Nothing", 3).error == ErrorCode::BadProperty);
  CHECK(box.get("Tool.PtMeasPar").error == ErrorCode::BadProperty);  // a block is no value
  CHECK(box.get("Probe.Name").error == ErrorCode::BadProperty);
}

TEST_CASE("tools: lowered gives Act only when the client set it below Max (a limit to apply)") {
  ToolBox box({tool("RefTool", 2, 5)});
  CHECK(box.lowered(Param::GoToAccel) == 10);  // Def 10 lies below Max 100
  box.set("Tool.GoToPar.Accel", 100);
  CHECK(box.lowered(Param::GoToAccel) == 0);   // at Max: nothing to apply
  box.set("Tool.GoToPar.Accel", 50);
  CHECK(box.lowered(Param::GoToAccel) == 50);
  CHECK(box.lowered(Param::PtMeasAccel) == 10);
}

TEST_CASE("tools: a tool change resets Act to the new tool's Def, an unknown name leaves UnDefTool") {
  ToolBox box({tool("RefTool", 2, 5), tool("Star1", 1.5, 3)});
  box.set("Tool.PtMeasPar.Speed", 9);
  REQUIRE(box.change("Star1"));
  CHECK(box.act(Param::PtMeasSpeed) == 3);
  CHECK(box.active()->radius == 1.5);
  REQUIRE(box.change("RefTool"));
  CHECK(box.act(Param::PtMeasSpeed) == 5);
  CHECK_FALSE(box.change("Nope"));
  CHECK(box.active() == nullptr);
  CHECK(box.active_name() == "UnDefTool");
  CHECK(box.get("Tool.Name").error == ErrorCode::ToolNotDefined);
  CHECK(box.set("Tool.GoToPar.Speed", 5).error == ErrorCode::ToolNotDefined);
}

TEST_CASE("tools: FoundTool names the last tool FindTool found and reads its Def values") {
  ToolBox box({tool("RefTool", 2, 5), tool("Star1", 1.5, 3)});
  CHECK(box.get("FoundTool.Name").error == ErrorCode::ToolNotDefined);  // none found yet: UnDefTool
  REQUIRE(box.find_tool("Star1"));
  CHECK(text(box.get("FoundTool.Name")) == "FoundTool.Name(\"Star1\")");
  CHECK(text(box.get("FoundTool.PtMeasPar.Speed")) == "FoundTool.PtMeasPar.Speed(3)");
  CHECK_FALSE(box.find_tool("Nope"));
  CHECK(text(box.get("FoundTool.Name")) == "FoundTool.Name(\"Star1\")");  // unchanged
}

TEST_CASE("tools: FoundTool's values are set as Tool's are, clamped the same, a change to it starts at Def") {
  ToolBox box({tool("RefTool", 2, 5), tool("Star1", 1.5, 3)});
  REQUIRE(box.find_tool("Star1"));
  auto r = box.set("FoundTool.PtMeasPar.Speed", 4);
  CHECK_FALSE(r.error);
  CHECK(text(box.get("FoundTool.PtMeasPar.Speed")) == "FoundTool.PtMeasPar.Speed(4)");
  CHECK(text(box.get("Tool.PtMeasPar.Speed")) == "Tool.PtMeasPar.Speed(5)");  // the active tool is another
  r = box.set("FoundTool.PtMeasPar.Speed.Act", 99);
  CHECK(r.error == ErrorCode::ArgumentOutOfRange);
  CHECK(text(box.get("FoundTool.PtMeasPar.Speed")) == "FoundTool.PtMeasPar.Speed(20)");
  REQUIRE(box.find_tool("RefTool"));  // FoundTool is the active tool: the same values
  CHECK_FALSE(box.set("FoundTool.GoToPar.Speed", 42).error);
  CHECK(box.act(Param::GoToSpeed) == 42);
  REQUIRE(box.change("Star1"));
  CHECK(box.act(Param::PtMeasSpeed) == 3);  // the spec: a tool change sets Act to Def
}

TEST_CASE("tools: FindTool finds BaseTool, the machine's base tool, which is neither listed nor changed to") {
  ToolBox box({tool("RefTool", 2, 5)});
  CHECK(box.names() == std::vector<std::string>{"RefTool", "NoTool"});
  REQUIRE(box.find_tool("BaseTool"));
  CHECK(text(box.get("FoundTool.Name")) == "FoundTool.Name(\"BaseTool\")");
  CHECK(text(box.get("FoundTool.PtMeasPar.Speed.Max")) == "FoundTool.PtMeasPar.Speed.Max(20)");
  CHECK_FALSE(box.set("FoundTool.PtMeasPar.Speed", 4).error);
  CHECK(text(box.get("FoundTool.PtMeasPar.Speed")) == "FoundTool.PtMeasPar.Speed(4)");
  CHECK(box.set("FoundTool.GoToPar.Accel", 500).error == ErrorCode::ArgumentOutOfRange);
  ErrorCode err{};
  const auto all = box.enumerate("FoundTool", true, err);
  REQUIRE(all);
  CHECK(all->size() == 1 + 1 + 2 * 5 + 1 + 5 * 5 + 1 + 3 * 5);  // Name, GoToPar, PtMeasPar, ScanPar
  CHECK_FALSE(box.exists("BaseTool"));
  CHECK_FALSE(box.change("BaseTool"));  // cannot be changed to: UnDefTool, as for any unknown name
  CHECK(box.active() == nullptr);
}

TEST_CASE("tools: NoTool moves but measures nothing: its PtMeasPar is not defined (1503)") {
  ToolBox box({tool("RefTool", 2, 5)});
  REQUIRE(box.change("NoTool"));
  CHECK_FALSE(box.active()->measures);
  CHECK(box.get("Tool.PtMeasPar.Speed").error == ErrorCode::ToolNotDefined);
  CHECK(box.set("Tool.PtMeasPar.Speed", 3).error == ErrorCode::ToolNotDefined);
  ErrorCode e{};
  CHECK_FALSE(box.enumerate("Tool.PtMeasPar", false, e));
  CHECK(e == ErrorCode::ToolNotDefined);
  CHECK(text(box.get("Tool.GoToPar.Speed")) == "Tool.GoToPar.Speed(10)");
  ErrorCode err{};
  const auto entries = box.enumerate("Tool", false, err);
  REQUIRE(entries);
  CHECK(entries->size() == 2);  // Name and GoToPar
}

TEST_CASE("tools: EnumProp lists children, EnumAllProp every descendant with dotted names") {
  ToolBox box({tool("RefTool", 2, 5)});
  ErrorCode err{};
  auto block = box.enumerate("Tool.GoToPar", false, err);
  REQUIRE(block);
  CHECK(*block == std::vector<PropertyEntry>{{"Speed", "Number"}, {"Accel", "Number"}});
  auto all = box.enumerate("Tool", true, err);
  REQUIRE(all);
  CHECK(all->size() == 1 + 1 + 2 * 5 + 1 + 5 * 5 + 1 + 3 * 5);  // Name, GoToPar, PtMeasPar, ScanPar
  CHECK((*all)[3] == PropertyEntry{"GoToPar.Speed.Min", "Number"});
  CHECK_FALSE(box.enumerate("Tool.Speed", false, err));
  CHECK(err == ErrorCode::BadProperty);
}

TEST_CASE("tools: ScanPar (Speed, Accel, Retract) follows PtMeasPar's rules: Min/Max/Act/Def, 0504, Def on a change") {
  ToolSpec star = tool("Star1", 1.5, 3);
  star.params[static_cast<int>(Param::ScanSpeed)] = {0.5, 20, 4};
  star.params[static_cast<int>(Param::ScanRetract)] = {0, 10, 2};
  ToolBox box({tool("RefTool", 2, 5), star});
  CHECK(block_name(Param::ScanAccel) == "ScanPar");
  CHECK(param_name(Param::ScanRetract) == "Retract");
  CHECK(text(box.get("Tool.ScanPar.Speed")) == "Tool.ScanPar.Speed(10)");
  CHECK(text(box.get("Tool.ScanPar.Accel.Max")) == "Tool.ScanPar.Accel.Max(100)");
  CHECK_FALSE(box.set("Tool.ScanPar.Retract.Act", 4).error);
  CHECK(box.act(Param::ScanRetract) == 4);
  CHECK(box.act(Param::Retract) == 10);  // PtMeasPar's Retract is another value
  auto r = box.set("Tool.ScanPar.Speed", 1000);
  CHECK(r.clamped);
  CHECK(r.error == ErrorCode::ArgumentOutOfRange);
  CHECK(box.act(Param::ScanSpeed) == 100);
  CHECK(box.set("Tool.ScanPar.Speed.Def", 3).error == ErrorCode::BadArgument);
  CHECK(box.set("Tool.ScanPar.Density", 3).error == ErrorCode::BadProperty);  // not a 1.4.3 ScanPar value
  REQUIRE(box.change("Star1"));
  CHECK(box.act(Param::ScanSpeed) == 4);
  CHECK(text(box.get("Tool.ScanPar.Retract.Def")) == "Tool.ScanPar.Retract.Def(2)");
  REQUIRE(box.change("RefTool"));
  CHECK(box.act(Param::ScanRetract) == 10);  // back to RefTool's Def
  REQUIRE(box.find_tool("Star1"));
  CHECK_FALSE(box.set("FoundTool.ScanPar.Speed", 7).error);
  CHECK(text(box.get("FoundTool.ScanPar.Speed")) == "FoundTool.ScanPar.Speed(7)");
  ErrorCode err{};
  const auto block = box.enumerate("Tool.ScanPar", false, err);
  REQUIRE(block);
  CHECK(*block == std::vector<PropertyEntry>{{"Speed", "Number"}, {"Accel", "Number"}, {"Retract", "Number"}});
  const auto top = box.enumerate("Tool", false, err);
  REQUIRE(top);
  CHECK(top->back() == PropertyEntry{"ScanPar", "Property"});
  // NoTool scans nothing: its ScanPar is not defined, as its PtMeasPar.
  REQUIRE(box.change("NoTool"));
  CHECK(box.get("Tool.ScanPar.Speed").error == ErrorCode::ToolNotDefined);
  CHECK(box.set("Tool.ScanPar.Speed", 3).error == ErrorCode::ToolNotDefined);
  CHECK_FALSE(box.enumerate("Tool.ScanPar", false, err));
  CHECK(err == ErrorCode::ToolNotDefined);
}

TEST_CASE("tools: reserved, repeated or malformed names and ranges with Def outside Min..Max are refused") {
  CHECK_THROWS_AS(ToolBox({}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("NoTool", 1, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("UnDefTool", 1, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("BaseTool", 1, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("A", 1, 5), tool("A", 2, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("1st", 1, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(ToolBox({tool("A", 1, 50)}), std::invalid_argument);
}
