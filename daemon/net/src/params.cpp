// Parameter table: one entry per name; Get lists them in this order.
#include "imess/net/params.hpp"

#include <array>
#include <cctype>
#include <cstdio>

#include "imess/protocol/numbers.hpp"

namespace imess::net {
namespace {
using core::ParamId;
constexpr double kBig = 1e9;
const std::array kParams{
    ParamSpec{"TipRadius", "mm", 0, 50, ParamId::TipRadius, false, "probe ball radius used for compensation; 0 = none"},
    ParamSpec{"SpeedLevel", "", 0.01, 2, ParamId::SpeedLevel, false, "multiplier for every speed (1996: 0.1 ... 1.5)"},
    ParamSpec{"MaxSpeed", "mm/s", 0.1, 1000, ParamId::MaxSpeed, false, "speed of StartMv 100"},
    ParamSpec{"MaxAccel", "mm/s2", 1, 20000, ParamId::MaxAccel, false, "acceleration of every move"},
    ParamSpec{"RetractDist", "mm", 0, 20, ParamId::RetractDistance, false, "retract behind the latched point"},
    ParamSpec{"RetractSpeed", "mm/s", 0.1, 200, ParamId::RetractSpeed, false, "speed of the retract"},
    ParamSpec{"RetractTime", "s", 0.1, 60, ParamId::RetractTimeout, false, "time for the tip to re-seat"},
    ParamSpec{"IdleOpen", "s", 0.1, kBig, ParamId::IdleOpenTime, false, "loops open this long after the last stop"},
    ParamSpec{"GoToSpeed", "mm/s", 0.1, 1000, ParamId::GoToSpeed, false, "GoTo speed when none is given"},
    ParamSpec{"HandTravel", "mm", 0.1, 50, ParamId::HandMinTravel, false, "travel that gives a hand hit its direction"},
    ParamSpec{"HandInterval", "s", 0, 60, ParamId::HandMinInterval, false, "minimum time between hand hits"},
    ParamSpec{"ReportHz", "Hz", 0.1, 100, std::nullopt, false, "CurrCor broadcast rate (only when the position changed)"},
};

std::string compact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}
}  // namespace

std::span<const ParamSpec> param_table() { return kParams; }

const ParamSpec* find_param(std::string_view name) {
  for (const auto& p : kParams)
    if (iequals(p.name, name)) return &p;
  return nullptr;
}

std::optional<double> parse_param_value(const ParamSpec& spec, std::string_view text, std::string& error) {
  auto v = protocol::parse_number(text);
  if (!v || *v < spec.min || *v > spec.max) {
    error = std::string(spec.name) + " takes a number from " + compact(spec.min) + " to " +
            (spec.max >= kBig ? std::string("any") : compact(spec.max)) +
            (spec.unit.empty() ? "" : " " + std::string(spec.unit)) + ", got '" + std::string(text) + "'";
    return std::nullopt;
  }
  return v;
}

}  // namespace imess::net
