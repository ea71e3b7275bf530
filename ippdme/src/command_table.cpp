// The method declarations: one entry per method — name, argument shape, queue, usage and the
// typed command it builds. Parsing, queue checks, errors and the docs test follow from them.
#include <array>

#include "imess/ippdme/command_spec.hpp"

namespace imess::ippdme {
namespace {

template <class T>
constexpr CommandSpec plain(std::string_view name, Queue q = Queue::Normal) {
  return {name, Shape::None, q, "", command_index<T>(), [](Checked&&) -> Command { return T{}; }};
}
constexpr CommandSpec not_implemented(std::string_view name) {
  return {name, Shape::NotImplemented, Queue::Normal, "...", kNoCommand, nullptr};
}
// A scanning method: its arguments read by scan_args.cpp into the command itself.
template <class T>
constexpr CommandSpec scan(std::string_view name, std::string_view usage) {
  return {name, Shape::ScanArgs, Queue::Normal, usage, command_index<T>(),
          [](Checked&& c) -> Command { return std::move(*c.built); }};
}
constexpr Queue kFast = Queue::Fast;
constexpr Queue kNormal = Queue::Normal;

const std::array kCommands{
    // Server
    plain<StartSession>("StartSession"),
    plain<EndSession>("EndSession"),
    CommandSpec{"StopDaemon", Shape::EventTag, kNormal, "Etag", command_index<StopDaemon>(),
                [](Checked&& c) -> Command { return StopDaemon{c.tag}; }},
    plain<StopAllDaemons>("StopAllDaemons"),
    plain<AbortE>("AbortE", kFast),
    CommandSpec{"GetErrorInfo", Shape::ErrorNumber, kNormal, "n", command_index<GetErrorInfo>(),
                [](Checked&& c) -> Command { return GetErrorInfo{c.integer}; }},
    plain<ClearAllErrors>("ClearAllErrors"),
    CommandSpec{"GetProp", Shape::PropertyQueries, kNormal, "p(), ...", command_index<GetProp>(),
                [](Checked&& c) -> Command { return GetProp{std::move(c.paths)}; }},
    CommandSpec{"GetPropE", Shape::PropertyQueries, kFast, "p(), ...", command_index<GetPropE>(),
                [](Checked&& c) -> Command { return GetPropE{std::move(c.paths)}; }},
    CommandSpec{"SetProp", Shape::PropertySettings, kNormal, "p(v), ...", command_index<SetProp>(),
                [](Checked&& c) -> Command { return SetProp{std::move(c.settings)}; }},
    CommandSpec{"SetPropE", Shape::PropertySettings, kFast, "p(v), ...", command_index<SetPropE>(),
                [](Checked&& c) -> Command { return SetPropE{std::move(c.settings)}; }},
    CommandSpec{"EnumProp", Shape::PropertyPointer, kNormal, "p()", command_index<EnumProp>(),
                [](Checked&& c) -> Command { return EnumProp{std::move(c.text)}; }},
    CommandSpec{"EnumAllProp", Shape::PropertyPointer, kNormal, "p()", command_index<EnumAllProp>(),
                [](Checked&& c) -> Command { return EnumAllProp{std::move(c.text)}; }},
    plain<GetDMEVersion>("GetDMEVersion"),
    // DME
    plain<Home>("Home"),
    plain<IsHomed>("IsHomed"),
    plain<EnableUser>("EnableUser"),
    plain<DisableUser>("DisableUser"),
    plain<IsUserEnabled>("IsUserEnabled"),
    CommandSpec{"OnPtMeasReport", Shape::PtMeasReportItems, kNormal, "X(), Y(), Z(), IJK(), ER(), Q(), ...",
                command_index<OnPtMeasReport>(),
                [](Checked&& c) -> Command { return OnPtMeasReport{std::move(c.items)}; }},
    CommandSpec{"OnMoveReportE", Shape::MoveReport, kFast, "Time(s), Dis(d), X(), Y(), Z(), ...",
                command_index<OnMoveReportE>(),
                [](Checked&& c) -> Command { return OnMoveReportE{c.time, c.dis, std::move(c.items)}; }},
    plain<GetMachineClass>("GetMachineClass"),
    plain<GetErrStatusE>("GetErrStatusE", kFast),
    plain<GetXtdErrStatus>("GetXtdErrStatus"),
    CommandSpec{"Get", Shape::GetItems, kNormal, "X(), Y(), Z(), R(), Tool.A(), ...", command_index<Get>(),
                [](Checked&& c) -> Command { return Get{std::move(c.items)}; }},
    CommandSpec{"GoTo", Shape::GoToTargets, kNormal, "X(x), Y(y), Z(z), Tool.A(a), ...", command_index<GoTo>(),
                [](Checked&& c) -> Command { return GoTo{c.axes}; }},
    CommandSpec{"PtMeas", Shape::PtMeasArgs, kNormal, "X(x), Y(y), Z(z), IJK(i, j, k)", command_index<PtMeas>(),
                [](Checked&& c) -> Command { return PtMeas{c.axes, c.ijk}; }},
    plain<EnumTools>("EnumTools"),
    CommandSpec{"ChangeTool", Shape::ToolName, kNormal, "\"name\"", command_index<ChangeTool>(),
                [](Checked&& c) -> Command { return ChangeTool{std::move(c.text)}; }},
    CommandSpec{"SetTool", Shape::ToolName, kNormal, "\"name\"", command_index<SetTool>(),
                [](Checked&& c) -> Command { return SetTool{std::move(c.text)}; }},
    CommandSpec{"FindTool", Shape::ToolName, kNormal, "\"name\"", command_index<FindTool>(),
                [](Checked&& c) -> Command { return FindTool{std::move(c.text)}; }},
    CommandSpec{"GetChangeToolAction", Shape::ToolName, kNormal, "\"name\"", command_index<GetChangeToolAction>(),
                [](Checked&& c) -> Command { return GetChangeToolAction{std::move(c.text)}; }},
    // CartCMM
    CommandSpec{"SetCoordSystem", Shape::CoordSystemWord, kNormal,
                "MachineCsy / MoveableMachineCsy / MultipleArmCsy / PartCsy", command_index<SetCoordSystem>(),
                [](Checked&& c) -> Command { return SetCoordSystem{c.coord_system}; }},
    plain<GetCoordSystem>("GetCoordSystem"),
    CommandSpec{"SetCsyTransformation", Shape::CsyTransformation, kNormal, "csy, x0, y0, z0, theta, psi, phi",
                command_index<SetCsyTransformation>(),
                [](Checked&& c) -> Command { return SetCsyTransformation{c.csy, c.transform}; }},
    CommandSpec{"GetCsyTransformation", Shape::CsyWord, kNormal, "csy", command_index<GetCsyTransformation>(),
                [](Checked&& c) -> Command { return GetCsyTransformation{c.csy}; }},
    // 1.4 methods the library knows by name only (IPPDME.md §11 "may answer 0501").
    not_implemented("AlignTool"),
    not_implemented("AlignPart"),
    not_implemented("CenterPart"),
    not_implemented("TiltPart"),
    not_implemented("TiltCenterPart"),
    not_implemented("LockAxis"),
    not_implemented("ReQualify"),
    // Scanning (1.4.3 §11, ScanOnHelix from 1.5; docs/ippdme.md "Scanning"): the unknown-contour
    // scans also in their 1.4.0 form (no plane normal, no n), which the NIST suite sends.
    CommandSpec{"OnScanReport", Shape::PtMeasReportItems, kNormal, "X(), Y(), Z(), IJK(), ER(), Q(), ...",
                command_index<OnScanReport>(),
                [](Checked&& c) -> Command { return OnScanReport{std::move(c.items)}; }},
    scan<ScanOnCircleHint>("ScanOnCircleHint", "Displacement, Form"),
    scan<ScanOnCircle>("ScanOnCircle", "Cx, Cy, Cz, Sx, Sy, Sz, i, j, k, delta, sfa, StepW"),
    scan<ScanOnHelix>("ScanOnHelix", "Cx, Cy, Cz, Sx, Sy, Sz, i, j, k, delta, sfa, StepW, pitch"),
    scan<ScanOnLineHint>("ScanOnLineHint", "Angle, Form"),
    scan<ScanOnLine>("ScanOnLine", "Sx, Sy, Sz, Ex, Ey, Ez, i, j, k, StepW"),
    not_implemented("ScanOnCurveHint"),
    not_implemented("ScanOnCurveDensity"),
    not_implemented("ScanOnCurve"),
    scan<ScanUnknownHint>("ScanUnknownHint", "MinRadiusOfCurvature"),
    scan<ScanUnknownDensity>("ScanUnknownDensity", "Dis(d), Angle(a), AngleBaseLength(l)"),
    scan<ScanInPlaneEndIsSphere>("ScanInPlaneEndIsSphere", "Sx, Sy, Sz, Si, Sj, Sk, Ni, Nj, Nk, Dx, Dy, Dz, StepW, Ex, Ey, Ez, Dia, n, Ei, Ej, Ek"),
    scan<ScanInPlaneEndIsPlane>("ScanInPlaneEndIsPlane", "Sx, Sy, Sz, Si, Sj, Sk, Ni, Nj, Nk, Dx, Dy, Dz, StepW, Px, Py, Pz, Pi, Pj, Pk, n, Ei, Ej, Ek"),
    scan<ScanInPlaneEndIsCyl>("ScanInPlaneEndIsCyl", "Sx, Sy, Sz, Si, Sj, Sk, Ni, Nj, Nk, Dx, Dy, Dz, StepW, Cx, Cy, Cz, Ci, Cj, Ck, d, n, Ei, Ej, Ek"),
    scan<ScanInCylEndIsSphere>("ScanInCylEndIsSphere", "Cx, Cy, Cz, Ci, Cj, Ck, Sx, Sy, Sz, Si, Sj, Sk, Dx, Dy, Dz, StepW, Ex, Ey, Ez, Dia, n, Ei, Ej, Ek"),
    scan<ScanInCylEndIsPlane>("ScanInCylEndIsPlane", "Cx, Cy, Cz, Ci, Cj, Ck, Sx, Sy, Sz, Si, Sj, Sk, Dx, Dy, Dz, StepW, Px, Py, Pz, Pi, Pj, Pk, n, Ei, Ej, Ek"),
};

}  // namespace

std::span<const CommandSpec> command_table() { return kCommands; }

const CommandSpec* find_command(std::string_view name) {
  for (const auto& spec : kCommands)
    if (spec.name == name) return &spec;
  return nullptr;
}

const CommandSpec& declaration_of(const Command& cmd) {
  for (const auto& spec : kCommands)
    if (spec.command == cmd.index()) return spec;
  return kCommands.front();  // unreachable: test_ippdme checks every alternative is declared
}

std::string_view method_name(const Command& cmd) { return declaration_of(cmd).name; }

}  // namespace imess::ippdme
