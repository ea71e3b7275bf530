// G-code translator: one line at a time into words, LinuxCNC's modal groups and order of
// execution (feed mode, feed, spindle, outputs, dwell, modes, home, motion, stop), absolute
// machine poses for the planner, the program frame of each item and notes for check.
#include "imess/programs/gcode.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gcode_arc.hpp"
#include "gcode_line.hpp"
#include "scanner.hpp"

namespace imess::programs {

namespace {
using namespace detail;

constexpr const char* kLetters = "N G M X Y Z A B C U V W I J K R F P Q S L T";
constexpr const char* kGcodes =
    "G0 G1 G2 G3 G4 G10 G17 G18 G19 G20 G21 G28 G30 G38.2 G38.3 G40 G49 G53 G54 G55 G56 G57 G58 G59 G59.1 G59.2 G59.3 G61 G61.1 G64 "
    "G80 G90 G91 G91.1 G92 G92.1 G92.2 G92.3 G94";
constexpr const char* kMcodes = "M0 M1 M2 M3 M4 M5 M6 M7 M8 M9 M30 M62 M63 M64 M65";
constexpr double kInch = 25.4;
// G54 ... G59 (codes 540 ... 590 in tenths), then G59.1 G59.2 G59.3 (591 ... 593): 0 ... 8.
int work_offset_index(int code_tenths) { return code_tenths > 590 ? 6 + (code_tenths - 591) : (code_tenths - 540) / 10; }

struct Word {
  char letter = 0;
  double value = 0;
  int column = 0;
  bool given = false;
};

enum Group {
  kMotion, kPlane, kDistance, kUnits, kCoord, kNonModal, kStop, kSpindle, kIo,
  kCancel, kComp, kLength, kFeedMode, kPath, kArcDistance, kToolChange, kCoolant, kGroups
};
constexpr const char* kGroupNames[kGroups] = {"motion (G0 G1 G2 G3 G38.2 G38.3)", "plane (G17 G18 G19)",
                                              "distance (G90 G91)", "units (G20 G21)", "work offset (G54-G59.3)",
                                              "non-modal (G4 G10 G28 G30 G53 G92 G92.1 G92.2 G92.3)", "stop (M0 M1 M2 M30)", "spindle (M3 M4 M5)",
                                              "output (M62 M63 M64 M65)", "motion cancel (G80)",
                                              "cutter compensation (G40)", "tool length (G49)", "feed mode (G94)",
                                              "path control (G61 G61.1 G64)", "arc distance (G91.1)",
                                              "tool change (M6)", "coolant (M7 M8 M9)"};

// Codes accepted for a state IMESS is always in: what messprog check says of them.
const char* accepted_meaning(const std::string& code) {
  if (code == "G40") return "cutter radius compensation off: IMESS never compensates";
  if (code == "G49") return "tool length compensation off: IMESS never offsets the tool length";
  if (code == "G80") return "canned cycle off: IMESS has none; as in LinuxCNC the motion mode is cancelled";
  if (code == "G94") return "feed per minute, IMESS's only feed mode; as in LinuxCNC it sets F to 0 (F again after it)";
  if (code == "G61") return "exact path: IMESS always follows the programmed path";
  if (code == "G61.1") return "exact stop: IMESS follows the same path, but links blocks at speed where the corner allows";
  if (code == "G64") return "path blending: IMESS follows the programmed path exactly, within any P/Q tolerance";
  if (code == "G91.1") return "arc centres I J K relative to the start, IMESS's only arc distance mode";
  if (code == "M1") return "optional stop: IMESS has no optional-stop switch on, M1 does not stop";
  return "";
}

// A G or M code on a line: code×10 for G (38.2 → 382), plain for M.
struct Code {
  int code = -1;
  int column = 0;
  std::string text;
};

std::string g_text(int code10) {
  return "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
}

class GcodeTranslator {
 public:
  explicit GcodeTranslator(const GcodeOptions& o) : o_(o), m_(o.machine) {
    planner::validate(m_);
    if (o.work_offset < 0 || o.work_offset >= kWorkOffsets) throw std::invalid_argument("GcodeOptions::work_offset: 0..8 (G54..G59.3)");
    pos_ = o.start;
    coord_ = o.work_offset;
    known_.fill(true);
    offsets_ = o.work_offsets;
    frames_.push_back(Frame{offset(), false});
    rapid_ = o.rapid_feed;
    if (!(rapid_ > 0))
      for (int i = 0; i < m_.count; ++i) rapid_ = std::max(rapid_, m_.axes[i].max_velocity);
  }

