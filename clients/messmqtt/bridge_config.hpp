// messmqtt's settings: the "mqtt" section of messd's own configuration file (docs/mqtt.md,
// "Configuration"), overridden by the command line. Unknown keys and wrong forms are refused
// naming the file, the key and what is accepted (client::UsageError, exit 2).
#pragma once
#include <string>

#include "imess/client/endpoint.hpp"

namespace imess::mqtt {

inline constexpr std::uint16_t kDefaultBrokerPort = 1883;
inline constexpr std::uint16_t kDefaultTlsBrokerPort = 8883;

struct BridgeConfig {
  client::Endpoint messd;        // server.port of the file, or HOST[:PORT] on the command line
  client::Endpoint broker{"localhost", kDefaultBrokerPort};
  std::string machine;           // the topic level imess/<machine>/...
  std::string user;              // broker credentials: never logged
  std::string password_file;     // its first line is the password
  std::string tls_ca;            // CA certificate file: TLS to the broker when given
  bool allow_stop = false;       // imess/<machine>/cmd/stop stops the machine
  std::string state_file;        // the acknowledged seq; default beside the journal
  bool help = false;
};

// Reads the command line, and the configuration file it names (--config FILE). Throws
// client::UsageError.
BridgeConfig parse_bridge_options(int argc, const char* const argv[]);
// The "mqtt" section (and server.port) of a configuration text read from `path`, into `cfg`.
void load_bridge_config_text(const std::string& text, const std::string& path, BridgeConfig& cfg);
std::string bridge_usage();

// The password file's first line (without its line end). Throws client::UsageError naming
// the file (never its content).
std::string read_password(const std::string& path);

}  // namespace imess::mqtt
