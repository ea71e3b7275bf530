// The verb declarations: one entry per verb — name, argument grammar with ranges, help, and
// the typed command it builds. Parsing, argument errors, Help, usage and the docs test follow.
#include <array>
#include <limits>

#include "imess/protocol/verbs.hpp"

namespace imess::protocol {
namespace {

// Axis speeds of a jog: percent of MaxSpeed.
constexpr ArgSpec percent(std::string_view name) {
  return number(name, -100, 100, "StartMv speeds are percent of MaxSpeed, {min} to {max}");
}
constexpr double kAny = std::numeric_limits<double>::infinity();
// A component of the probe offset (the ProbeOffX/Y/Z parameters' range).
constexpr ArgSpec offset(std::string_view name) {
  return number(name, -100, 100, "Qualify takes probe offsets from {min} to {max} mm, got '{got}'");
}
constexpr ArgSpec coordinate(std::string_view name) { return number(name, -kAny, kAny, ""); }
Xyz xyz(const Args& a) { return {a.number(0), a.number(1), a.number(2)}; }
std::optional<double> optional_number(const Args& a, std::size_t i) {
  return a.has(i) ? std::optional<double>(a.number(i)) : std::nullopt;
}

// A queued move's id: the client's number, echoed in Done / Failed.
constexpr ArgSpec move_id() {
  return whole(number("id", 0, 4294967295.0, "a move id is a whole number from {min} to {max}, got '{got}'"));
}
// SetFrame's O, X and Z vectors, each three AxisWords of its letter in order.
Command set_frame(const Args& a) {
  SetFrame f{std::string(a.at[0].text), {}, {}, {}};
  int count[3] = {0, 0, 0};
  for (const auto& w : a.axis_words) {
    const int v = w.letter == 'O' ? 0 : w.letter == 'X' ? 1 : 2;
    auto& slot = v == 0 ? f.origin : v == 1 ? f.x_axis : f.z_axis;
    if (!slot) slot = Vector3{};
    (*slot)[static_cast<std::size_t>(count[v]++)] = w.value;
  }
  return f;
}
std::uint32_t id_of(const Args& a) { return static_cast<std::uint32_t>(a.number(0)); }
PathWords path_words(const Args& a) {
  PathWords w;
  int normal_words = 0;
  for (const auto& x : a.axis_words) {
    if (auto* word = w.axis(x.letter)) {
      *word = x.value;
      continue;
    }
    switch (x.letter) {
      case 'I': w.i = x.value; break;
      case 'J': w.j = x.value; break;
      case 'K': w.k = x.value; break;
      case 'F': w.f = x.value; break;
      case 'P': w.p = x.value; break;
      case 'N':  // three words in order: i j k
        if (!w.n) w.n = std::array<double, 3>{};
        (*w.n)[normal_words++] = x.value;
        break;
      default: break;
    }
  }
  return w;
}

const std::array kVerbs{
    VerbSpec{"StartMv", args(percent("vx"), percent("vy"), percent("vz")),
             "jog: per-axis speed in % of MaxSpeed (x SpeedLevel), sign = direction", true, Access::Moving,
             command_index<StartMv>(), [](const Args& a) -> Command { return StartMv{xyz(a)}; }},
    VerbSpec{"StopMv", args(), "stop any motion (jog, GoTo, Home)", true, Access::Stop,
             command_index<StopMv>(), [](const Args&) -> Command { return StopMv{}; }},
    VerbSpec{"ForcePt", args(), "measure here: broadcast the current position as MeasPt, no radius correction", true, Access::Moving,
             command_index<ForcePt>(), [](const Args&) -> Command { return ForcePt{}; }},
    VerbSpec{"Hello", args(optional(word("name"))), "protocol version and capabilities; names this client in the log", false, Access::Open,
             command_index<Hello>(), [](const Args& a) -> Command { return Hello{std::string(a.at[0].text)}; }},
    VerbSpec{"Help", args(), "list every command with its usage", false, Access::Open,
             command_index<Help>(), [](const Args&) -> Command { return Help{}; }},
    VerbSpec{"Status", args(), "state, position, loops, tip, limits, homed, tip radius, speed level", false, Access::Open,
             command_index<Status>(), [](const Args&) -> Command { return Status{}; }},
    VerbSpec{"GoTo",
             args(coordinate("x"), coordinate("y"), coordinate("z"),
                  optional(above_min(number("speed", 0, kAny, "GoTo speed must be greater than {min} mm/s")))),
             "straight move to an absolute position (mm), speed in mm/s", false, Access::Moving,
             command_index<GoTo>(), [](const Args& a) -> Command { return GoTo{xyz(a), optional_number(a, 3)}; }},
    VerbSpec{"Home", args(), "reference search on all axes; zero at the encoder index", false, Access::Moving,
             command_index<Home>(), [](const Args&) -> Command { return Home{}; }},
    VerbSpec{"Free", args(), "open the position loops now so the machine can be moved by hand", false, Access::Moving,
             command_index<Free>(), [](const Args&) -> Command { return Free{}; }},
    VerbSpec{"Reset", args(), "clear a fault after its cause was removed", false, Access::Moving,
             command_index<Reset>(), [](const Args&) -> Command { return Reset{}; }},
    VerbSpec{"Set", args(word("name"), word("value")), "set a runtime parameter (Get lists them)", false, Access::Controlling,
             command_index<Set>(),
             [](const Args& a) -> Command { return Set{std::string(a.at[0].text), std::string(a.at[1].text)}; }},
    VerbSpec{"Get", args(optional(word("name"))), "read one runtime parameter, or all of them", false, Access::Open,
             command_index<Get>(), [](const Args& a) -> Command { return Get{std::string(a.at[0].text)}; }},
    VerbSpec{"Stats",
             args(optional(choice("form", "Reset Interval Hist",
                                  "Stats takes nothing, Reset, Interval or Hist, got '{got}'; usage: {usage}"))),
             "motion-loop period, wake-up latency percentiles, overruns, cycles since the start; form Reset starts a "
             "measuring interval, Interval (figures) and Hist (1 us buckets) report it", false, Access::Open,
             command_index<Stats>(),
             [](const Args& a) -> Command {
               return Stats{a.has(0) ? static_cast<Stats::Form>(a.at[0].choice + 1) : Stats::Form::SinceStart};
             }},
    VerbSpec{"HandMv",
             args(coordinate("dx"), coordinate("dy"), coordinate("dz"),
                  optional(above_min(number("speed", 0, kAny, "HandMv speed must be greater than {min} mm/s")))),
             "simulator only: push the carriage by hand (loops open), mm and mm/s", false, Access::Moving,
             command_index<HandMv>(), [](const Args& a) -> Command { return HandMv{xyz(a), optional_number(a, 3)}; }},
    VerbSpec{"Quit", args(), "close this connection", false, Access::Open,
             command_index<Quit>(), [](const Args&) -> Command { return Quit{}; }},
    VerbSpec{"Replay",
             args(sequence("from-seq", "Replay takes a hit sequence number, a whole number from 0 to {max}, got '{got}'")),
             "re-send the journaled hits from this sequence number (Hit lines), at most 1000", false, Access::Open,
             command_index<Replay>(), [](const Args& a) -> Command { return Replay{a.at[0].sequence}; }},
    VerbSpec{"Take", args(optional(choice("force", "force", "Take takes nothing or the word 'force', got '{got}'; usage: {usage}"))),
             "take control of the machine; force (configured hosts only) stops it and takes over", false, Access::Own,
             command_index<Take>(), [](const Args& a) -> Command { return Take{a.has(0)}; }},
    VerbSpec{"Release", args(), "stop the machine and give up control", false, Access::Own,
             command_index<Release>(), [](const Args&) -> Command { return Release{}; }},
    VerbSpec{"Watch",
             args(or_zero(whole(number("ms", kWatchMinMs, kWatchMaxMs,
                                       "Watch takes whole milliseconds from {min} to {max}, or 0 to switch it off")))),
             "dead-man: stop the machine when this controlling client is silent for ms (50-60000; 0 = off)", false, Access::Open,
             command_index<Watch>(), [](const Args& a) -> Command { return Watch{static_cast<int>(a.number(0))}; }},
    VerbSpec{"Stream",
             args(or_zero(number("hz", kStreamMinHz, kStreamMaxHz,
                                 "Stream takes a rate in Hz from {min} up to the motion loop's rate, or 0 for ReportHz, got '{got}'"))),
             "this client's CurrCor rate in Hz, up to the motion loop's; 0 = the shared ReportHz", false, Access::Open,
             command_index<Stream>(), [](const Args& a) -> Command { return Stream{a.number(0)}; }},
    VerbSpec{"Version", args(), "the daemon's version", false, Access::Open,
             command_index<Version>(), [](const Args&) -> Command { return Version{}; }},
    VerbSpec{"MoveTo",
             args(move_id(), axis_words("X.. Y.. Z.. F..", "XYZABCUVWF",
                                        "MoveTo takes words X Y Z A B C U V W (the machine's axes: mm, rotary in degrees) and F (mm/s), each at most once, got '{got}'; usage: {usage}")),
             "queue a straight move; axes not named keep their planned position; F mm/s (default GoToSpeed)", false,
             Access::Moving, command_index<MoveTo>(),
             [](const Args& a) -> Command { return MoveTo{id_of(a), path_words(a)}; }},
    VerbSpec{"ArcTo",
             args(move_id(),
                  choice("dir", "CW CCW", "ArcTo turns CW or CCW (seen from the tip of the plane's normal), got '{got}'; usage: {usage}"),
                  with_vectors(axis_words("X.. Y.. Z.. I.. J.. K.. N i j k P.. F..", "XYZIJKNPF",
                                          "ArcTo takes words X Y Z (end), I J K (centre offset from the start), "
                                          "N i j k (plane normal), P (turns), F, each once, got '{got}'; usage: {usage}"),
                               "N")),
             "queue an arc: end XYZ, centre start+IJK; plane XY (I J), ZX (I K), YZ (J K) with helix, or normal N; P turns", false,
             Access::Moving, command_index<ArcTo>(),
             [](const Args& a) -> Command { return ArcTo{id_of(a), a.at[1].choice == 1, path_words(a)}; }},
    VerbSpec{"Dwell",
             args(move_id(), number("seconds", 0, kMaxDwellSeconds, "Dwell takes seconds from {min} to {max}, got '{got}'")),
             "queue a pause of the given seconds (the path stops there)", false, Access::Moving,
             command_index<Dwell>(), [](const Args& a) -> Command { return Dwell{id_of(a), a.number(1)}; }},
    VerbSpec{"Probe",
             args(move_id(), axis_words("X.. Y.. Z.. F..", "XYZF",
                                        "Probe takes words X Y Z (target, mm) and F (approach mm/s), each at most once, got '{got}'; usage: {usage}")),
             "queue a probing cycle: toward the target (F, then ProbeSpeed from PrehitDist before it), on to SearchDist "
             "beyond; at the edge Hit, retract RetractDist from the hit, Done (no edge: Failed PartNotFound)",
             false, Access::Moving, command_index<Probe>(),
             [](const Args& a) -> Command { return Probe{id_of(a), path_words(a)}; }},
    VerbSpec{"ScanLine",
             args(move_id(), coordinate("x1"), coordinate("y1"), coordinate("z1"), coordinate("x2"), coordinate("y2"),
                  coordinate("z2"), coordinate("i"), coordinate("j"), coordinate("k"),
                  optional(above_min(number("speed", 0, kAny, "ScanLine speed must be greater than {min} mm/s")))),
             "queue a scan along a line on a surface: start and end surface points, the surface's outward normal i j k, "
             "mm/s (default ScanSpeed); Scan points, Done (lost contact: Failed ScanLostContact)",
             false, Access::Moving, command_index<ScanLine>(),
             [](const Args& a) -> Command {
               return ScanLine{id_of(a), {a.number(1), a.number(2), a.number(3)}, {a.number(4), a.number(5), a.number(6)},
                               {a.number(7), a.number(8), a.number(9)}, optional_number(a, 10)};
             }},
    VerbSpec{"ScanCirc",
             args(move_id(), coordinate("cx"), coordinate("cy"), coordinate("cz"), coordinate("x"), coordinate("y"),
                  coordinate("z"), coordinate("i"), coordinate("j"), coordinate("k"),
                  number("sweep", -kMaxScanSweep, kMaxScanSweep, "ScanCirc sweeps from {min} to {max} degrees, got '{got}'"),
                  choice("surface", "bore boss", "ScanCirc scans a bore or a boss, got '{got}'; usage: {usage}"),
                  optional(above_min(number("speed", 0, kAny, "ScanCirc speed must be greater than {min} mm/s")))),
             "queue a scan round an axis: centre, start surface point, axis i j k, sweep degrees (right hand), bore or "
             "boss, mm/s (default ScanSpeed); Scan points, Done",
             false, Access::Moving, command_index<ScanCircle>(),
             [](const Args& a) -> Command {
               return ScanCircle{id_of(a),      {a.number(1), a.number(2), a.number(3)}, {a.number(4), a.number(5), a.number(6)},
                                 {a.number(7), a.number(8), a.number(9)}, a.number(10), a.at[11].choice == 0,
                                 optional_number(a, 12)};
             }},
    VerbSpec{"SetOut",
             args(move_id(), word("output"), choice("state", "off on", "SetOut switches an output on or off, got '{got}'; usage: {usage}")),
             "queue an output switch (Outputs lists them): the path stops, switches, holds the output's settle time, Done",
             false, Access::Moving, command_index<SetOut>(),
             [](const Args& a) -> Command { return SetOut{id_of(a), std::string(a.at[1].text), a.at[2].choice == 1}; }},
    VerbSpec{"Outputs", args(), "the machine's outputs and their states (name on|off ...), and whether the probe is armed",
             false, Access::Open, command_index<Outputs>(), [](const Args&) -> Command { return Outputs{}; }},
    VerbSpec{"Queue", args(), "queued moves: how many are pending, the running id, held or not", false, Access::Open,
             command_index<Queue>(), [](const Args&) -> Command { return Queue{}; }},
    VerbSpec{"Pause", args(), "feed hold: queued moves brake to rest on their path", false, Access::Controlling,
             command_index<Pause>(), [](const Args&) -> Command { return Pause{}; }},
    VerbSpec{"Resume", args(), "end a feed hold: queued moves go on", false, Access::Controlling,
             command_index<Resume>(), [](const Args&) -> Command { return Resume{}; }},
    VerbSpec{"JogAx",
             args(axis_words("X.. Y.. C..", "XYZABCUVW",
                             "JogAx takes words of an axis letter X Y Z A B C U V W and a speed in % of MaxSpeed, such as C20 or U-10, each axis at most once, got '{got}'; usage: {usage}")),
             "jog named axes: % of MaxSpeed (x SpeedLevel), mm/s or deg/s; axes not named stand", false,
             Access::Moving, command_index<JogAx>(), [](const Args& a) -> Command { return JogAx{path_words(a)}; }},
    VerbSpec{"Programs", args(), "the programs in the controller's programs folder (.nc .ngc .gcode .tap .plt .hpgl .mrm)",
             false, Access::Open, command_index<Programs>(), [](const Args&) -> Command { return Programs{}; }},
    VerbSpec{"Load", args(word("name")), "load a program from the programs folder and check it all against this machine",
             false, Access::Controlling, command_index<Load>(),
             [](const Args& a) -> Command { return Load{std::string(a.at[0].text)}; }},
    VerbSpec{"Upload", args(word("name")),
             "send a program: its lines follow, then a line '.'; checked like Load (the name's extension gives the language)",
             false, Access::Controlling, command_index<Upload>(),
             [](const Args& a) -> Command { return Upload{std::string(a.at[0].text)}; }},
    VerbSpec{"Run",
             args(optional(choice("detached", "detached",
                                  "Run takes nothing or the word 'detached', got '{got}'; usage: {usage}"))),
             "run the loaded program (Block and ProgEnd events); detached: it goes on if this client disconnects", false,
             Access::Controlling, command_index<Run>(), [](const Args& a) -> Command { return Run{a.has(0)}; }},
    VerbSpec{"Abort", args(), "stop the running program: brake, empty the queue, ProgEnd aborted", false, Access::Stop,
             command_index<Abort>(), [](const Args&) -> Command { return Abort{}; }},
    VerbSpec{"Program", args(), "the loaded program: name, state (none loaded running paused ended), line, block",
             false, Access::Open, command_index<Program>(), [](const Args&) -> Command { return Program{}; }},
    VerbSpec{"Key", args(word("name")),
             "a key of the jog panel for the inspection software (I++ DME KeyPress: Done, Del, F1 ...), while it has enabled the user",
             false, Access::Operator, command_index<Key>(), [](const Args& a) -> Command { return Key{std::string(a.at[0].text)}; }},
    VerbSpec{"Frames", args(), "the part frames on the controller: the active one and every name", false, Access::Open,
             command_index<Frames>(), [](const Args&) -> Command { return Frames{}; }},
    VerbSpec{"Frame", args(optional(word("name"))), "one part frame (default: the active one): origin and axes in machine coordinates",
             false, Access::Open, command_index<Frame>(), [](const Args& a) -> Command { return Frame{std::string(a.at[0].text)}; }},
    VerbSpec{"PartPos", args(optional(word("name"))), "the current position in a part frame (default: the active one)",
             false, Access::Open, command_index<PartPos>(),
             [](const Args& a) -> Command { return PartPos{std::string(a.at[0].text)}; }},
    VerbSpec{"UseFrame", args(word("name")), "make a stored part frame (or machine) the active one; hits are then also sent as PartPt",
             false, Access::Controlling, command_index<UseFrame>(),
             [](const Args& a) -> Command { return UseFrame{std::string(a.at[0].text)}; }},
    VerbSpec{"SetFrame",
             args(word("name"), optional(with_vectors(axis_words("O x y z X i j k Z i j k", "OXZ",
                                                                 "SetFrame takes O (origin), X and Z (axis directions), each a letter "
                                                                 "followed by three numbers and at most once, got '{got}'; usage: {usage}"),
                                                      "OXZ"))),
             "store a part frame and make it active: origin O (default: here), axes X and Z (default: the machine's)", false,
             Access::Controlling, command_index<SetFrame>(), [](const Args& a) -> Command { return set_frame(a); }},
    VerbSpec{"Align",
             args(word("name"), choice("method", "321 holes", "Align takes the method 321 (plane line point) or holes (plane hole hole), got '{got}'; usage: {usage}"),
                  word("plane-hits|last"), optional(word("hits")), optional(word("hits"))),
             "build a part frame from journaled hits (numbers like 1-3 or 4,5, or last: the newest 6, holes 9): 321 plane line point, or holes plane hole hole",
             false, Access::Controlling, command_index<Align>(),
             [](const Args& a) -> Command {
               return Align{std::string(a.at[0].text), a.at[1].choice == 1,
                            {std::string(a.at[2].text), std::string(a.at[3].text), std::string(a.at[4].text)}};
             }},
    VerbSpec{"Qualify",
             args(number("radius", 0, 50, "Qualify takes a tip radius from {min} to {max} mm, got '{got}'"),
                  number("form", 0, 50, "Qualify takes the sphere's form error from {min} to {max} mm, got '{got}'"),
                  offset("dx"), offset("dy"), offset("dz")),
             "a probe qualification: TipRadius and the probe offset (ProbeOffX/Y/Z) at once; the Qualified event tells all",
             false, Access::Controlling, command_index<Qualify>(),
             [](const Args& a) -> Command { return Qualify{a.number(0), a.number(1), {a.number(2), a.number(3), a.number(4)}}; }},
    VerbSpec{"Verdict",
             args(word("part"),
                  whole(number("in", 0, 100000, "Verdict takes the characteristics in tolerance as a whole number from {min} to {max}, got '{got}'")),
                  whole(number("out", 0, 100000, "Verdict takes the characteristics not in tolerance as a whole number from {min} to {max}, got '{got}'")),
                  choice("result", "pass fail", "Verdict takes the result pass or fail, got '{got}'; usage: {usage}")),
             "an inspection's result (messcap inspect announces it after a run): the Inspected event tells all",
             false, Access::Operator, command_index<Verdict>(),
             [](const Args& a) -> Command {
               return Verdict{std::string(a.at[0].text), static_cast<int>(a.number(1)), static_cast<int>(a.number(2)),
                                a.at[3].choice == 0};
             }},
    VerbSpec{"DelFrame", args(word("name")), "delete a stored part frame (the active one: machine becomes active)", false,
             Access::Controlling, command_index<DelFrame>(),
             [](const Args& a) -> Command { return DelFrame{std::string(a.at[0].text)}; }},
};

}  // namespace

std::span<const VerbSpec> verb_table() { return kVerbs; }

}  // namespace imess::protocol
