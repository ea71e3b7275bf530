// The language of a file, one translate() for the three, and the dry run through the planner.
#include "imess/programs/check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "imess/planner/probe.hpp"

namespace imess::programs {

namespace {
std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The kind of a planner refusal in the words of the translators' errors (docs/programs.md).
const char* plan_kind(planner::PlanError e) {
  switch (e) {
    case planner::PlanError::OutOfTravel: return kind_name(ErrorKind::OutOfTravel);
    case planner::PlanError::BadFeed:
    case planner::PlanError::BadPose:
    case planner::PlanError::BadDwell: return kind_name(ErrorKind::BadValue);
    case planner::PlanError::ProbeNoDirection: return "probe without direction";
    default: return kind_name(ErrorKind::BadArc);
  }
}

// The bounding box grows by a segment: its ends, and for an arc each plane axis' extremes,
// where its derivative along the circle (or helix) is zero: x_k(θ) = c_k + r·m·cos(θ − α) +
// n_k·h·θ/φ, so sin(θ − α) = n_k·h / (φ·r·m). Exact for circles and helices.
void extend_box(Check& c, const planner::PlannedSegment& seg, const planner::Machine& machine) {
  Pose p{}, d{};
  auto take = [&](double s) {
    planner::pose_at(seg, s, p, d);
    for (int a = 0; a < machine.count; ++a) {
      c.low[a] = std::min(c.low[a], p[a]);
      c.high[a] = std::max(c.high[a], p[a]);
    }
  };
  take(0);
  take(seg.length);
  if (seg.kind != planner::SegmentKind::Arc) return;
  constexpr double kTwoPi = 6.283185307179586;
  const auto& g = seg.arc;
  const double r = 0.5 * (g.r0 + g.r1);
  if (!(std::abs(g.phi) > 0) || !(r > 0)) return;
  const double lo = std::min(0.0, g.phi), hi = std::max(0.0, g.phi);
  for (int k = 0; k < 3; ++k) {
    const double m = std::hypot(g.e1[k], g.e2[k]);
    if (m < 1e-12) continue;
    const double q = g.n[k] * g.h / (g.phi * r * m);
    if (std::abs(q) > 1) continue;
    const double alpha = std::atan2(g.e2[k], g.e1[k]);
    for (double base : {alpha + std::asin(q), alpha + kTwoPi / 2 - std::asin(q)}) {
      for (double th = base - kTwoPi * std::ceil((base - lo) / kTwoPi); th <= hi; th += kTwoPi)
        if (th >= lo) take(th / g.phi * seg.length);
    }
  }
}

double fastest_axis(const planner::Machine& m) {
  double v = 0;
  for (int i = 0; i < m.count; ++i) v = std::max(v, m.axes[i].max_velocity);
  return v;
}
}  // namespace

std::optional<Language> language_of(std::string_view file_name) {
  const auto dot = file_name.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const std::string ext = lower(file_name.substr(dot));
  if (ext == ".nc" || ext == ".ngc" || ext == ".gcode" || ext == ".tap") return Language::Gcode;
  if (ext == ".plt" || ext == ".hpgl") return Language::Hpgl;
  if (ext == ".mrm") return Language::Mrm;
  return std::nullopt;
}

std::optional<Language> language_named(std::string_view word) {
  const std::string w = lower(word);
  if (w == "gcode") return Language::Gcode;
  if (w == "hpgl") return Language::Hpgl;
  if (w == "mrm") return Language::Mrm;
  return std::nullopt;
}

const char* language_name(Language lang) {
  switch (lang) {
    case Language::Gcode: return "gcode";
    case Language::Hpgl: return "hpgl";
    case Language::Mrm: return "mrm";
  }
  return "?";
}

Translation translate(Language lang, std::string_view text, const Setup& setup) {
  switch (lang) {
    case Language::Gcode: {
      GcodeOptions o = setup.gcode;
      o.machine = setup.machine;
      o.start = setup.start;
      return translate_gcode(text, o);
    }
    case Language::Hpgl: {
      HpglOptions o = setup.hpgl;
      o.machine = setup.machine;
      o.start = setup.start;
      return translate_hpgl(text, o);
    }
    case Language::Mrm: {
      MrmOptions o = setup.mrm;
      o.machine = setup.machine;
      o.start = setup.start;
      return translate_mrm(text, o);
    }
  }
  return {};
}

std::optional<planner::Request> request_of(const Item& item, std::uint32_t id, const Pose& from,
                                           const planner::Machine& machine, double rapid_feed) {
  return std::visit(
      [&](const auto& s) -> std::optional<planner::Request> {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, planner::Line> || std::is_same_v<T, planner::Arc> ||
                      std::is_same_v<T, planner::Dwell> || std::is_same_v<T, planner::SetOutput>) {
          T r = s;
          r.id = id;
          return r;
        } else if constexpr (std::is_same_v<T, Probe>) {
          // G38.2/.3: the whole move is the search, at the program's feed; a miss ends at the target.
          const planner::ProbeGeometry g{std::numeric_limits<double>::infinity(), 0, s.feed, s.feed};
          const auto cycle = planner::probe_cycle(id, from, s.target, g);
          if (!cycle) return planner::Line{id, s.target, s.feed, planner::ProbePhase::Search};  // refused: no direction
          return cycle->search;
        } else if constexpr (std::is_same_v<T, Home>) {
          return planner::Line{id, s.target, rapid_feed > 0 ? rapid_feed : fastest_axis(machine)};
        } else {
          return std::nullopt;  // Pause, End
        }
      },
      item.step);
}

