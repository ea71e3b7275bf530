// The configuration keys of runtime parameters: read with the ranges of the parameter
// registry (imess/net/params.hpp), so a range is written once for Set and the configuration.
#pragma once
#include <string>

#include "imess/net/params.hpp"
#include "json_object.hpp"  // JsonObject, ConfigError

namespace imess::app {

struct DaemonConfig;  // config.hpp

// Where the configuration keeps a parameter's start value; null for ones it cannot set.
double* config_place(const net::ParamSpec& spec, DaemonConfig& cfg);

// Reads every registry parameter whose key lies in `section` ("motion" for "motion.tip_radius").
void read_param_keys(JsonObject& o, const std::string& section, DaemonConfig& cfg);

// The messdrc line `<WireName> <value>` for a settable parameter (SpeedLevel, TipRadius):
// its registry entry's range; throws ConfigError with `at` (file:line) otherwise.
double messdrc_number(const net::ParamSpec& spec, const std::string& value, bool extra, const std::string& at);

}  // namespace imess::app