  std::vector<Item> run(std::string_view text) {
    const auto lines = split_lines(text);
    for (std::size_t k = 0; k < lines.size() && !ended_; ++k) line(static_cast<int>(k + 1), lines[k]);
    return std::move(items_);
  }
  const std::vector<Note>& notes() const { return notes_; }
  const std::vector<Frame>& frames() const { return frames_; }
  const std::vector<OffsetWrite>& offset_writes() const { return writes_; }

 private:
  int axis_index(char letter) const {
    for (int i = 0; i < m_.count; ++i)
      if (m_.axes[i].letter == letter) return i;
    return -1;
  }
  std::string machine_axes() const {
    std::string s;
    for (int i = 0; i < m_.count; ++i) s += std::string(i ? " " : "") + m_.axes[i].letter;
    return s;
  }
  [[noreturn]] void fail(ErrorKind k, int col, std::string found, std::string accepted) const {
    raise(k, line_, col, std::move(found), std::move(accepted));
  }
  void emit(Step step, bool rapid = false) {
    std::visit(
        [&](auto& x) {
          if constexpr (requires { x.id; }) x.id = ++next_id_;
        },
        step);
    items_.push_back(Item{line_, rapid, std::move(step), static_cast<std::uint32_t>(frames_.size() - 1)});
  }
  void note(const std::string& code, std::string meaning) {
    for (auto& n : notes_)
      if (n.code == code) {
        ++n.count;
        return;
      }
    notes_.push_back(Note{code, line_, 1, std::move(meaning)});
  }
  void note_code(const Code& c) {
    if (c.code >= 0) note(c.text, accepted_meaning(c.text));
  }
  void set_frame() {
    const Frame f{offset(), inches_};
    if (!(frames_.back() == f)) frames_.push_back(f);
  }
  Word& word(char letter) { return words_[static_cast<std::size_t>(letter - 'A')]; }
  std::string word_text(const Word& w) const { return std::string(1, w.letter) + num(w.value); }

  void parse(const CompactLine& cl) {
    const std::string_view s = cl.text;
    words_ = {};
    for (auto& c : codes_) c = Code{};
    bool first = true;
    std::size_t i = 0;
    for (;;) {
      if (i >= s.size()) break;
      const int col = cl.column(i);
      const char c = s[i];
      if (c == ';') break;
      if (c == '(') {
        const std::size_t close = s.find(')', i);
        if (close == std::string_view::npos) fail(ErrorKind::UnterminatedComment, col, "'(' without ')'", "a comment closed by ')' on the same line");
        i = close + 1;
        continue;
      }
      if (!is_letter(c)) fail(ErrorKind::BadCharacter, col, char_text(s, i), std::string("words ") + kLetters + ", '(comment)', ';comment'");
      const char L = upper(c);
      if (std::string_view(kLetters).find(L) == std::string_view::npos || L == ' ')
        fail(ErrorKind::UnsupportedWord, col, std::string(1, L), std::string("words ") + kLetters);
      ++i;
      double v = 0;
      if (!scan_number(s, i, v)) {
        fail(ErrorKind::BadNumber, col, std::string(1, L) + " followed by " + char_text(s, i), std::string("a decimal number after ") + L);
      }
      if (L == 'N') {
        if (!first) fail(ErrorKind::WordNotAllowed, col, "N" + num(v) + " after other words", "N only as the first word of a line");
      } else if (L == 'G' || L == 'M') {
        code(L, v, col);
      } else {
        Word& w = word(L);
        if (w.given) fail(ErrorKind::RepeatedWord, col, std::string(1, L) + num(v) + " after " + word_text(w) + " at column " + std::to_string(w.column), std::string("one ") + L + " word per line");
        w = Word{L, v, col, true};
      }
      first = false;
    }
  }

