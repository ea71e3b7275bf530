// messmqtt: one messd on an MQTT broker (docs/mqtt.md).
#include <iostream>

#include "bridge.hpp"
#include "bridge_config.hpp"
#include "imess/client/usage_error.hpp"
#include "seq_file.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  mqtt::BridgeConfig cfg;
  std::string password;
  try {
    cfg = mqtt::parse_bridge_options(argc, argv);
    if (cfg.help) {
      std::cout << mqtt::bridge_usage();
      return client::kExitOk;
    }
    if (!cfg.password_file.empty()) password = mqtt::read_password(cfg.password_file);
  } catch (const client::UsageError& e) {
    std::cerr << "messmqtt: " << e.what() << "\n(try messmqtt --help)\n";
    return client::kExitUsage;
  }
  std::uint64_t acked = 0;
  try {
    acked = mqtt::load_acked(cfg.state_file, cfg.machine).value_or(0);
    mqtt::save_acked(cfg.state_file, cfg.machine, acked);  // writable now, not at the first hit
  } catch (const std::exception& e) {
    std::cerr << "messmqtt: " << e.what() << "\n";
    return client::kExitFailure;
  }
  return mqtt::Bridge(std::move(cfg), std::move(password), acked).run();
}
