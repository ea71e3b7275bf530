// What every translator produces: program items (planner requests plus program-level steps),
// each with its source line, or the first error with its line, column, what was found and
// what is accepted. Translation is complete before anything moves.
#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "imess/planner/axes.hpp"
#include "imess/planner/segment.hpp"

namespace imess::programs {

using planner::Pose;

// A straight probing move toward `target` (absolute machine pose) at `feed` (the planner's
// feed rule units): G38.2 (error_on_miss) and G38.3 (silent miss). The planner has no probe
// request; the executor runs it as a ProbeMove (MOTION.md (d)). After it, the axes it moved
// are where the probe tripped: known only at run time.
struct Probe {
  Pose target{};
  double feed = 0;
  bool error_on_miss = true;
};

// Go to the home position (G28, G30) at traverse rate: `target` is the caller-given home
// pose (GcodeOptions::home, g30) for the axes the line named (all without axis words),
// and where the machine stands for the others.
struct Home {
  Pose target{};
};

// Stop and wait for the operator to resume (M0; M6, a tool change by hand: "M6 T3").
struct Pause {
  std::string reason = "M0";
};

// Program end (M2, M30, MRM M02). Nothing after it is translated.
struct End {};

// One step of a program. Planner requests carry ids 1, 2, 3 ... in item order.
using Step = std::variant<planner::Line, planner::Arc, planner::Dwell, planner::SetOutput, Probe, Home, Pause, End>;

struct Item {
  int line = 0;        // 1-based source line
  bool rapid = false;  // at traverse rate (G0, G28/G30 and their via point, HPGL pen-up travel)
  Step step;
  std::uint32_t frame = 0;  // index into Translation::frames: the program frame in force
};

// The program's frame of reference for an item (G-code): machine = program + offset (mm,
// deg), and the length unit of its words. What LinuxCNC's canonical calls are printed in.
struct Frame {
  Pose offset{};
  bool inches = false;
  bool operator==(const Frame&) const = default;
};

// A code accepted although it changes nothing in IMESS (a state IMESS is always in, like
// G40 or G64), or a reading worth knowing (block delete, F on a G20 line): what
// `messprog check` reports. One note per code, with its first line and how often it came.
struct Note {
  std::string code;     // "G40", "/"
  int line = 0;         // first line
  int count = 0;
  std::string meaning;  // "cutter radius compensation off: IMESS never compensates"
};

// A work offset the program writes (G-code G10 L2 / L20): what messd stores as the part frame
// of that name when a run reaches the line (docs/programs.md, G10).
struct OffsetWrite {
  std::size_t before_item = 0;  // written before this item is planned (items.size(): at the end)
  int line = 0;                 // 1-based source line of the G10
  int offset = 0;               // 0 ... 8: G54 ... G59.3 (kWorkOffsetNames)
  Pose origin{};                // the offset's whole pose afterwards, machine coordinates (mm, deg)
};

// Why a program was refused. Never renumbered.
enum class ErrorKind : std::uint8_t {
  BadCharacter = 1,       // a character that starts no word
  BadNumber = 2,          // a word's value is missing or not a number of the accepted form
  UnsupportedWord = 3,    // a letter the language (or this translator) does not take
  UnsupportedCode = 4,    // a G/M code or HPGL instruction not supported
  ModalConflict = 5,      // two words of the same modal group on one line
  RepeatedWord = 6,       // the same word letter twice on one line
  AxisNotOnMachine = 7,   // an axis word for an axis the machine does not have
  MissingWord = 8,        // a word the command needs is absent (G4 P, G2 I/J/K or R ...)
  NoFeed = 9,             // a feed move before any feed rate was set
  BadValue = 10,          // a value outside its range (negative dwell, output number ...)
  BadArc = 11,            // end not on the circle, radius too small, start on the centre
  NotConfigured = 12,     // a word that needs a caller-configured output or axis not given
  WordNotAllowed = 13,    // a word that cannot be used with the rest of the line
  UnterminatedComment = 14,
  PositionUnknown = 15,   // an incremental or unnamed axis after a probe moved it
  OutOfTravel = 16,       // an end point outside the machine's travel
  TooManyWords = 17,      // MRM: more than one word on a line
};

struct Error {
  ErrorKind kind = ErrorKind::BadCharacter;
  int line = 0, column = 0;  // 1-based; column of the offending word
  std::string found;         // what was there ("G7", "'#'", "end of line")
  std::string accepted;      // what would have been accepted
  // "line 3:7: unsupported code: found G7, accepted G0 G1 G2 G3 ..."
  std::string message() const;
};

// All items of the program, or the first error (and then no items).
struct Translation {
  std::vector<Item> items;
  bool ok = true;
  Error error;
  std::vector<Note> notes;
  std::vector<Frame> frames{Frame{}};  // items' frames; G-code pushes one per change
  std::vector<OffsetWrite> offset_writes;  // G10 L2 / L20, in line order
};

// The name of an error kind ("unsupported code").
const char* kind_name(ErrorKind kind);

// One item as a line of text, for logs and exact test comparisons, e.g.
// "3 LINE rapid X10 Y0 Z5 F50", "4 ARC ccw X0 Y10 Z0 C0,0,0 N0,0,1 P0,1,2 T0 F10",
// "5 DWELL 2", "6 OUT 3=1", "7 PROBE X0 Y0 Z-5 F1 error", "8 HOME", "9 PAUSE" (M0; else
// "9 PAUSE M6 T3"), "10 END".
// Numbers print with up to 6 decimals, trailing zeros removed; only machine axes print.
std::string describe(const Item& item, const planner::Machine& machine);

// The end pose of every motion item in turn, starting from `start` (Probe: its target).
Pose end_pose(const std::vector<Item>& items, const Pose& start);

}  // namespace imess::programs
