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

inline std::string private_port_config(const std::string& shipped_path) {
  std::ifstream in(shipped_path);
  std::stringstream text;
  text << in.rdbuf();
  std::string json = text.str();
  // The port_io key's value, not the same path in the file's _comment.
  const std::string key = "\"file\": \"/tmp/imess-ports-";
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

}  // namespace imess::test
