// Error text and the one-line description of items.
#include "imess/programs/program.hpp"

#include <cstdio>

#include "scanner.hpp"

namespace imess::programs {

using detail::num;

const char* kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::BadCharacter: return "bad character";
    case ErrorKind::BadNumber: return "bad number";
    case ErrorKind::UnsupportedWord: return "unsupported word";
    case ErrorKind::UnsupportedCode: return "unsupported code";
    case ErrorKind::ModalConflict: return "two words of one modal group";
    case ErrorKind::RepeatedWord: return "repeated word";
    case ErrorKind::AxisNotOnMachine: return "axis not on this machine";
    case ErrorKind::MissingWord: return "missing word";
    case ErrorKind::NoFeed: return "no feed rate";
    case ErrorKind::BadValue: return "value out of range";
    case ErrorKind::BadArc: return "bad arc";
    case ErrorKind::NotConfigured: return "not configured";
    case ErrorKind::WordNotAllowed: return "word not allowed here";
    case ErrorKind::UnterminatedComment: return "unterminated comment";
    case ErrorKind::PositionUnknown: return "position known only at run time";
    case ErrorKind::OutOfTravel: return "out of travel";
    case ErrorKind::TooManyWords: return "more than one word on a line";
  }
  return "error";
}

std::string Error::message() const {
  return "line " + std::to_string(line) + ":" + std::to_string(column) + ": " + kind_name(kind) + ": found " + found +
         ", accepted " + accepted;
}

namespace {
std::string pose_text(const Pose& p, const planner::Machine& m) {
  std::string s;
  for (int i = 0; i < m.count; ++i) s += std::string(i ? " " : "") + m.axes[i].letter + num(p[i]);
  return s;
}
template <class T>
std::string triple(const std::array<T, 3>& a) {
  return num(a[0]) + "," + num(a[1]) + "," + num(a[2]);
}
}  // namespace

std::string describe(const Item& item, const planner::Machine& m) {
  std::string s = std::to_string(item.line) + " ";
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, planner::Line>) {
          s += std::string("LINE ") + (item.rapid ? "rapid " : "") + pose_text(x.target, m) + " F" + num(x.feed);
        } else if constexpr (std::is_same_v<T, planner::Arc>) {
          s += std::string("ARC ") + (x.ccw ? "ccw " : "cw ") + pose_text(x.target, m) + " C" + triple(x.centre) + " N" +
               triple(x.normal) + " P" + std::to_string(x.plane_axes[0]) + "," + std::to_string(x.plane_axes[1]) +
               "," + std::to_string(x.plane_axes[2]) + " T" + std::to_string(x.turns) + " F" + num(x.feed);
        } else if constexpr (std::is_same_v<T, planner::Dwell>) {
          s += "DWELL " + num(x.seconds);
        } else if constexpr (std::is_same_v<T, planner::SetOutput>) {
          s += "OUT " + std::to_string(x.output) + "=" + num(x.value);
        } else if constexpr (std::is_same_v<T, Probe>) {
          s += "PROBE " + pose_text(x.target, m) + " F" + num(x.feed) + (x.error_on_miss ? " error" : " silent");
        } else if constexpr (std::is_same_v<T, Home>) {
          s += "HOME " + pose_text(x.target, m);
        } else if constexpr (std::is_same_v<T, Pause>) {
          s += x.reason == "M0" ? std::string("PAUSE") : "PAUSE " + x.reason;
        } else {
          s += "END";
        }
      },
      item.step);
  return s;
}

Pose end_pose(const std::vector<Item>& items, const Pose& start) {
  Pose p = start;
  for (const auto& it : items) {
    if (const auto* l = std::get_if<planner::Line>(&it.step)) p = l->target;
    else if (const auto* a = std::get_if<planner::Arc>(&it.step)) p = a->target;
    else if (const auto* pr = std::get_if<Probe>(&it.step)) p = pr->target;
    else if (const auto* h = std::get_if<Home>(&it.step)) p = h->target;
  }
  return p;
}

}  // namespace imess::programs