  void code(char L, double v, int col) {
    const std::string text = std::string(1, L) + num(v);
    int group = -1, c = -1;
    if (L == 'G') {
      const double t = v * 10;
      const long r = std::lround(t);
      if (std::fabs(t - static_cast<double>(r)) < 1e-6 && r >= 0 && r < 10000) {
        c = static_cast<int>(r);
        switch (c) {
          case 0: case 10: case 20: case 30: case 382: case 383: group = kMotion; break;
          case 170: case 180: case 190: group = kPlane; break;
          case 200: case 210: group = kUnits; break;
          case 900: case 910: group = kDistance; break;
          case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593: group = kCoord; break;
          case 40: case 100: case 280: case 300: case 530: case 920: case 921: case 922: case 923: group = kNonModal; break;
          case 800: group = kCancel; break;
          case 400: group = kComp; break;
          case 490: group = kLength; break;
          case 940: group = kFeedMode; break;
          case 610: case 611: case 640: group = kPath; break;
          case 911: group = kArcDistance; break;
          default: break;
        }
      }
      if (group < 0) fail(ErrorKind::UnsupportedCode, col, text, kGcodes);
    } else {
      const long r = std::lround(v);
      if (std::fabs(v - static_cast<double>(r)) < 1e-9 && r >= 0 && r < 1000) {
        c = static_cast<int>(r);
        switch (c) {
          case 0: case 1: case 2: case 30: group = kStop; break;
          case 3: case 4: case 5: group = kSpindle; break;
          case 62: case 63: case 64: case 65: group = kIo; break;
          case 6: group = kToolChange; break;
          case 7: case 8: case 9: group = kCoolant; break;
          default: break;
        }
      }
      if (group < 0) fail(ErrorKind::UnsupportedCode, col, text, kMcodes);
    }
    Code& slot = codes_[group];
    if (slot.code >= 0)
      fail(ErrorKind::ModalConflict, col, text + " after " + slot.text + " at column " + std::to_string(slot.column),
           std::string("one word of group ") + kGroupNames[group] + " per line");
    slot = Code{c, col, text};
  }

  double unit() const { return inches_ ? kInch : 1.0; }
  double scale_of(int i) const { return m_.axes[i].kind == planner::AxisKind::Linear ? unit() : 1.0; }
  // machine = program + offset(): the selected work offset plus G92's.
  Pose offset() const {
    Pose p = offsets_[static_cast<std::size_t>(coord_)];
    for (int i = 0; i < m_.count; ++i) p[i] += g92_[i];
    return p;
  }

