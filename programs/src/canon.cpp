// LinuxCNC's canonical calls for program items (rs274 -g's text).
#include "imess/programs/canon.hpp"

#include <cmath>
#include <cstdio>
#include <string_view>

namespace imess::programs {

namespace {
std::string f4(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return std::string(buf) == "-0.0000" ? "0.0000" : buf;
}

int index_of(const planner::Machine& m, char letter) {
  for (int i = 0; i < m.count; ++i)
    if (m.axes[i].letter == letter) return i;
  return -1;
}

// Machine value of axis i in the program frame: less the offset, linear axes in its unit.
double program_value(const Pose& p, int i, const planner::Machine& m, const Frame& f) {
  const double unit = f.inches && m.axes[i].kind == planner::AxisKind::Linear ? 25.4 : 1.0;
  return (p[i] - f.offset[i]) / unit;
}

std::string value_of(const Pose& p, char letter, const planner::Machine& m, const Frame& f) {
  const int i = index_of(m, letter);
  return f4(i < 0 ? 0.0 : program_value(p, i, m, f));
}

std::string xyzabc(const Pose& p, const planner::Machine& m, const Frame& f) {
  std::string s;
  for (char c : {'X', 'Y', 'Z', 'A', 'B', 'C'}) s += std::string(c == 'X' ? "" : ", ") + value_of(p, c, m, f);
  return s;
}

std::string arc_feed(const planner::Arc& a, const planner::Machine& m, const Frame& f) {
  // LinuxCNC names the plane's first and second axes and the axis along the normal:
  // G17 X Y (Z), G18 Z X (Y), G19 Y Z (X). Arcs from G-code keep plane_axes = X Y Z.
  int first = 0, second = 1, normal = 2;
  if (a.normal[1] != 0) first = 2, second = 0, normal = 1;
  if (a.normal[0] != 0) first = 1, second = 2, normal = 0;
  const auto& ax = a.plane_axes;
  auto centre = [&](int k) {
    Pose p{};
    p[ax[k]] = a.centre[k];
    return f4(program_value(p, ax[k], m, f));
  };
  const int rot = a.ccw ? 1 + a.turns : -1 - a.turns;
  std::string s = "ARC_FEED(" + f4(program_value(a.target, ax[first], m, f)) + ", " +
                  f4(program_value(a.target, ax[second], m, f)) + ", " + centre(first) + ", " + centre(second) + ", " +
                  std::to_string(rot) + ", " + f4(program_value(a.target, ax[normal], m, f));
  for (char c : {'A', 'B', 'C'}) s += ", " + value_of(a.target, c, m, f);
  return s + ")";
}

bool linear_moves(const Pose& from, const Pose& to, const planner::Machine& m) {
  for (int i = 0; i < m.count; ++i)
    if (m.axes[i].kind == planner::AxisKind::Linear && from[i] != to[i]) return true;
  return false;
}
}  // namespace

std::string canonical(const Item& item, const planner::Machine& m, const Frame& f) {
  if (const auto* l = std::get_if<planner::Line>(&item.step))
    return std::string(item.rapid ? "STRAIGHT_TRAVERSE(" : "STRAIGHT_FEED(") + xyzabc(l->target, m, f) + ")";
  if (const auto* h = std::get_if<Home>(&item.step)) return "STRAIGHT_TRAVERSE(" + xyzabc(h->target, m, f) + ")";
  if (const auto* p = std::get_if<Probe>(&item.step)) return "STRAIGHT_PROBE(" + xyzabc(p->target, m, f) + ")";
  if (const auto* d = std::get_if<planner::Dwell>(&item.step)) return "DWELL(" + f4(d->seconds) + ")";
  if (const auto* a = std::get_if<planner::Arc>(&item.step)) return arc_feed(*a, m, f);
  return {};
}

std::string canonical_program(const Translation& t, const planner::Machine& m, const Pose& start) {
  std::string out;
  Pose pos = start;
  int inches = -1;
  double rate = -1;  // program units (deg) per minute, as last printed
  auto frame_of = [&](const Item& it) { return it.frame < t.frames.size() ? t.frames[it.frame] : Frame{}; };
  auto units = [&](const Frame& f) {
    if (inches != static_cast<int>(f.inches))
      out += std::string("USE_LENGTH_UNITS(") + (f.inches ? "CANON_UNITS_INCHES" : "CANON_UNITS_MM") + ")\n";
    inches = f.inches;
  };
  units(t.frames.empty() ? Frame{} : t.frames.front());
  const char* plane = "CANON_PLANE_XY";
  for (const auto& it : t.items) {
    const Frame f = frame_of(it);
    units(f);
    Pose to = pos;
    double feed = 0;
    bool feed_move = false;
    if (const auto* l = std::get_if<planner::Line>(&it.step)) to = l->target, feed = l->feed, feed_move = !it.rapid;
    else if (const auto* a = std::get_if<planner::Arc>(&it.step)) to = a->target, feed = a->feed, feed_move = true;
    else if (const auto* p = std::get_if<Probe>(&it.step)) to = p->target, feed = p->feed, feed_move = true;
    else if (const auto* h = std::get_if<Home>(&it.step)) to = h->target;
    if (feed_move) {
      const bool lin = linear_moves(pos, to, m) || std::holds_alternative<planner::Arc>(it.step);
      const double r = feed * 60 / (lin && f.inches ? 25.4 : 1.0);
      if (std::fabs(r - rate) > 1e-9 * std::max(1.0, r)) out += "SET_FEED_RATE(" + f4(r) + ")\n";
      rate = r;
    }
    if (const auto* a = std::get_if<planner::Arc>(&it.step)) {
      const char* p = a->normal[1] != 0 ? "CANON_PLANE_XZ" : a->normal[0] != 0 ? "CANON_PLANE_YZ" : "CANON_PLANE_XY";
      if (std::string_view(p) != plane) out += std::string("SELECT_PLANE(") + p + ")\n";
      plane = p;
    }
    if (const std::string c = canonical(it, m, f); !c.empty()) out += c + "\n";
    if (const auto* p = std::get_if<Pause>(&it.step))
      out += p->reason == "M0" ? std::string("PROGRAM_STOP()\n") : "COMMENT(\"" + p->reason + ": pause for the operator\")\n";
    if (std::holds_alternative<End>(it.step)) out += "PROGRAM_END()\n";
    pos = to;
  }
  return out;
}

}  // namespace imess::programs
