// MRM translator: one word per line (after an optional N), every move incremental and on
// one axis, units converted to the planner's mm, degrees and per-second feeds.
#include "imess/programs/mrm.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "scanner.hpp"

namespace imess::programs {

namespace {
using namespace detail;

constexpr const char* kWords = "N F S X Y A B C M";

class MrmTranslator {
 public:
  explicit MrmTranslator(const MrmOptions& o) : o_(o), m_(o.machine) {
    planner::validate(m_);
    pos_ = o.start;
    // A B C: the letters given, else the machine's rotary axes in order (0: none left).
    int next = 0;
    for (int i = 0; i < m_.count && next < 3; ++i)
      if (m_.axes[i].kind == planner::AxisKind::Rotary) rotary_[next++] = m_.axes[i].letter;
    const char given[3] = {o.a_axis, o.b_axis, o.c_axis};
    for (int w = 0; w < 3; ++w)
      if (given[w]) rotary_[w] = given[w];
  }

  std::vector<Item> run(std::string_view text) {
    const auto lines = split_lines(text);
    for (std::size_t k = 0; k < lines.size() && !ended_; ++k) line(static_cast<int>(k + 1), lines[k]);
    return std::move(items_);
  }

 private:
  [[noreturn]] void fail(ErrorKind k, std::size_t i, std::string found, std::string accepted) const {
    raise(k, line_, static_cast<int>(i + 1), std::move(found), std::move(accepted));
  }
  void emit(Step step) {
    std::visit(
        [&](auto& x) {
          if constexpr (requires { x.id; }) x.id = ++next_id_;
        },
        step);
    items_.push_back(Item{line_, false, std::move(step)});
  }
  int index(char letter) const {
    for (int i = 0; i < m_.count; ++i)
      if (m_.axes[i].letter == letter) return i;
    return -1;
  }

  // Reads one word at s[i]: letter and number (blanks allowed between them).
  bool word(std::string_view s, std::size_t& i, char& letter, double& value, std::size_t& at) const {
    while (i < s.size() && is_blank(s[i])) ++i;
    if (i >= s.size()) return false;
    at = i;
    if (!is_letter(s[i])) fail(ErrorKind::BadCharacter, i, char_text(s, i), std::string("one word ") + kWords + ", after an optional N");
    letter = upper(s[i]);
    if (std::string_view(kWords).find(letter) == std::string_view::npos || letter == ' ')
      fail(ErrorKind::UnsupportedWord, i, std::string(1, letter), std::string("words ") + kWords);
    ++i;
    if (!scan_number(s, i, value)) {
      while (i < s.size() && is_blank(s[i])) ++i;
      fail(ErrorKind::BadNumber, at, std::string(1, letter) + " followed by " + char_text(s, i), std::string("a number after ") + letter);
    }
    return true;
  }

  void line(int number, std::string_view s) {
    line_ = number;
    std::size_t i = 0, at = 0;
    char L = 0;
    double v = 0;
    if (!word(s, i, L, v, at)) return;  // blank line
    if (L == 'N') {
      if (v < 0 || v != std::floor(v)) fail(ErrorKind::BadNumber, at, "N" + num(v), "N followed by a whole number >= 0");
      if (!word(s, i, L, v, at)) return;  // N alone
      if (L == 'N') fail(ErrorKind::TooManyWords, at, "a second N", "one N, then one word");
    }
    std::size_t rest = i;
    while (rest < s.size() && is_blank(s[rest])) ++rest;
    if (rest < s.size()) fail(ErrorKind::TooManyWords, rest, char_text(s, rest) + " after " + std::string(1, L) + num(v), "one word per line (after an optional N)");
    const std::string text = std::string(1, L) + num(v);
    switch (L) {
      case 'F':
      case 'S':
        if (!(v > 0)) fail(ErrorKind::BadValue, at, text, L == 'F' ? "F > 0 (mm/min)" : "S > 0 (degrees/min)");
        (L == 'F' ? feed_ : speed_) = v / 60.0;
        break;
      case 'M': {
        if (v == 2) {
          emit(End{});
          ended_ = true;
        } else if (v == 3 || v == 4) {
          emit(planner::SetOutput{0, o_.gripper_output, v == 3 ? 1.0 : 0.0});
        } else {
          fail(ErrorKind::UnsupportedCode, at, text, "M02 (end) M03 (gripper on) M04 (gripper off)");
        }
        break;
      }
      default: {  // X Y A B C: incremental moves in 0.1 mm / 0.1°
        if (v != std::floor(v)) fail(ErrorKind::BadNumber, at, text, std::string("a whole number of 0.1 ") + (L == 'X' || L == 'Y' ? "mm" : "degree"));
        const bool linear = L == 'X' || L == 'Y';
        const char axis = linear ? L : rotary_[L - 'A'];
        const int k = axis ? index(axis) : -1;
        if (k < 0)
          fail(ErrorKind::AxisNotOnMachine, at, text + (axis ? " (machine axis " + std::string(1, axis) + ")" : " (the machine has no rotary axis for it)"),
               "words for the machine's axes");
        const double feed = linear ? feed_ : speed_;
        if (!(feed > 0)) fail(ErrorKind::NoFeed, at, text + (linear ? " before any F" : " before any S"), linear ? "an F word (mm/min) before X/Y moves" : "an S word (degrees/min) before A/B/C moves");
        Pose t = pos_;
        t[k] += v / 10.0;
        if (o_.check_travel && (t[k] < m_.axes[k].travel_min || t[k] > m_.axes[k].travel_max))
          fail(ErrorKind::OutOfTravel, at, std::string(1, axis) + " at " + num(t[k]), std::string(1, axis) + " within " + num(m_.axes[k].travel_min) + " ... " + num(m_.axes[k].travel_max));
        emit(planner::Line{0, t, feed});
        pos_ = t;
      }
    }
  }

  const MrmOptions& o_;
  const planner::Machine& m_;
  std::vector<Item> items_;
  std::uint32_t next_id_ = 0;
  int line_ = 0;
  Pose pos_{};
  char rotary_[3] = {0, 0, 0};   // the machine axis of A, B, C (0: none)
  double feed_ = 0, speed_ = 0;  // mm/s, deg/s
  bool ended_ = false;
};
}  // namespace

Translation translate_mrm(std::string_view text, const MrmOptions& options) {
  MrmTranslator t(options);
  return translate_with(t, text);
}

}  // namespace imess::programs
