// Typed client -> daemon commands. The parser (verbs.hpp) produces them; the daemon acts on them.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

namespace imess::protocol {

struct Xyz {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Xyz&, const Xyz&) = default;
};

// 1996 verbs
struct StartMv { Xyz percent; };  // per-axis speed, % of MaxSpeed (x SpeedLevel); sign = direction
struct StopMv {};
struct ForcePt {};
// extensions
struct Hello { std::string client; };
struct Help {};
struct Status {};
struct GoTo { Xyz target; std::optional<double> speed; };  // mm, mm/s
struct Home {};
struct Free {};                                             // open the position loops now
struct Reset {};                                            // clear a fault
struct Set { std::string name; std::string value; };
struct Get { std::string name; };                           // empty name: list all
// Stats: since the start; Reset: a new measuring interval; Interval, Hist: that interval.
struct Stats { enum class Form { SinceStart, Reset, Interval, Hist } form = Form::SinceStart; };
struct HandMv { Xyz delta; std::optional<double> speed; };  // simulator: push the carriage by hand
struct Quit {};
struct Replay { std::uint64_t from = 0; };                  // re-send journaled hits from this seq
inline constexpr std::uint64_t kMaxReplayHits = 1000;       // per Replay request; the client asks again
// control of the machine (docs/protocol.md, "Control")
struct Take { bool force = false; };                        // force: stop the machine, take over
struct Release {};                                          // stop the machine, give up control
struct Watch { int ms = 0; };                               // dead-man interval; 0 = off
struct Stream { double hz = 0; };                           // this client's position rate; 0 = ReportHz

struct Version {};                                          // the daemon's version

// Queued motion (planner segments; docs/protocol.md, "Queued moves"). Ids are the client's;
// each queued id ends in exactly one `Done id` or `Failed id <Reason> <text>` event.
struct PathWords {  // named words; an axis not named keeps its planned position
  std::optional<double> x, y, z, i, j, k, f;
  std::optional<double> p;                   // ArcTo: turns
  std::optional<std::array<double, 3>> n;    // ArcTo: the plane's normal (N i j k)
  std::optional<double> a, b, c, u, v, w;  // the other axis letters (mm or degrees)
  // The word of an axis letter (X Y Z A B C U V W), nullptr for another letter.
  std::optional<double>* axis(char letter) noexcept {
    switch (letter) {
      case 'X': return &x;
      case 'Y': return &y;
      case 'Z': return &z;
      case 'A': return &a;
      case 'B': return &b;
      case 'C': return &c;
      case 'U': return &u;
      case 'V': return &v;
      case 'W': return &w;
      default: return nullptr;
    }
  }
  const std::optional<double>* axis(char letter) const noexcept { return const_cast<PathWords*>(this)->axis(letter); }
  friend bool operator==(const PathWords&, const PathWords&) = default;
};
struct MoveTo { std::uint32_t id = 0; PathWords words; };          // straight line, mm, F mm/s
struct ArcTo { std::uint32_t id = 0; bool ccw = true; PathWords words; };  // end XYZ, centre offset IJK, N, P
struct Dwell { std::uint32_t id = 0; double seconds = 0; };
struct Probe { std::uint32_t id = 0; PathWords words; };           // move until the probe edge: target XYZ, F
// Jog named axes (C20 U-10): % of MaxSpeed (x SpeedLevel) each, mm/s or deg/s; others stand.
struct JogAx { PathWords percent; };
// Queue the switch of a configured output (the path comes to rest first and holds for the
// output's settle time); Outputs lists the outputs and their states.
struct SetOut { std::uint32_t id = 0; std::string output; bool on = false; };
struct Outputs {};
struct Queue {};                                            // pending count, running id
struct Pause {};                                            // feed hold on the path
struct Resume {};
// Programs (G-code, HPGL, MRM; docs/programs.md): the controller's folder, loading one by
// name or sent over the connection (the lines up to a line '.'), running it, aborting it.
struct Programs {};
struct Load { std::string name; };
struct Key { std::string name; };                          // I++ DME KeyPress for the inspection software
struct Upload { std::string name; };
struct Run { bool detached = false; };
struct Abort {};
struct Program {};
// Part frames (docs/protocol.md, "Part frames"): named frames mapping part coordinates to the
// machine's, stored on the controller; the active one tags every hit with PartPt.
struct Frames {};                                           // the active frame and all names
struct Frame { std::string name; };                         // one frame (empty: the active one)
struct PartPos { std::string name; };                       // the position in a frame (empty: active)
struct UseFrame { std::string name; };
using Vector3 = std::array<double, 3>;
struct SetFrame {                                           // nothing given: origin here, machine axes
  std::string name;
  std::optional<Vector3> origin, x_axis, z_axis;            // O x y z, X i j k, Z i j k
};
struct Align {                                              // from journaled hits: "1-3", "4,5", "6"
  std::string name;
  bool holes = false;                                       // false: 3-2-1 plane line point; true: plane hole hole
  std::array<std::string, 3> hits;
};
struct DelFrame { std::string name; };
// A probe qualification's result (messcap qualify measures it on a reference sphere): the
// effective tip radius, the sphere's form error and the probe offset, applied at once.
struct Qualify { double radius = 0, form = 0; Xyz offset; };
// An inspection's verdict, announced by the client that measured it (messcap inspect): the
// part, its characteristics in tolerance and not (out of tolerance or not evaluated), pass.
// messd passes it on as the Inspected event.
struct Verdict { std::string part; int in = 0, out = 0; bool pass = false; };
// Scans (docs/protocol.md, "Scanning"): surface points in machine coordinates, mm. ScanLine:
// from start to end on a surface whose outward normal is `normal`; ScanCircle: about the axis
// through `centre` with direction `axis` from the surface point `start`, `sweep` degrees
// (right hand about the axis), in a bore (the surface faces the axis) or round a boss. speed:
// mm/s along the surface (default ScanSpeed).
struct ScanLine { std::uint32_t id = 0; Vector3 start{}, end{}, normal{}; std::optional<double> speed; };
struct ScanCircle {
  std::uint32_t id = 0;
  Vector3 centre{}, start{}, axis{};
  double sweep = 360;
  bool bore = true;
  std::optional<double> speed;
};
inline constexpr double kMaxScanSweep = 36000;  // degrees: a hundred turns
inline constexpr double kMaxDwellSeconds = 3600;
inline constexpr int kMaxArcTurns = 1000;  // ArcTo P: 1 (the arc alone) ... this

inline constexpr int kWatchMinMs = 50;     // below this, io jitter alone would stop the machine
inline constexpr int kWatchMaxMs = 60000;
inline constexpr double kStreamMinHz = 0.1;      // as ReportHz
inline constexpr double kStreamMaxHz = 10000;    // the fastest motion loop (Period 100 us)

using Command = std::variant<StartMv, StopMv, ForcePt, Hello, Help, Status, GoTo, Home, Free,
                             Reset, Set, Get, Stats, HandMv, Quit, Replay, Take, Release, Watch, Version,
                             MoveTo, ArcTo, Dwell, Queue, Pause, Resume, Probe, JogAx, SetOut, Outputs,
                             Programs, Load, Upload, Run, Abort, Program, Key, Frames, Frame, PartPos, UseFrame,
                             SetFrame, Align, DelFrame, Qualify, Stream, Verdict, ScanLine, ScanCircle>;

}  // namespace imess::protocol
