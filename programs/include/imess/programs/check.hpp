// A whole program, checked as it will run: the language from a file's name, the translation
// with one set-up for the three languages, and a dry run through the planner (the machine's
// travel and axis limits, arcs' extreme points, feeds) that gives what a user asks before
// pressing Run: segments, path length, estimated time, bounding box. messd checks with it
// before the first segment moves (Load, Run); messprog check and plot use the same code.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/planner/planner.hpp"
#include "imess/programs/gcode.hpp"
#include "imess/programs/hpgl.hpp"
#include "imess/programs/mrm.hpp"

namespace imess::programs {

enum class Language : std::uint8_t { Gcode, Hpgl, Mrm };

// From the file name's extension (case-insensitive): .nc .ngc .gcode .tap → G-code,
// .plt .hpgl → HPGL, .mrm → MRM.
std::optional<Language> language_of(std::string_view file_name);
// From its name as a word: gcode, hpgl, mrm.
std::optional<Language> language_named(std::string_view word);
const char* language_name(Language lang);  // "gcode", "hpgl", "mrm"
inline constexpr const char* kExtensions = ".nc .ngc .gcode .tap .plt .hpgl .mrm";

// One set-up for every language: the machine and where it stands are copied into the
// language's own options by translate().
struct Setup {
  planner::Machine machine = planner::make_machine("XYZ", -1000, 1000, 100, 1000);
  Pose start{};
  GcodeOptions gcode;
  HpglOptions hpgl;
  MrmOptions mrm;
};

Translation translate(Language lang, std::string_view text, const Setup& setup);

// The planner request id run for item i (0-based) is i + 1 in the dry run and in messd, so a
// Done, a Failed or a segment names its item.
inline std::uint32_t item_id(std::size_t index) { return static_cast<std::uint32_t>(index + 1); }

// How a program's items become planner requests, the same in the dry run and in messd:
// Line/Arc/Dwell/SetOutput as they are; Probe (G38.2/.3) one search line from where the
// machine stands to the target at the probe's feed (a miss ends at the target); Home a rapid
// line to its target at `rapid_feed` (0: the fastest axis' max_velocity). Pause and End
// give no request (nullopt).
std::optional<planner::Request> request_of(const Item& item, std::uint32_t id, const Pose& from,
                                           const planner::Machine& machine, double rapid_feed = 0);

struct Check {
  bool ok = true;
  std::string error;  // "line 12:1: out of travel: segment 12: axis Y leaves its travel at 1012.5"
  int error_line = 0;
  std::size_t lines = 0;     // source lines
  std::size_t blocks = 0;    // items
  std::size_t segments = 0;  // planned segments (a probe is one)
  double length = 0;         // path length: mm along X Y Z (else U V W, else degrees)
  double time = 0;           // estimated seconds: planned motion, dwells and output holds; a
                             // probe as its whole search, Pause (M0) as no time
  double feed_length = 0, rapid_length = 0, probe_length = 0;
  Pose low{}, high{};        // bounding box of the path, every axis
  bool moves = false;        // any motion at all (else low/high are the start)
  std::vector<Note> notes;   // codes accepted without effect, block delete (G-code)
  std::vector<OffsetWrite> offset_writes;  // work offsets a run writes (G10 L2 / L20)
};

// One planned segment of the dry run and the item it came from.
using SegmentVisitor = std::function<void(const planner::PlannedSegment& seg, const Item& item)>;

// Plans every item from `start` as messd will (request_of), to the end; the first refusal
// ends it with the item's line. `visit`, when given, sees every segment in order.
Check check_items(const std::vector<Item>& items, const planner::Machine& machine,
                  const planner::PlannerOptions& options, const Pose& start, double rapid_feed = 0,
                  const SegmentVisitor& visit = {});

// The number of source lines of a program text (a last line without its LF counts).
std::size_t line_count(std::string_view text);

// translate() then check_items(); a translation error gives ok = false with its message.
Check check_program(Language lang, std::string_view text, const Setup& setup,
                    const planner::PlannerOptions& options = {}, const SegmentVisitor& visit = {});

}  // namespace imess::programs
