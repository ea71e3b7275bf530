// The machine's axes on the MESSD wire: the 1996 X Y Z words mapped onto the configured axes,
// the named-axis jog (JogAx) and the Help words of the machine's letters.
#include <cstdio>

#include "imess/net/messd_dispatch.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "imess/protocol/verbs.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;

namespace {
constexpr double kMaxPercent = 100;

std::string spaced(const hal::AxisLayout& l) {
  std::string s;
  for (int a = 0; a < l.count; ++a) s += (a ? " " : "") + std::string(1, l.letters[a]);
  return s;
}
}  // namespace

std::string MessdDispatch::no_axis_text(char letter) const {
  return std::string("this machine has no axis ") + letter + "; its axes are " + spaced(layout());
}

// StartMv / GoTo / HandMv x y z: onto the machine's linear X Y Z axes. A non-zero value for a
// Cartesian axis the machine lacks is refused (its coordinate reads 0 in CurrCor).
bool MessdDispatch::machine_vector(Session& s, std::uint32_t slot, const protocol::Xyz& p, core::AxisVec& out,
                            unsigned& given) {
  const double xyz[3] = {p.x, p.y, p.z};
  out = core::AxisVec::Zero();
  given = 0;
  for (int c = 0; c < 3; ++c) {
    const int a = layout().cartesian_axis(c);
    if (a < 0) {
      if (xyz[c] != 0) {
        reply(s, slot, format_err(ErrorCode::BadValue, no_axis_text("XYZ"[c]) + "; give 0 for " + "XYZ"[c]));
        return false;
      }
      continue;
    }
    out[a] = xyz[c];
    given |= 1u << a;
  }
  return true;
}

// Every axis word names an axis of this machine, else Err 105 naming it.
bool MessdDispatch::axes_known(Session& s, std::uint32_t slot, const protocol::PathWords& w) {
  for (char letter : hal::kAxisLetters)
    if (w.axis(letter)->has_value() && layout().index_of(letter) < 0) {
      reply(s, slot, format_err(ErrorCode::BadValue, no_axis_text(letter)));
      return false;
    }
  return true;
}

// JogAx C20 U-10: a StartMv of the named axes (the others stand), each within ±100 %.
void MessdDispatch::jog_axes(Session& s, std::uint32_t slot, const protocol::JogAx& c) {
  if (!axes_known(s, slot, c.percent)) return;
  core::Command cmd{core::CommandKind::JogAx};
  for (int a = 0; a < layout().count; ++a) {
    const auto& word = *c.percent.axis(layout().letters[a]);
    if (!word) continue;
    if (*word < -kMaxPercent || *word > kMaxPercent) {
      char got[48];
      std::snprintf(got, sizeof got, "%c%g", layout().letters[a], *word);
      reply(s, slot, format_err(ErrorCode::BadValue, std::string("JogAx speeds are percent of MaxSpeed, -100 to 100, got ") + got));
      return;
    }
    cmd.v[a] = *word;
  }
  to_core(s, slot, cmd);
}

// Help as this machine takes it: on the X Y Z machine the 1996 list; on another, MoveTo's
// words are its letters and JogAx is listed.
std::string MessdDispatch::machine_help_line(const protocol::VerbSpec& v) const {
  std::string line = protocol::help_line(v);
  if (layout().is_xyz()) return v.name == "JogAx" ? std::string() : line;
  const std::string declared = v.name == "MoveTo" ? "X.. Y.. Z.." : v.name == "JogAx" ? "X.. Y.. C.." : "";
  if (declared.empty()) return line;
  if (auto at = line.find(declared); at != std::string::npos) {
    std::string words;
    for (int a = 0; a < layout().count; ++a) words += (a ? " " : "") + std::string(1, layout().letters[a]) + "..";
    line.replace(at, declared.size(), words);
  }
  return line;
}

}  // namespace imess::net
