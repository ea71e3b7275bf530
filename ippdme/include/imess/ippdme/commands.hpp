// Typed I++ DME commands: one struct per method the library reads (IPPDME.md §7 and the §11
// "must" list; the scanning methods in scan_commands.hpp). Their declarations (name, argument
// shape, queue) are in command_table.cpp.
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "imess/ippdme/scan_commands.hpp"
#include "imess/ippdme/tag.hpp"

namespace imess::ippdme {

// Targets of GoTo (X, Y, Z, Tool.A/B/C) and nominals of PtMeas (X, Y, Z); absent = stay put.
struct Axes {
  std::optional<double> x, y, z, tool_a, tool_b, tool_c;
  friend bool operator==(const Axes&, const Axes&) = default;
};

// SetProp's `Tool.PtMeasPar.Speed(100)`: the dotted path and the value.
struct PropertySetting {
  std::string path;
  double value = 0;
  friend bool operator==(const PropertySetting&, const PropertySetting&) = default;
};

enum class CoordSystem : unsigned char { MachineCsy, MoveableMachineCsy, MultipleArmCsy, PartCsy };
// The systems Set/GetCsyTransformation address.
enum class CsyTarget : unsigned char { PartCsy, MoveableMachineCsy, MultipleArmCsy, JogDisplayCsy, JogMoveCsy, SensorCsy };

#define IMESS_IPPDME_EQ(T) friend bool operator==(const T&, const T&) = default
// Server
struct StartSession { IMESS_IPPDME_EQ(StartSession); };
struct EndSession { IMESS_IPPDME_EQ(EndSession); };
struct StopDaemon { Tag daemon; IMESS_IPPDME_EQ(StopDaemon); };                     // E0001..E9999
struct StopAllDaemons { IMESS_IPPDME_EQ(StopAllDaemons); };
struct AbortE { IMESS_IPPDME_EQ(AbortE); };
struct GetErrorInfo { int number = 0; IMESS_IPPDME_EQ(GetErrorInfo); };             // 0..9999
struct ClearAllErrors { IMESS_IPPDME_EQ(ClearAllErrors); };
struct GetProp { std::vector<std::string> paths; IMESS_IPPDME_EQ(GetProp); };       // "Tool.PtMeasPar.Speed"
struct GetPropE { std::vector<std::string> paths; IMESS_IPPDME_EQ(GetPropE); };
struct SetProp { std::vector<PropertySetting> settings; IMESS_IPPDME_EQ(SetProp); };
struct SetPropE { std::vector<PropertySetting> settings; IMESS_IPPDME_EQ(SetPropE); };
struct EnumProp { std::string path; IMESS_IPPDME_EQ(EnumProp); };                   // "Tool.PtMeasPar"
struct EnumAllProp { std::string path; IMESS_IPPDME_EQ(EnumAllProp); };
struct GetDMEVersion { IMESS_IPPDME_EQ(GetDMEVersion); };
// DME
struct Home { IMESS_IPPDME_EQ(Home); };
struct IsHomed { IMESS_IPPDME_EQ(IsHomed); };
struct EnableUser { IMESS_IPPDME_EQ(EnableUser); };
struct DisableUser { IMESS_IPPDME_EQ(DisableUser); };
struct IsUserEnabled { IMESS_IPPDME_EQ(IsUserEnabled); };
struct OnPtMeasReport { std::vector<Item> items; IMESS_IPPDME_EQ(OnPtMeasReport); };  // not empty
struct OnMoveReportE {
  std::optional<double> time, dis;  // s and mm; Time/Dis are conditions, never reported
  std::vector<Item> items;          // what each report line holds, in this order
  IMESS_IPPDME_EQ(OnMoveReportE);
};
struct GetMachineClass { IMESS_IPPDME_EQ(GetMachineClass); };
struct GetErrStatusE { IMESS_IPPDME_EQ(GetErrStatusE); };
struct GetXtdErrStatus { IMESS_IPPDME_EQ(GetXtdErrStatus); };
struct Get { std::vector<Item> items; IMESS_IPPDME_EQ(Get); };                       // not empty
struct GoTo { Axes target; IMESS_IPPDME_EQ(GoTo); };                                // at least one
struct PtMeas { Axes nominal; std::optional<Vector3> ijk; IMESS_IPPDME_EQ(PtMeas); };  // X/Y/Z; IJK normless refused
struct EnumTools { IMESS_IPPDME_EQ(EnumTools); };
struct ChangeTool { std::string name; IMESS_IPPDME_EQ(ChangeTool); };
struct SetTool { std::string name; IMESS_IPPDME_EQ(SetTool); };
struct FindTool { std::string name; IMESS_IPPDME_EQ(FindTool); };
struct GetChangeToolAction { std::string name; IMESS_IPPDME_EQ(GetChangeToolAction); };
// CartCMM
struct SetCoordSystem { CoordSystem csy = CoordSystem::MachineCsy; IMESS_IPPDME_EQ(SetCoordSystem); };
struct GetCoordSystem { IMESS_IPPDME_EQ(GetCoordSystem); };
// A coordinate system's offsets stay within ±kMaxCsyOffset mm (MESSD's SetFrame bounds a
// frame's origin the same): beyond it a typo, and the chain's products would overflow.
inline constexpr double kMaxCsyOffset = 1e6;
struct CsyTransformation {
  double x0 = 0, y0 = 0, z0 = 0;        // mm, each within ±kMaxCsyOffset
  double theta = 0, psi = 0, phi = 0;   // degrees; theta 0..180
  friend bool operator==(const CsyTransformation&, const CsyTransformation&) = default;
};
struct SetCsyTransformation { CsyTarget csy = CsyTarget::PartCsy; CsyTransformation transform; IMESS_IPPDME_EQ(SetCsyTransformation); };
struct GetCsyTransformation { CsyTarget csy = CsyTarget::PartCsy; IMESS_IPPDME_EQ(GetCsyTransformation); };
#undef IMESS_IPPDME_EQ

using Command =
    std::variant<StartSession, EndSession, StopDaemon, StopAllDaemons, AbortE, GetErrorInfo, ClearAllErrors,
                 GetProp, GetPropE, SetProp, SetPropE, EnumProp, EnumAllProp, GetDMEVersion, Home, IsHomed,
                 EnableUser, DisableUser, IsUserEnabled, OnPtMeasReport, OnMoveReportE, GetMachineClass,
                 GetErrStatusE, GetXtdErrStatus, Get, GoTo, PtMeas, EnumTools, ChangeTool, SetTool, FindTool,
                 GetChangeToolAction, SetCoordSystem, GetCoordSystem, SetCsyTransformation, GetCsyTransformation,
                 // Scanning (scan_commands.hpp)
                 OnScanReport, ScanOnCircleHint, ScanOnLineHint, ScanUnknownHint, ScanUnknownDensity, ScanOnCircle,
                 ScanOnHelix, ScanOnLine, ScanInPlaneEndIsSphere, ScanInPlaneEndIsPlane, ScanInPlaneEndIsCyl,
                 ScanInCylEndIsSphere, ScanInCylEndIsPlane>;

// Wire names of the enums ("Tool.A", "PartCsy").
std::string_view item_name(Item item);
std::string_view coord_system_name(CoordSystem c);
std::string_view csy_target_name(CsyTarget c);

}  // namespace imess::ippdme
