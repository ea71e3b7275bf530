// Tools and their properties (IPPDME.md §10): the tools a server offers, the active one
// (`Tool`), the last found (`FoundTool`), and the GoToPar / PtMeasPar / ScanPar blocks whose
// values each have Min, Max, Act and Def. Pure: the server feeds the machine's limits in.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/syntax.hpp"

namespace imess::ippdme {

// One settable value: Act starts at Def and is kept within [Min, Max].
struct Range {
  double min = 0, max = 0, def = 0;
};

// The values of the three blocks, in the order EnumProp lists them: GoToPar (Speed, Accel),
// PtMeasPar (Speed, Accel, Approach, Search, Retract), ScanPar (Speed, Accel, Retract: 1.4.3
// §6.3.15).
enum class Param : unsigned char {
  GoToSpeed, GoToAccel,
  PtMeasSpeed, PtMeasAccel, Approach, Search, Retract,
  ScanSpeed, ScanAccel, ScanRetract,
};
inline constexpr int kParamCount = 10;

struct ToolSpec {
  std::string name;     // as EnumTools lists it
  double radius = 0;    // mm, the ball's radius (ER, and the hit's compensation)
  Range params[kParamCount]{};
  bool measures = true;  // false: NoTool (moves, but PtMeas, scans, PtMeasPar and ScanPar are refused)
};

// Reserved names (IPPDME.md §10): NoTool is always offered; UnDefTool is the state after a
// failed change (and FoundTool before any FindTool); BaseTool, the machine's base tool (the
// probe head without a stylus: the machine's ranges, radius 0), is never offered or changed
// to, but FindTool finds it, and FoundTool then reads and sets its values.
inline constexpr std::string_view kNoTool = "NoTool";
inline constexpr std::string_view kUnDefTool = "UnDefTool";
inline constexpr std::string_view kBaseTool = "BaseTool";

// The answer of a property read or write: a value (GetProp's item), or an error number;
// `clamped`: SetProp stored Min or Max instead (warning 0504).
struct PropertyResult {
  std::optional<Value> value;
  std::optional<ErrorCode> error;
  bool clamped = false;
};

// EnumProp's lines: a child's name and "Number", "String" or "Property".
using PropertyEntry = std::pair<std::string, std::string>;

class ToolBox {
 public:
  // `tools`: the configured tools (NoTool and the hidden BaseTool are added after them, with
  // the first tool's ranges).
  // The first tool is active at start; throws std::invalid_argument for an empty list, a
  // reserved or repeated name, or a range with min > max or def outside it.
  explicit ToolBox(std::vector<ToolSpec> tools);

  // EnumTools: every tool a client may change to, in order (not BaseTool).
  std::vector<std::string> names() const;
  bool exists(std::string_view name) const { return find(name) >= 0; }  // BaseTool: false
  // ChangeTool / SetTool: the named tool becomes active, its Act values reset to Def; false
  // for an unknown name (the active tool becomes UnDefTool, as the spec says).
  bool change(std::string_view name);
  // FindTool: FoundTool names it (BaseTool too); false (FoundTool stays as it was) for an
  // unknown name.
  bool find_tool(std::string_view name);

  // The active tool; null while UnDefTool (after a failed change).
  const ToolSpec* active() const { return active_ < 0 ? nullptr : &tools_[active_]; }
  std::string_view active_name() const { return active_ < 0 ? kUnDefTool : std::string_view(tools_[active_].name); }
  // The active tool's Act value (while UnDefTool: the last active tool's, as GoTo moves on).
  double act(Param p) const { return acts_[active_ < 0 ? last_active_ : active_][static_cast<int>(p)]; }
  // Act when the client set it below Max (a limit to apply, e.g. an acceleration), else 0.
  double lowered(Param p) const;

  // GetProp item `path` ("Tool.PtMeasPar.Speed", "Tool.GoToPar.Speed.Max", "Tool.Name",
  // "FoundTool.Name"); the value is a call named by the path as asked.
  PropertyResult get(std::string_view path) const;
  // SetProp of `path`: Act of the active tool's (Tool) or the found tool's (FoundTool) values;
  // outside Min..Max clamped (0504); a property that is read only (Min, Max, Def, Name) 0509.
  PropertyResult set(std::string_view path, double value);
  // EnumProp (children) / EnumAllProp (every descendant, dotted) of a pointer or block.
  std::optional<std::vector<PropertyEntry>> enumerate(std::string_view path, bool recursive, ErrorCode& error) const;

 private:
  int find(std::string_view name) const;  // a tool one may change to (not BaseTool)
  int base() const { return static_cast<int>(tools_.size()) - 1; }
  std::vector<ToolSpec> tools_;  // the configured tools, NoTool, BaseTool (last)
  std::vector<std::array<double, kParamCount>> acts_;  // each tool's Act values
  int active_ = 0;     // index into tools_, -1: UnDefTool
  int last_active_ = 0;
  int found_ = -1;     // FoundTool, -1: UnDefTool
};

// The block and value name of a parameter ("PtMeasPar", "Speed"; "ScanPar", "Retract").
std::string_view block_name(Param p);
std::string_view param_name(Param p);

}  // namespace imess::ippdme
