// The vocabulary of a command declaration: the argument shapes, the queue a method belongs
// to, the values a shape reads, and CommandSpec. The declarations are in command_table.cpp,
// the shape readers in parser.cpp: adding a method is one table entry (plus its struct).
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "imess/ippdme/commands.hpp"

namespace imess::ippdme {

// Which queue carries a method (IPPDME.md §2): the fast queue's methods end in E and travel
// with event tags; all others with command tags. A mismatch is IllegalTag (NIST).
enum class Queue : unsigned char { Normal, Fast };

// The argument form of a method; each shape names the errors it answers (docs/ippdme.md).
enum class Shape : unsigned char {
  None,               // Name()
  ErrorNumber,        // GetErrorInfo(502): a whole number 0..9999
  EventTag,           // StopDaemon(E0005)
  GetItems,           // Get(X(), Y(), Z(), R(), Tool.A(), ...)
  PtMeasReportItems,  // OnPtMeasReport / OnScanReport(X(), Y(), Z(), IJK(), ER(), Q(), ...)
  MoveReport,         // OnMoveReportE(Time(0.5), Dis(1), X(), Y(), Z(), ...)
  GoToTargets,        // GoTo(X(1), Y(2), Z(3), Tool.A(90), ...)
  PtMeasArgs,         // PtMeas(X(1), Y(2), Z(3), IJK(0, 0, 1))
  PropertyQueries,    // GetProp(Tool.PtMeasPar.Speed(), Tool.Name(), ...)
  PropertySettings,   // SetProp(Tool.PtMeasPar.Speed(100), ...)
  PropertyPointer,    // EnumProp(Tool.PtMeasPar())
  ToolName,           // ChangeTool("RefTool")
  CoordSystemWord,    // SetCoordSystem(PartCsy)
  CsyTransformation,  // SetCsyTransformation(PartCsy, x0, y0, z0, theta, psi, phi)
  CsyWord,            // GetCsyTransformation(PartCsy)
  ScanArgs,           // the scanning methods: ScanOnCircle(100, 0, -3, 120, 0, -3, 0, 0, 1, 360, 180, 0.5) ...
  NotImplemented,     // a 1.4 method this library knows by name only: UnsupportedCommand
};

// What a shape read from the arguments; `build` takes what its shape fills.
struct Checked {
  int integer = 0;
  Tag tag;
  std::vector<Item> items;
  std::optional<double> time, dis;
  Axes axes;
  std::optional<Vector3> ijk;
  std::vector<std::string> paths;
  std::vector<PropertySetting> settings;
  std::string text;
  CoordSystem coord_system = CoordSystem::MachineCsy;
  CsyTarget csy = CsyTarget::PartCsy;
  CsyTransformation transform;
  std::optional<Command> built;  // ScanArgs: the command itself
};

inline constexpr std::size_t kNoCommand = static_cast<std::size_t>(-1);

struct CommandSpec {
  std::string_view name;     // exact, case-sensitive
  Shape shape;
  Queue queue;
  std::string_view usage;    // the argument list as documented: "X(), Y(), Z(), ..."
  std::size_t command;       // index in Command, kNoCommand for NotImplemented
  Command (*build)(Checked&&);  // null for NotImplemented
};

std::span<const CommandSpec> command_table();
const CommandSpec* find_command(std::string_view name);
// The declaration a command was built from (every Command alternative has one).
const CommandSpec& declaration_of(const Command& cmd);
std::string_view method_name(const Command& cmd);

template <class T, class V = Command, std::size_t I = 0>
constexpr std::size_t command_index() {
  static_assert(I < std::variant_size_v<V>, "not a Command alternative");
  if constexpr (std::is_same_v<T, std::variant_alternative_t<I, V>>) return I;
  else return command_index<T, V, I + 1>();
}

}  // namespace imess::ippdme
