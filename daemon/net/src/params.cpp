// The parameter registry: one entry per name; Get lists them in this order.
#include "imess/net/params.hpp"

#include <array>
#include <cctype>
#include <cstdio>

#include "imess/net/motion_gateway.hpp"
#include "imess/protocol/numbers.hpp"
#include "imess/protocol/words.hpp"

namespace imess::net {
namespace {
using core::ParamId;

constexpr ParamSpec core_param(std::string_view name, std::string_view unit, double min, double max, double initial,
                               ParamId id, std::string_view config, std::string_view help) {
  ParamSpec p;
  p.name = name, p.unit = unit, p.min = min, p.max = max, p.initial = initial;
  p.home = ParamHome::Core, p.core_id = id, p.config = config, p.help = help;
  return p;
}
constexpr ParamSpec net_param(ParamSpec p, ParamHome home, bool read_only, int decimals, bool text = false) {
  p.home = home, p.read_only = read_only, p.decimals = decimals, p.text = text;
  return p;
}
constexpr ParamSpec plain(std::string_view name, std::string_view unit, double min, double max, double initial,
                          std::string_view config, std::string_view help) {
  ParamSpec p;
  p.name = name, p.unit = unit, p.min = min, p.max = max, p.initial = initial, p.config = config, p.help = help;
  return p;
}

// One component of the probe offset (Qualify sets all three with the tip radius).
constexpr ParamSpec probe_offset(std::string_view name, int axis, std::string_view config) {
  ParamSpec p = plain(name, "mm", -100, 100, 0, config,
                      "probe offset, added to every measured point (the ball centre seen from the machine's position)");
  p.home = ParamHome::ProbeOffset, p.axis = axis, p.decimals = 4;
  return p;
}

const std::array kParams{
    core_param("TipRadius", "mm", 0, 50, 2.0, ParamId::TipRadius, "motion.tip_radius",
               "probe ball radius used for compensation; 0 = none"),
    core_param("SpeedLevel", "", 0.01, 2, 1.0, ParamId::SpeedLevel, "motion.speed_level",
               "multiplier for every speed (1996: 0.1 ... 1.5)"),
    core_param("MaxSpeed", "mm/s", 0.1, 1000, 100, ParamId::MaxSpeed, "motion.max_speed", "speed of StartMv 100"),
    core_param("MaxAccel", "mm/s2", 1, 20000, 1000, ParamId::MaxAccel, "motion.max_accel", "acceleration of every move"),
    core_param("RetractDist", "mm", 0, 20, 0.5, ParamId::RetractDistance, "motion.retract_distance",
               "retract behind the latched point"),
    core_param("RetractSpeed", "mm/s", 0.1, 200, 10, ParamId::RetractSpeed, "motion.retract_speed", "speed of the retract"),
    core_param("RetractTime", "s", 0.1, 60, 5, ParamId::RetractTimeout, "motion.retract_timeout_s",
               "time for the tip to re-seat"),
    core_param("IdleOpen", "s", 0.1, kUnbounded, 7, ParamId::IdleOpenTime, "motion.idle_open_s",
               "loops open this long after the last stop"),
    core_param("GoToSpeed", "mm/s", 0.1, 1000, 50, ParamId::GoToSpeed, "motion.goto_speed", "GoTo speed when none is given"),
    core_param("HandTravel", "mm", 0.1, 50, 1.0, ParamId::HandMinTravel, "motion.hand_min_travel",
               "travel that gives a hand hit its direction"),
    core_param("HandInterval", "s", 0, 60, 1.0, ParamId::HandMinInterval, "motion.hand_min_interval_s",
               "minimum time between hand hits"),
    core_param("SearchDist", "mm", 0.1, 100, 10, ParamId::SearchDistance, "motion.search_distance",
               "probing: searched past the target before the part counts as not found"),
    core_param("PrehitDist", "mm", 0, 50, 2, ParamId::PrehitDistance, "motion.prehit_distance",
               "probing: before the target, where the touch speed is reached"),
    core_param("ProbeSpeed", "mm/s", 0.1, 50, 5, ParamId::ProbeSpeed, "motion.probe_speed", "probing: the touch speed"),
    probe_offset("ProbeOffX", 0, "motion.probe_offset_x"),
    probe_offset("ProbeOffY", 1, "motion.probe_offset_y"),
    probe_offset("ProbeOffZ", 2, "motion.probe_offset_z"),
    net_param(plain("ReportHz", "Hz", 0.1, 100, 10, "server.report_hz", "CurrCor broadcast rate (only when the position changed)"),
              ParamHome::ReportHz, false, 3),
    net_param(plain("Period", "us", 100, 100000, 1000, "motion.period_us", "the motion loop's period, from the configuration's motion.period_us"),
              ParamHome::LoopPeriod, true, 0),
    net_param(plain("Axes", "", 1, core::kMaxAxes, 3, "", "axes the motion loop drives (axes.letters)"),
              ParamHome::AxisCount, true, 0),
    net_param(plain("Backend", "", 0, 0, 0, "", "the machine behind the motion loop, from the configuration's backend.type"),
              ParamHome::Backend, true, 0, true),
};

std::string compact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::span<const ParamSpec> param_table() { return kParams; }

const ParamSpec* find_param(std::string_view name) {
  for (const auto& p : kParams)
    if (protocol::iequals(p.name, name)) return &p;
  return nullptr;
}

std::optional<double> parse_param_value(const ParamSpec& spec, std::string_view text, std::string& error) {
  auto v = protocol::parse_number(text);
  if (!v || *v < spec.min || *v > spec.max) {
    error = std::string(spec.name) + " takes a number from " + compact(spec.min) + " to " +
            (spec.max >= kUnbounded ? std::string("any") : compact(spec.max)) +
            (spec.unit.empty() ? "" : " " + std::string(spec.unit)) + ", got '" + std::string(text) + "'";
    return std::nullopt;
  }
  return v;
}

std::string param_text(const ParamSpec& spec, const ParamPlaces& at) {
  double v = 0;
  switch (spec.home) {
    case ParamHome::Core: v = core::param_value(at.motion.params(), spec.core_id); break;
    case ParamHome::ReportHz: v = at.report_hz; break;
    case ParamHome::LoopPeriod: v = at.period_us; break;
    case ParamHome::AxisCount: v = at.motion.config().layout.count; break;
    case ParamHome::Backend: return std::string(at.backend);
    case ParamHome::ProbeOffset: v = at.probe_offset[static_cast<std::size_t>(spec.axis)]; break;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", spec.decimals, v);
  return buf;
}

void store_param(const ParamSpec& spec, ParamPlaces& at, double value) {
  switch (spec.home) {
    case ParamHome::Core: at.motion.set_param(spec.core_id, value); break;  // the parameter lane: no ring slot
    case ParamHome::ReportHz: at.report_hz = value; break;
    case ParamHome::ProbeOffset: at.probe_offset[static_cast<std::size_t>(spec.axis)] = value; break;
    case ParamHome::LoopPeriod:
    case ParamHome::AxisCount:
    case ParamHome::Backend: break;  // read-only: Set refuses them before this
  }
}

}  // namespace imess::net