  void line(int number, std::string_view source) {
    line_ = number;
    const CompactLine cl = compact_line(source);
    if (cl.block_delete && o_.block_delete) {
      note("/", "block delete: lines starting with '/' are skipped (BlockDelete on)");
      return;
    }
    // '%': the first line that is not blank starts the program, the next '%' ends it.
    if (cl.text == "%") {
      if (!started_) {
        started_ = percent_ = true;
        return;
      }
      if (percent_) {
        ended_ = true;
        return;
      }
      fail(ErrorKind::BadCharacter, cl.column(0), "'%' after the first line of a program that did not begin with '%'",
           "'%' as the first line (it starts the program) and once more to end it");
    }
    if (!cl.text.empty()) started_ = true;
    parse(cl);
    const Code& motion_code = codes_[kMotion];
    const Code& nonmodal = codes_[kNonModal];
    const bool home_line = nonmodal.code == 280 || nonmodal.code == 300;
    // G28, G30, G10 and G92 take the line's axis words (no motion of their own mode then).
    const bool axis_user = home_line || nonmodal.code == 100 || nonmodal.code == 920;
    // Axis words must name machine axes.
    bool any_axis = false;
    int first_axis_col = 0;
    for (char L : {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'}) {
      const Word& w = word(L);
      if (!w.given) continue;
      if (axis_index(L) < 0) fail(ErrorKind::AxisNotOnMachine, w.column, word_text(w), "axis words of this machine: " + machine_axes());
      if (!any_axis) first_axis_col = w.column;
      any_axis = true;
    }
    // The motion mode this line moves in: its own code, none after G80, else the modal one.
    const int motion_now = motion_code.code >= 0 ? motion_code.code : codes_[kCancel].code >= 0 ? -1 : motion_;
    const bool any_centre = word('I').given || word('J').given || word('K').given || word('R').given;
    const bool arc_on_line = (motion_now == 20 || motion_now == 30) && !axis_user &&
                             (motion_code.code >= 0 || any_axis || any_centre);
    // 1. Feed mode (G94 sets F to 0, as LinuxCNC), feed and spindle speed. F is read in the
    // units in force before this line's G20/G21 (LinuxCNC's order) and kept as a speed.
    if (codes_[kFeedMode].code >= 0) {
      note_code(codes_[kFeedMode]);
      feed_mm_ = feed_deg_ = 0;
      feed_reset_line_ = line_;
    }
    if (const Word& f = word('F'); f.given) {
      if (f.value < 0) fail(ErrorKind::BadValue, f.column, word_text(f), "F >= 0 (units per minute)");
      feed_mm_ = f.value * unit();
      feed_deg_ = f.value;
      if (const Code& u = codes_[kUnits]; u.code >= 0 && (u.code == 200) != inches_)
        note("F with " + u.text, "F on a line that changes units is read in the units before the change (LinuxCNC's order)");
    }
    if (const Word& sw = word('S'); sw.given) {
      if (sw.value < 0) fail(ErrorKind::BadValue, sw.column, word_text(sw), "S >= 0");
      speed_ = sw.value;
      speed_set_ = true;
    }
    // P belongs to G4, M62-M65, an arc (turns) or G64 (tolerance); exactly one of them. Q to G64.
    const Word& p = word('P');
    const bool g64 = codes_[kPath].code == 640;
    {
      int users = (nonmodal.code == 40 || nonmodal.code == 100) + (codes_[kIo].code >= 0) + arc_on_line + g64;
      if (p.given && users == 0) fail(ErrorKind::WordNotAllowed, p.column, word_text(p), "P only with G4, G10, M62-M65, G2/G3 (turns) or G64");
      if (p.given && users > 1) fail(ErrorKind::WordNotAllowed, p.column, word_text(p), "P for one of G4, G10, M62-M65, G2/G3, G64 per line");
      if (const Word& q = word('Q'); q.given && !g64) fail(ErrorKind::WordNotAllowed, q.column, word_text(q), "Q only with G64");
      if (const Word& l = word('L'); l.given && nonmodal.code != 100) fail(ErrorKind::WordNotAllowed, l.column, word_text(l), "L only with G10");
    }
    // Tool select and change (LinuxCNC: the spindle stops, then the change; here a pause).
    if (const Word& tw = word('T'); tw.given) {
      const long n = std::lround(tw.value);
      if (std::fabs(tw.value - static_cast<double>(n)) > 1e-9 || n < 0) fail(ErrorKind::BadValue, tw.column, word_text(tw), "T0, T1, T2 ... (a tool number)");
      tool_ = n;
      note("T", "tool (on a CMM: stylus) selected; M6 changes to it");
    }
    if (const Code& tc = codes_[kToolChange]; tc.code >= 0) {
      if (o_.spindle_output) emit(planner::SetOutput{0, *o_.spindle_output, 0.0});
      const std::string what = "M6 T" + std::to_string(tool_);
      if (o_.tool_change_pause) emit(Pause{what});
      note("M6", o_.tool_change_pause ? "tool change: the program pauses like M0 for the operator" : "tool change: recorded, no pause (configured)");
    }
    // 2. Spindle.
    if (const Code& sp = codes_[kSpindle]; sp.code >= 0) {
      if (!o_.spindle_output) fail(ErrorKind::NotConfigured, sp.column, sp.text, "M3/M4/M5 only with a configured spindle output");
      if (sp.code != 5 && o_.spindle_ccw_output) emit(planner::SetOutput{0, *o_.spindle_ccw_output, sp.code == 4 ? 1.0 : 0.0});
      emit(planner::SetOutput{0, *o_.spindle_output, sp.code == 5 ? 0.0 : (speed_set_ ? speed_ : 1.0)});
    }
    // Coolant: M7 mist on, M8 flood on, M9 both off.
    if (const Code& co = codes_[kCoolant]; co.code >= 0) {
      const auto& out = co.code == 7 ? o_.mist_output : o_.flood_output;
      if (co.code != 9 && !out) fail(ErrorKind::NotConfigured, co.column, co.text, co.text + (co.code == 7 ? " only with a configured mist output" : " only with a configured flood output"));
      if (co.code == 9 && !o_.mist_output && !o_.flood_output) fail(ErrorKind::NotConfigured, co.column, co.text, "M9 only with a configured mist or flood output");
      if (co.code != 9) emit(planner::SetOutput{0, *out, 1.0});
      for (const auto& o : {o_.mist_output, o_.flood_output})
        if (co.code == 9 && o) emit(planner::SetOutput{0, *o, 0.0});
    }
    // 3. Digital outputs.
    if (const Code& io = codes_[kIo]; io.code >= 0) {
      if (o_.digital_output_count == 0) fail(ErrorKind::NotConfigured, io.column, io.text, "M62-M65 only with configured digital outputs");
      if (!p.given) fail(ErrorKind::MissingWord, io.column, io.text + " without P", "P<output number> with " + io.text);
      const long n = std::lround(p.value);
      if (std::fabs(p.value - static_cast<double>(n)) > 1e-9 || n < 0 || n >= o_.digital_output_count)
        fail(ErrorKind::BadValue, p.column, word_text(p), "P0 ... P" + std::to_string(o_.digital_output_count - 1));
      emit(planner::SetOutput{0, static_cast<std::uint16_t>(o_.digital_output_base + n), (io.code == 62 || io.code == 64) ? 1.0 : 0.0});
    }
    // 4. Dwell (axis words on its line move afterwards, in the motion mode, as LinuxCNC).
    if (nonmodal.code == 40) {
      if (!p.given) fail(ErrorKind::MissingWord, nonmodal.column, "G4 without P", "G4 P<seconds>");
      if (p.value < 0) fail(ErrorKind::BadValue, p.column, word_text(p), "P >= 0 seconds");
      emit(planner::Dwell{0, p.value});
    }
    // 5. Modes.
    if (codes_[kPlane].code >= 0) plane_ = codes_[kPlane].code / 10;
    if (codes_[kUnits].code >= 0) inches_ = codes_[kUnits].code == 200;
    note_code(codes_[kComp]);
    note_code(codes_[kLength]);
    if (codes_[kCoord].code >= 0) coord_ = work_offset_index(codes_[kCoord].code);
    set_frame();
    note_code(codes_[kPath]);
    if (codes_[kDistance].code >= 0) absolute_ = codes_[kDistance].code == 900;
    note_code(codes_[kArcDistance]);
    note_code(codes_[kCancel]);
    motion_ = motion_now;
    // I J K R only on arcs.
    for (char L : {'I', 'J', 'K', 'R'}) {
      const Word& w = word(L);
      if (w.given && !arc_on_line) fail(ErrorKind::WordNotAllowed, w.column, word_text(w), std::string(1, L) + " only with G2/G3");
    }
    // 6. Home, machine coordinates, motion.
    if (nonmodal.code >= 921 && nonmodal.code <= 923) g92_clear(nonmodal);
    if (axis_user && motion_code.code >= 0)
      fail(ErrorKind::WordNotAllowed, motion_code.column, motion_code.text + " with " + nonmodal.text,
           nonmodal.text + " or a motion code on a line: both take the axis words");
    if (home_line) {
      home(nonmodal, any_axis);
    } else if (nonmodal.code == 100) {
      g10(nonmodal);
    } else if (nonmodal.code == 920) {
      g92(nonmodal, any_axis);
    } else if (nonmodal.code == 530) {
      if (!(motion_ == 0 || motion_ == 10)) fail(ErrorKind::WordNotAllowed, nonmodal.column, "G53 with " + (motion_ < 0 ? std::string("no motion mode") : g_text(motion_)), "G53 with G0 or G1");
      if (!absolute_) fail(ErrorKind::WordNotAllowed, nonmodal.column, "G53 in G91", "G53 in G90");
      if (any_axis) move(target(true, first_axis_col));
    } else if (any_axis || arc_on_line || motion_code.code == 382 || motion_code.code == 383) {
      if (motion_ < 0)
        fail(ErrorKind::MissingWord, first_axis_col, "axis words without a motion mode" + std::string(codes_[kCancel].code >= 0 || cancel_line_ ? " (G80 cancelled it)" : ""),
             "G0 G1 G2 G3 G38.2 G38.3 before or on this line");
      const int col = motion_code.code >= 0 ? motion_code.column : first_axis_col;
      if (motion_ == 382 || motion_ == 383) {
        if (!any_axis) fail(ErrorKind::MissingWord, col, g_text(motion_) + " without axis words", "G38.2/G38.3 with the point to probe toward");
        probe(target(false, col), col);
      } else if (motion_ == 20 || motion_ == 30) {
        arc(target(false, col), col);
      } else {
        move(target(false, col));
      }
    }
    if (codes_[kCancel].code >= 0 && motion_code.code < 0) cancel_line_ = true;
    if (motion_code.code >= 0) cancel_line_ = false;
    // 7. Stop.
    if (const Code& st = codes_[kStop]; st.code >= 0) {
      if (st.code == 1) {
        note_code(st);
      } else if (st.code == 0) {
        emit(Pause{});
      } else {
        emit(End{});
        ended_ = true;
      }
    }
  }

  // G92 (axis words: the current position reads those values), G92.1 (offsets cleared),
  // G92.2 (suspended), G92.3 (restored). G92.1-.3 leave the axis words to the motion mode.
  void g92_clear(const Code& c) {
    if (c.code == 921) g92_ = g92_kept_ = Pose{};
    if (c.code == 922) g92_ = Pose{};
    if (c.code == 923) g92_ = g92_kept_;
    set_frame();
  }
  void g92(const Code& c, bool any_axis) {
    if (!any_axis) fail(ErrorKind::MissingWord, c.column, "G92 without axis words", "G92 with the values the current position gets");
    for (int i = 0; i < m_.count; ++i) {
      const Word& w = word(m_.axes[i].letter);
      if (!w.given) continue;
      if (!known_[i]) fail(ErrorKind::PositionUnknown, w.column, word_text(w) + " with G92 after the probe on line " + std::to_string(probe_line_),
                           std::string(1, w.letter) + " named in G90 (or G53) first");
      g92_[i] = pos_[i] - offsets_[static_cast<std::size_t>(coord_)][i] - w.value * scale_of(i);
    }
    g92_kept_ = g92_;
    set_frame();
    note("G92", "offsets set by G92 last for this program (each program starts without)");
  }

  // G10 L2 P<n>: work offset n (P0: the one in force) to the axis words, machine
  // coordinates; G10 L20 P<n>: so that the machine's position reads the axis words there.
  void g10(const Code& c) {
    const Word& l = word('L');
    const Word& p = word('P');
    if (!l.given || (l.value != 2 && l.value != 20)) fail(ErrorKind::MissingWord, c.column, "G10" + (l.given ? " " + word_text(l) : std::string(" without L")), "G10 L2 or G10 L20");
    if (!p.given) fail(ErrorKind::MissingWord, c.column, "G10 without P", "G10 L2/L20 P0 ... P9 (P0 the offset in force, P1 ... P9 G54 ... G59.3)");
    const long n = std::lround(p.value);
    if (std::fabs(p.value - static_cast<double>(n)) > 1e-9 || n < 0 || n > kWorkOffsets)
      fail(ErrorKind::BadValue, p.column, word_text(p), "P0 ... P9 (P0 the offset in force, P1 ... P9 G54 ... G59.3)");
    const std::size_t k = n == 0 ? static_cast<std::size_t>(coord_) : static_cast<std::size_t>(n - 1);
    for (int i = 0; i < m_.count; ++i) {
      const Word& w = word(m_.axes[i].letter);
      if (!w.given) continue;
      if (l.value == 2) {
        offsets_[k][i] = w.value * scale_of(i);
      } else {
        if (!known_[i]) fail(ErrorKind::PositionUnknown, w.column, word_text(w) + " with G10 L20 after the probe on line " + std::to_string(probe_line_),
                             std::string(1, w.letter) + " named in G90 (or G53) first");
        offsets_[k][i] = pos_[i] - w.value * scale_of(i) - g92_[i];
      }
    }
    set_frame();
    writes_.push_back(OffsetWrite{items_.size(), line_, static_cast<int>(k), offsets_[k]});
    note("G10", "work offsets written by G10: messd stores each as its part frame (G54 ... G59.3) when a run reaches the line");
  }

  // G28 / G30: with axis words a rapid to that point (in the current G90/G91), then those
  // axes alone to the home pose; without axis words every axis to it. Both at traverse rate.
  void home(const Code& code, bool any_axis) {
    const Pose& home = code.code == 280 ? o_.home : o_.g30;
    Pose goal = home;
    if (any_axis) {
      // The via point; incremental zero words stay where the machine is (even after a probe).
      bool here = !absolute_;
      for (int i = 0; i < m_.count; ++i)
        if (const Word& w = word(m_.axes[i].letter); w.given && w.value != 0) here = false;
      if (!here) {
        const Pose via = target(false, code.column);
        if (via != pos_) emit(planner::Line{0, via, rapid_}, true);
        pos_ = via;
      }
      goal = pos_;
      for (int i = 0; i < m_.count; ++i) {
        if (word(m_.axes[i].letter).given) {
          goal[i] = home[i];
          known_[i] = true;
        } else if (!known_[i]) {
          fail(ErrorKind::PositionUnknown, code.column,
               std::string("no ") + m_.axes[i].letter + " word after the probe on line " + std::to_string(probe_line_),
               "every axis the probe moved named in G90 (or G53), or in this " + code.text + ", before it moves again");
        }
      }
    } else {
      known_.fill(true);
    }
    emit(Home{goal}, true);
    pos_ = goal;
  }

  // The absolute machine target of this line's axis words (G53: machine coordinates).
  Pose target(bool machine_coords, int col) {
    Pose t = pos_;
    for (int i = 0; i < m_.count; ++i) {
      const Word& w = word(m_.axes[i].letter);
      const double scale = m_.axes[i].kind == planner::AxisKind::Linear ? unit() : 1.0;
      if (!w.given) {
        if (!known_[i])
          fail(ErrorKind::PositionUnknown, col, std::string("no ") + m_.axes[i].letter + " word after the probe on line " + std::to_string(probe_line_),
               std::string("every axis the probe moved named in G90 (or G53) before it moves again"));
        continue;
      }
      if (machine_coords) {
        t[i] = w.value * scale;
        known_[i] = true;
      } else if (absolute_) {
        t[i] = w.value * scale + offset()[i];
        known_[i] = true;
      } else {
        if (!known_[i])
          fail(ErrorKind::PositionUnknown, w.column, word_text(w) + " in G91 after the probe on line " + std::to_string(probe_line_), std::string(1, w.letter) + " in G90 (or G53)");
        t[i] = pos_[i] + w.value * scale;
      }
    }
    if (o_.check_travel)
      for (int i = 0; i < m_.count; ++i) {
        const auto& a = m_.axes[i];
        if (t[i] < a.travel_min || t[i] > a.travel_max) {
          const Word& w = word(a.letter);
          fail(ErrorKind::OutOfTravel, w.given ? w.column : col, std::string(1, a.letter) + " at " + num(t[i]) + " (machine)",
               std::string(1, a.letter) + " within " + num(a.travel_min) + " ... " + num(a.travel_max));
        }
      }
    return t;
  }

  // The planner feed for a move from pos_ to t: the speed F set, per second (mm/s when a
  // linear axis moves, else deg/s: F is deg/min for a rotary-only move).
  double feed_for(const Pose& t, int col, bool arc = false) const {
    bool linear = arc;
    for (int i = 0; i < m_.count; ++i)
      if (m_.axes[i].kind == planner::AxisKind::Linear && t[i] != pos_[i]) linear = true;
    const double f = linear ? feed_mm_ : feed_deg_;
    if (!(f > 0))
      fail(ErrorKind::NoFeed, col,
           g_text(motion_) + " with feed F0 (" +
               (feed_reset_line_ ? "G94 on line " + std::to_string(feed_reset_line_) + " set it to 0" : std::string("none set yet?")) + ")",
           "an F word > 0 on this or an earlier line");
    return f / 60.0;
  }

  void move(const Pose& t) {
    const bool rapid = motion_ == 0;
    const double f = rapid ? rapid_ : feed_for(t, codes_[kMotion].code >= 0 ? codes_[kMotion].column : 1);
    emit(planner::Line{0, t, f}, rapid);
    pos_ = t;
  }

  void probe(const Pose& t, int col) {
    const double f = feed_for(t, col);
    emit(Probe{t, f, motion_ == 382});
    for (int i = 0; i < m_.count; ++i)  // where it trips is known at run time only
      if (t[i] != pos_[i] || word(m_.axes[i].letter).given) known_[i] = false;
    probe_line_ = line_;
    pos_ = t;
  }

  void arc(const Pose& t, int col) {
    const int ix = axis_index('X'), iy = axis_index('Y'), iz = axis_index('Z');
    if (ix < 0 || iy < 0 || iz < 0 || m_.axes[ix].kind != planner::AxisKind::Linear ||
        m_.axes[iy].kind != planner::AxisKind::Linear || m_.axes[iz].kind != planner::AxisKind::Linear)
      fail(ErrorKind::AxisNotOnMachine, col, g_text(motion_) + " on a machine with axes " + machine_axes(), "arcs on machines with linear X, Y and Z");
    // Plane coordinates (first, second) and the normal, as indices into X Y Z.
    int a1 = 0, a2 = 1, an = 2;
    if (plane_ == 18) a1 = 2, a2 = 0, an = 1;
    if (plane_ == 19) a1 = 1, a2 = 2, an = 0;
    const std::array<int, 3> idx{ix, iy, iz};
    const char offset_letter[3] = {'I', 'J', 'K'};
    const Word& r = word('R');
    const Word& off_n = word(offset_letter[an]);
    if (off_n.given) fail(ErrorKind::WordNotAllowed, off_n.column, word_text(off_n) + " in G" + std::to_string(plane_),
                          std::string("centre offsets ") + offset_letter[a1] + " " + offset_letter[a2] + " in G" + std::to_string(plane_));
    const Word& o1 = word(offset_letter[a1]);
    const Word& o2 = word(offset_letter[a2]);
    const bool ccw = motion_ == 30;
    const double s1 = pos_[idx[a1]], s2 = pos_[idx[a2]], e1 = t[idx[a1]], e2 = t[idx[a2]];
    if (!known_[idx[a1]] || !known_[idx[a2]] || !known_[idx[an]])
      fail(ErrorKind::PositionUnknown, col, g_text(motion_) + " after the probe on line " + std::to_string(probe_line_), "a G0/G1 in G90 naming the probed axes first");
    double c1 = 0, c2 = 0, spiral = 0;
    if (r.given) {
      if (o1.given || o2.given) fail(ErrorKind::WordNotAllowed, r.column, word_text(r) + " with centre offsets", "either R or centre offsets");
      const double R = r.value * unit();
      const double d = std::hypot(e1 - s1, e2 - s2);
      if (d < 1e-9) fail(ErrorKind::BadArc, r.column, word_text(r) + " with the end on the start", "R arcs with distinct ends (a full circle takes I/J/K)");
      if (d / 2 - std::fabs(R) > kArcRadiusTolerance)
        fail(ErrorKind::BadArc, r.column, word_text(r) + " for ends " + num(d / unit()) + " apart",
             "|R| >= half the distance between the ends (less " + num(kArcRadiusTolerance / unit()) + (inches_ ? " in" : " mm") + ", as LinuxCNC)");
      const double h = std::sqrt(std::max(0.0, R * R - d * d / 4));
      const double u1 = (e1 - s1) / d, u2 = (e2 - s2) / d;
      const double side = (ccw ? 1.0 : -1.0) * (R > 0 ? 1.0 : -1.0);
      c1 = (s1 + e1) / 2 - side * h * u2;
      c2 = (s2 + e2) / 2 + side * h * u1;
    } else {
      if (!o1.given && !o2.given)
        fail(ErrorKind::MissingWord, col, g_text(motion_) + " without centre", std::string(1, offset_letter[a1]) + "/" + offset_letter[a2] + " or R");
      c1 = s1 + (o1.given ? o1.value * unit() : 0);
      c2 = s2 + (o2.given ? o2.value * unit() : 0);
      const double r0 = std::hypot(s1 - c1, s2 - c2), r1 = std::hypot(e1 - c1, e2 - c2);
      if (r0 < kArcRadiusTolerance) fail(ErrorKind::BadArc, col, "centre on the start point", "a centre away from the start");
      if (r1 < kArcRadiusTolerance) fail(ErrorKind::BadArc, col, "centre on the end point", "a centre away from the end");
      if (!arc_ends_fit(r0, r1, inches_))
        fail(ErrorKind::BadArc, col, "end radius " + num(r1 / unit()) + " vs start radius " + num(r0 / unit()), arc_ends_rule(inches_));
      spiral = std::fabs(r1 - r0);
    }
    int turns = 0;
    if (const Word& p = word('P'); p.given) {
      const long n = std::lround(p.value);
      if (std::fabs(p.value - static_cast<double>(n)) > 1e-9 || n < 1 || n > 10000) fail(ErrorKind::BadValue, p.column, word_text(p), "P1 ... P10000 (turns)");
      turns = static_cast<int>(n - 1);
    }
    planner::Arc a;
    a.target = t;
    a.plane_axes = {static_cast<std::int8_t>(ix), static_cast<std::int8_t>(iy), static_cast<std::int8_t>(iz)};
    a.centre = {pos_[ix], pos_[iy], pos_[iz]};
    a.centre[a1] = c1;
    a.centre[a2] = c2;
    a.normal = {0, 0, 0};
    a.normal[an] = 1;
    a.ccw = ccw;
    a.turns = turns;
    a.feed = feed_for(t, col, true);
    if (spiral > 0) a.radius_tolerance = spiral * (1 + 1e-9) + 1e-9;  // a spiral LinuxCNC runs too
    emit(a);
    pos_ = t;
  }

  const GcodeOptions& o_;
  const planner::Machine& m_;
  std::vector<Item> items_;
  std::uint32_t next_id_ = 0;
  int line_ = 0;
  std::array<Word, 26> words_{};
  std::array<Code, kGroups> codes_{};
  Pose pos_{};
  std::array<bool, planner::kMaxAxes> known_{};
  int probe_line_ = 0;
  int motion_ = -1;  // code×10, -1: none yet
  int plane_ = 17;
  bool absolute_ = true, inches_ = false;
  int coord_ = 0;
  long tool_ = 0;                  // the last T
  std::array<Pose, kWorkOffsets> offsets_{};  // G54 ... G59.3: the caller's, as G10 changes them in this program
  Pose g92_{}, g92_kept_{};        // G92's offset in force; the one G92.2 suspended
  double feed_mm_ = 0, feed_deg_ = 0;  // the F speed: mm/min for linear moves, deg/min for rotary-only
  int feed_reset_line_ = 0;            // the last G94, which set F to 0
  bool cancel_line_ = false;           // G80 cancelled the motion mode
  bool started_ = false, percent_ = false;  // a line that is not blank came; the first was '%'
  std::vector<Note> notes_;
  std::vector<OffsetWrite> writes_;  // G10 L2 / L20
  std::vector<Frame> frames_;
  double speed_ = 0;
  bool speed_set_ = false;
  double rapid_ = 0;
  bool ended_ = false;
};
}  // namespace

Translation translate_gcode(std::string_view text, const GcodeOptions& options) {
  GcodeTranslator t(options);
  return translate_with(t, text);
}

}  // namespace imess::programs
