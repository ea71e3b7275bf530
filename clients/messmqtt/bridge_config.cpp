// The "mqtt" section and messmqtt's command line (bridge_config.hpp).
#include "bridge_config.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "imess/client/usage_error.hpp"
#include "imess/jsontext/strict_json.hpp"
#include "topics.hpp"

namespace imess::mqtt {

namespace {

using client::UsageError;

const char* const kMqttKeys = "broker, machine, user, password_file, tls_ca, allow_stop, state_file, _comment";

std::string text_key(const nlohmann::json& o, const std::string& path, const char* key) {
  if (!o.contains(key)) return {};
  if (!o.at(key).is_string()) throw UsageError(path + ": key 'mqtt." + key + "' must be a text, got " + o.at(key).type_name());
  return o.at(key).get<std::string>();
}

// A file named in the configuration, relative to the configuration file's folder.
std::string beside(const std::string& config_path, const std::string& file) {
  if (file.empty()) return file;
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::absolute(std::filesystem::path(config_path).parent_path() / p);
  return p.lexically_normal().string();
}

void check_machine(const std::string& name, const std::string& where) {
  if (auto problem = name_problem(name); !problem.empty())
    throw UsageError(where + " '" + name + "': the machine's name is a topic level: " + problem);
}

client::Endpoint broker_endpoint(const std::string& text, const std::string& where) {
  try {
    return client::parse_endpoint(text, client::Endpoint{"localhost", kDefaultBrokerPort});
  } catch (const UsageError& e) {
    throw UsageError(where + ": " + e.what());
  }
}

std::string read_file_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read the configuration file '" + path + "' (--config)");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string default_state_file(const std::string& machine) {
  const char* dir = std::getenv("STATE_DIRECTORY");  // systemd's StateDirectory=
  const std::string base = dir && *dir ? std::string(dir) : std::string(".");
  return base + "/messmqtt-" + machine + ".json";
}

}  // namespace

void load_bridge_config_text(const std::string& text, const std::string& path, BridgeConfig& cfg) {
  jsontext::Options options;
  options.comments = true;  // as messd reads the same file
  nlohmann::json j;
  try {
    j = jsontext::parse_strict(text, path, options);
  } catch (const jsontext::JsonTextError& e) {
    throw UsageError(e.what());
  }
  if (!j.is_object()) throw UsageError(path + ": a configuration is a JSON object { ... }");
  // messd's sections are messd's to check; of them the bridge reads only where messd listens.
  if (j.contains("server") && j.at("server").is_object() && j.at("server").contains("port")) {
    const auto& port = j.at("server").at("port");
    if (!port.is_number_unsigned() || port.get<std::uint64_t>() > 65535)
      throw UsageError(path + ": key 'server.port' must be a whole number from 0 to 65535");
    if (port.get<std::uint64_t>() != 0) cfg.messd.port = static_cast<std::uint16_t>(port.get<std::uint64_t>());
  }
  if (!j.contains("mqtt")) throw UsageError(path + ": has no \"mqtt\" section; messmqtt needs at least {\"mqtt\": {\"machine\": \"<name>\"}} (docs/mqtt.md)");
  const auto& m = j.at("mqtt");
  if (!m.is_object()) throw UsageError(path + ": key 'mqtt' must be an object { ... } with the keys " + std::string(kMqttKeys));
  for (const auto& [key, value] : m.items()) {
    const std::string keys = kMqttKeys;
    bool known = false;
    std::size_t start = 0;
    while (start < keys.size()) {
      auto end = keys.find(", ", start);
      if (end == std::string::npos) end = keys.size();
      known = known || keys.substr(start, end - start) == key;
      start = end + 2;
    }
    if (!known) throw UsageError(path + ": unknown key 'mqtt." + key + "'; accepted here: " + keys);
  }
  if (m.contains("broker")) cfg.broker = broker_endpoint(text_key(m, path, "broker"), path + ": key 'mqtt.broker'");
  if (m.contains("machine")) {
    cfg.machine = text_key(m, path, "machine");
    check_machine(cfg.machine, path + ": key 'mqtt.machine'");
  }
  if (m.contains("user")) cfg.user = text_key(m, path, "user");
  if (m.contains("password_file")) cfg.password_file = beside(path, text_key(m, path, "password_file"));
  if (m.contains("tls_ca")) cfg.tls_ca = beside(path, text_key(m, path, "tls_ca"));
  if (m.contains("state_file")) cfg.state_file = beside(path, text_key(m, path, "state_file"));
  if (m.contains("allow_stop")) {
    if (!m.at("allow_stop").is_boolean()) throw UsageError(path + ": key 'mqtt.allow_stop' must be true or false");
    cfg.allow_stop = m.at("allow_stop").get<bool>();
  }
  if (m.contains("_comment")) (void)text_key(m, path, "_comment");
  if (!cfg.tls_ca.empty() && !m.contains("broker")) cfg.broker.port = kDefaultTlsBrokerPort;
  if (!cfg.tls_ca.empty() && m.contains("broker") && text_key(m, path, "broker").find(':') == std::string::npos)
    cfg.broker.port = kDefaultTlsBrokerPort;
}

