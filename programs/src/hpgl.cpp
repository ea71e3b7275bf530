// HPGL translator: two-letter instructions with comma/space separated parameters, ended by
// ';' or the next instruction; plotter units (40 per mm) held exactly and scaled per move.
#include "imess/programs/hpgl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scanner.hpp"

namespace imess::programs {

namespace {
using namespace detail;

constexpr const char* kInstructions = "IN SP PU PD PA PR VS";

struct Param {
  double value = 0;
  std::size_t at = 0;
};

class HpglTranslator {
 public:
  explicit HpglTranslator(const HpglOptions& o) : o_(o), m_(o.machine) {
    planner::validate(m_);
    ix_ = index('X');
    iy_ = index('Y');
    iz_ = index('Z');
    if (ix_ < 0 || iy_ < 0) throw std::invalid_argument("HpglOptions::machine: needs axes X and Y");
    if (o.pen == HpglOptions::Pen::ZMove && iz_ < 0) throw std::invalid_argument("HpglOptions::pen ZMove: the machine needs axis Z");
    if (!(o.units_per_mm > 0) || !(o.feed > 0) || !(o.pen_feed > 0)) throw std::invalid_argument("HpglOptions: units_per_mm, feed and pen_feed must be > 0");
    rapid_ = o.rapid_feed;
    if (!(rapid_ > 0))
      for (int i = 0; i < m_.count; ++i) rapid_ = std::max(rapid_, m_.axes[i].max_velocity);
    pos_ = o.start;
    px_ = (pos_[ix_] - o.origin_x) * o.units_per_mm;
    py_ = (pos_[iy_] - o.origin_y) * o.units_per_mm;
    feed_ = o.feed;
  }

  std::vector<Item> run(std::string_view text) {
    text_ = text;
    line_starts_.assign(1, 0);
    for (std::size_t k = 0; k < text.size(); ++k)
      if (text[k] == '\n') line_starts_.push_back(k + 1);
    std::size_t i = 0;
    for (;;) {
      while (i < text.size() && (is_space(text[i]) || text[i] == ';')) ++i;
      if (i >= text.size()) break;
      const std::size_t at = i;
      if (!is_letter(text[i]) || i + 1 >= text.size() || !is_letter(text[i + 1]))
        fail(ErrorKind::BadCharacter, at, char_text(text, is_letter(text[i]) ? i + 1 : i), std::string("an instruction ") + kInstructions);
      const std::string mn{upper(text[i]), upper(text[i + 1])};
      if (std::string_view(kInstructions).find(mn) == std::string_view::npos || mn.find(' ') != std::string::npos)
        fail(ErrorKind::UnsupportedCode, at, mn, kInstructions);
      i += 2;
      std::vector<Param> params;
      for (;;) {
        while (i < text.size() && (is_space(text[i]) || text[i] == ',')) ++i;
        if (i >= text.size() || text[i] == ';' || is_letter(text[i])) break;
        Param p{0, i};
        if (!scan_number(text, i, p.value, false))
          fail(ErrorKind::BadNumber, i, char_text(text, i), "numbers separated by ',' or spaces, ended by ';'");
        params.push_back(p);
      }
      instruction(mn, at, params);
    }
    return std::move(items_);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  int index(char letter) const {
    for (int i = 0; i < m_.count; ++i)
      if (m_.axes[i].letter == letter) return i;
    return -1;
  }
  // Line and column (1-based) of text offset `at`.
  std::pair<int, int> where(std::size_t at) const {
    const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), at);
    const std::size_t line = static_cast<std::size_t>(next - line_starts_.begin());
    return {static_cast<int>(line), static_cast<int>(at - line_starts_[line - 1] + 1)};
  }
  [[noreturn]] void fail(ErrorKind k, std::size_t at, std::string found, std::string accepted) const {
    const auto [line, col] = where(at);
    raise(k, line, col, std::move(found), std::move(accepted));
  }
  void emit(Step step, std::size_t at, bool rapid = false) {
    std::visit(
        [&](auto& x) {
          if constexpr (requires { x.id; }) x.id = ++next_id_;
        },
        step);
    items_.push_back(Item{where(at).first, rapid, std::move(step)});
  }

