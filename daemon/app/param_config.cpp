// Runtime parameters in the configuration: keys and ranges from the parameter registry.
#include "param_config.hpp"

#include "config.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::app {

double* config_place(const net::ParamSpec& spec, DaemonConfig& cfg) {
  switch (spec.home) {
    case net::ParamHome::Core: return &core::param_ref(cfg.core.params, spec.core_id);
    case net::ParamHome::ReportHz: return &cfg.server.report_hz;
    case net::ParamHome::ProbeOffset: return &cfg.server.probe_offset[static_cast<std::size_t>(spec.axis)];
    case net::ParamHome::LoopPeriod: return &cfg.period_us;
    case net::ParamHome::AxisCount:
    case net::ParamHome::Backend: return nullptr;
  }
  return nullptr;
}

void read_param_keys(JsonObject& o, const std::string& section, DaemonConfig& cfg) {
  const std::string prefix = section + ".";
  for (const auto& spec : net::param_table()) {
    if (spec.config.substr(0, prefix.size()) != prefix) continue;
    double* place = config_place(spec, cfg);
    if (!place) continue;
    *place = o.number(std::string(spec.config.substr(prefix.size())), *place, spec.min, spec.max);
  }
}

double messdrc_number(const net::ParamSpec& spec, const std::string& value, bool extra, const std::string& at) {
  auto v = protocol::parse_number(value);
  if (!v || *v < spec.min || *v > spec.max || extra)
    throw ConfigError(at + std::string(spec.name) + " takes one number from " + compact(spec.min) + " to " +
                      compact(spec.max) + ", got '" + value + "'");
  return *v;
}

}  // namespace imess::app