BridgeConfig parse_bridge_options(int argc, const char* const argv[]) {
  BridgeConfig cfg;
  bool have_host = false;
  std::string config_path;
  // The file first, whatever the order: the command line overrides it.
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--config") {
      if (i + 1 >= argc) throw UsageError("--config needs a file name");
      config_path = argv[i + 1];
    }
  if (!config_path.empty()) load_bridge_config_text(read_file_text(config_path), config_path, cfg);
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc) throw UsageError(std::string(a) + " needs " + what);
      return argv[++i];
    };
    if (a == "-h" || a == "--help") {
      cfg.help = true;
    } else if (a == "--config") {
      ++i;
    } else if (a == "--broker") {
      cfg.broker = broker_endpoint(value("HOST[:PORT]"), "--broker");
    } else if (a == "--machine") {
      cfg.machine = value("a name");
      check_machine(cfg.machine, "--machine");
    } else if (a == "--user") {
      cfg.user = value("a user name");
    } else if (a == "--password-file") {
      cfg.password_file = value("a file name");
    } else if (a == "--tls-ca") {
      cfg.tls_ca = value("a file name");
    } else if (a == "--state-file") {
      cfg.state_file = value("a file name");
    } else if (a == "--allow-stop") {
      cfg.allow_stop = true;
    } else if (a == "--no-stop") {
      cfg.allow_stop = false;
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) +
                       "'; accepted: --config, --broker, --machine, --user, --password-file, --tls-ca, "
                       "--state-file, --allow-stop, --no-stop, --help");
    } else {
      client::take_host_argument(a, cfg.messd, have_host);
    }
  }
  if (cfg.help) return cfg;
  if (cfg.machine.empty())
    throw UsageError("no machine name: give --machine NAME or \"mqtt\": {\"machine\": \"NAME\"} in the --config file");
  if (!cfg.user.empty() && cfg.password_file.empty())
    throw UsageError("a broker user needs a password file (mqtt.password_file or --password-file)");
  if (cfg.state_file.empty()) cfg.state_file = default_state_file(cfg.machine);
  return cfg;
}

std::string read_password(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read the broker's password file '" + path + "'");
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.empty()) throw UsageError("the broker's password file '" + path + "' has an empty first line");
  return line;
}

std::string bridge_usage() {
  return "usage: messmqtt [HOST[:PORT]] [--config FILE] [--broker HOST[:PORT]] [--machine NAME]\n"
         "                [--user USER --password-file FILE] [--tls-ca FILE] [--state-file FILE]\n"
         "                [--allow-stop | --no-stop]\n"
         "Publishes one messd (HOST[:PORT], default localhost and server.port of the --config file,\n"
         "else 1066) on an MQTT broker as imess/NAME/{state,hit,event,online}; answers read-only\n"
         "replay requests on imess/NAME/replay; with --allow-stop (mqtt.allow_stop) a message on\n"
         "imess/NAME/cmd/stop stops the machine (StopMv). It never moves a machine. Every journaled\n"
         "hit reaches the broker: after a break it publishes again from the last one the broker\n"
         "acknowledged (kept in the state file). docs/mqtt.md.\n"
         "\n"
         "  --config FILE        messd's configuration file: its \"mqtt\" section (broker, machine,\n"
         "                       user, password_file, tls_ca, allow_stop, state_file)\n"
         "  --broker HOST[:PORT] the broker (default localhost:1883; 8883 with --tls-ca)\n"
         "  --machine NAME       the machine's topic level: letters, digits, '-', '_'\n"
         "  --user USER, --password-file FILE   broker credentials (the password is never logged)\n"
         "  --tls-ca FILE        TLS to the broker, verified against this CA certificate\n"
         "  --state-file FILE    the last acknowledged hit (default $STATE_DIRECTORY or .,\n"
         "                       messmqtt-NAME.json)\n"
         "  --allow-stop, --no-stop   whether the broker may stop the machine (default: not)\n"
         "  -h, --help           this text\n"
         "\n"
         "Exit status: 0 on SIGINT/SIGTERM, 1 when the state file is unusable, 2 on bad arguments\n"
         "or configuration. messd and the broker may come and go: it reconnects to both.\n";
}

}  // namespace imess::mqtt
