// The parameter registry: the core's table (core_params.hpp) and the io side's own entries.
#include "imess/net/params.hpp"

#include <array>
#include <cctype>
#include <cstdio>

#include "imess/net/motion_gateway.hpp"
#include "imess/protocol/numbers.hpp"
#include "imess/protocol/words.hpp"

namespace imess::net {
namespace {

// A core parameter: its row of the core's table (imess/core/core_params.hpp).
constexpr ParamSpec core_param(const core::CoreParamSpec& c) {
  ParamSpec p;
  p.name = c.name, p.unit = c.unit, p.min = c.min, p.max = c.max, p.initial = c.initial();
  p.home = ParamHome::Core, p.core_id = c.id, p.config = c.config, p.help = c.help;
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

// The parameters that do not live in the motion loop.
constexpr std::array kOtherParams{
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

// Get lists them in this order: the core's table, then the others.
constexpr auto kParams = [] {
  std::array<ParamSpec, core::kCoreParams.size() + kOtherParams.size()> all{};
  std::size_t i = 0;
  for (const auto& c : core::kCoreParams) all[i++] = core_param(c);
  for (const auto& p : kOtherParams) all[i++] = p;
  return all;
}();

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