  void check(const Pose& t, std::size_t at) const {
    if (!o_.check_travel) return;
    for (int i = 0; i < m_.count; ++i) {
      const auto& a = m_.axes[i];
      if (t[i] < a.travel_min || t[i] > a.travel_max)
        fail(ErrorKind::OutOfTravel, at, std::string(1, a.letter) + " at " + num(t[i]) + " (machine)",
             std::string(1, a.letter) + " within " + num(a.travel_min) + " ... " + num(a.travel_max));
    }
  }

  void pen(bool down, std::size_t at) {
    if (pen_known_ && pen_down_ == down) return;
    pen_known_ = true;
    pen_down_ = down;
    if (o_.pen == HpglOptions::Pen::Output) {
      emit(planner::SetOutput{0, o_.pen_output, down ? 1.0 : 0.0}, at);
      return;
    }
    Pose t = pos_;
    t[iz_] = down ? o_.pen_down_z : o_.pen_up_z;
    check(t, at);
    emit(planner::Line{0, t, down ? o_.pen_feed : rapid_}, at, !down);
    pos_ = t;
  }

  void moves(const std::string& mn, const std::vector<Param>& ps) {
    if (ps.size() % 2 != 0)
      fail(ErrorKind::BadValue, ps.back().at, mn + " with " + std::to_string(ps.size()) + " coordinates", "x,y pairs (an even number of coordinates)");
    for (std::size_t k = 0; k < ps.size(); k += 2) {
      if (!pen_known_) pen(false, ps[k].at);
      px_ = relative_ ? px_ + ps[k].value : ps[k].value;
      py_ = relative_ ? py_ + ps[k + 1].value : ps[k + 1].value;
      Pose t = pos_;
      t[ix_] = o_.origin_x + px_ / o_.units_per_mm;
      t[iy_] = o_.origin_y + py_ / o_.units_per_mm;
      check(t, ps[k].at);
      emit(planner::Line{0, t, pen_down_ ? feed_ : rapid_}, ps[k].at, !pen_down_);
      pos_ = t;
    }
  }

  void instruction(const std::string& mn, std::size_t at, const std::vector<Param>& ps) {
    auto at_most = [&](std::size_t n, const char* accepted) {
      if (ps.size() > n) fail(ErrorKind::BadValue, ps[n].at, mn + " with " + std::to_string(ps.size()) + " parameters", accepted);
    };
    if (mn == "IN") {
      at_most(0, "IN without parameters");
      relative_ = false;
      feed_ = o_.feed;
      pen(false, at);
    } else if (mn == "SP") {
      at_most(1, "SP or SP<pen 0..8>");
      if (!ps.empty()) {
        const double v = ps[0].value;
        if (v != std::floor(v) || v < 0 || v > 8) fail(ErrorKind::BadValue, ps[0].at, "SP" + num(v), "SP0 ... SP8");
        if (v == 0) pen(false, at);
      }
    } else if (mn == "PU" || mn == "PD") {
      pen(mn == "PD", at);
      moves(mn, ps);
    } else if (mn == "PA" || mn == "PR") {
      relative_ = mn == "PR";
      moves(mn, ps);
    } else {  // VS
      at_most(1, "VS or VS<cm/s>");
      if (ps.empty()) {
        feed_ = o_.feed;
      } else {
        if (!(ps[0].value > 0)) fail(ErrorKind::BadValue, ps[0].at, "VS" + num(ps[0].value), "VS > 0 (cm/s)");
        feed_ = ps[0].value * 10;  // cm/s → mm/s
      }
    }
  }

  const HpglOptions& o_;
  const planner::Machine& m_;
  std::string_view text_;
  std::vector<std::size_t> line_starts_;
  std::vector<Item> items_;
  std::uint32_t next_id_ = 0;
  int ix_ = -1, iy_ = -1, iz_ = -1;
  Pose pos_{};
  double px_ = 0, py_ = 0;  // plotter units
  double feed_ = 0, rapid_ = 0;
  bool relative_ = false, pen_known_ = false, pen_down_ = false;
};
}  // namespace

Translation translate_hpgl(std::string_view text, const HpglOptions& options) {
  HpglTranslator t(options);
  return translate_with(t, text);
}

}  // namespace imess::programs
