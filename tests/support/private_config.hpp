// A shipped configuration with a simulated port space of its own: tests that start messd on
// config/sim-parport-*.json or sim-mrm-arm.json may run at the same time as another test on
// the same file, and the port file is locked by the messd that uses it. The copy sits in the
// temporary directory (give messd --programs when the test needs the programs folder: the
// shipped one is relative to the configuration's folder).
#pragma once
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace imess::test {

// The port_io key's value, not the same path in the file's _comment.
inline const std::string kPortFileKey = "\"file\": \"/tmp/imess-ports-";

inline std::string config_file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string private_port_config(const std::string& shipped_path) {
  std::string json = config_file_text(shipped_path);
  const std::string& key = kPortFileKey;
  const auto at = json.find(key);
  REQUIRE(at != std::string::npos);
  const auto end = json.find('"', at + key.size());
  const std::string name = json.substr(at + key.size(), end - at - key.size());
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string tag = name + "-" + std::to_string(getpid());
  json.replace(at, end + 1 - at, "\"file\": \"" + dir + "/imess-test-ports-" + tag + "\"");
  const std::string path = dir + "/imess-test-config-" + tag + ".json";
  std::ofstream(path) << json;
  return path;
}

// The shipped file itself when it has no simulated port space, else a private copy.
inline std::string private_config_if_ports(const std::string& shipped_path) {
  return config_file_text(shipped_path).find(kPortFileKey) == std::string::npos ? shipped_path : private_port_config(shipped_path);
}

}  // namespace imess::test