Check check_items(const std::vector<Item>& items, const planner::Machine& machine,
                  const planner::PlannerOptions& options, const Pose& start, double rapid_feed,
                  const SegmentVisitor& visit) {
  Check c;
  c.blocks = items.size();
  c.low = c.high = start;
  planner::Planner dry(machine, options);
  dry.set_position(start);
  planner::PlannedSegment seg;
  auto drain = [&] {
    while (dry.take(seg)) {
      const Item& item = items.at(seg.id - 1);
      ++c.segments;
      c.time += seg.duration();
      if (seg.kind == planner::SegmentKind::Line || seg.kind == planner::SegmentKind::Arc) {
        c.length += seg.length;
        if (seg.probe != planner::ProbePhase::None) c.probe_length += seg.length;
        else if (item.rapid) c.rapid_length += seg.length;
        else c.feed_length += seg.length;
        if (seg.length > 0) {
          extend_box(c, seg, machine);
          c.moves = true;
        }
      }
      if (visit) visit(seg, item);
    }
  };
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Item& item = items[i];
    if (std::holds_alternative<End>(item.step)) break;
    if (std::holds_alternative<Pause>(item.step)) {
      dry.flush();
      drain();
      continue;
    }
    const auto req = request_of(item, item_id(i), dry.position(), machine, rapid_feed);
    if (!req) continue;
    const bool probe = std::holds_alternative<Probe>(item.step);
    if (probe && !planner::probe_cycle(item_id(i), dry.position(), std::get<Probe>(item.step).target, {1, 0, 1, 1})) {
      c.ok = false;
      c.error_line = item.line;
      c.error = "line " + std::to_string(item.line) + ":1: probe without direction: found a target on the start, accepted a target " +
                std::to_string(planner::kMinProbeTravel) + " mm away or more";
      break;
    }
    if (const auto r = dry.append(*req); !r.ok()) {
      c.ok = false;
      c.error_line = item.line;
      const std::string why = planner::describe(r, machine);  // "segment N: <why>"
      c.error = "line " + std::to_string(item.line) + ":1: " + plan_kind(r.error) + ": " + why.substr(why.find(": ") + 2);
      break;
    }
    if (probe) dry.flush();  // the machine stops at the hit (or at the target): a probe ends at rest
    drain();
  }
  if (c.ok) {
    dry.flush();
    drain();
  }
  return c;
}

std::size_t line_count(std::string_view text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + (!text.empty() && text.back() != '\n' ? 1 : 0);
}

Check check_program(Language lang, std::string_view text, const Setup& setup, const planner::PlannerOptions& options,
                    const SegmentVisitor& visit) {
  Check c;
  c.lines = line_count(text);
  const Translation t = translate(lang, text, setup);
  if (!t.ok) {
    c.ok = false;
    c.error = t.error.message();
    c.error_line = t.error.line;
    c.low = c.high = setup.start;
    return c;
  }
  const double rapid = lang == Language::Gcode ? setup.gcode.rapid_feed : lang == Language::Hpgl ? setup.hpgl.rapid_feed : 0;
  Check r = check_items(t.items, setup.machine, options, setup.start, rapid, visit);
  r.lines = c.lines;
  r.notes = t.notes;
  r.offset_writes = t.offset_writes;
  return r;
}

}  // namespace imess::programs
