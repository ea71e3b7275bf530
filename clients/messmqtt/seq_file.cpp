// The acknowledged seq on disk (seq_file.hpp).
#include "seq_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::mqtt {

std::optional<std::uint64_t> load_acked(const std::string& path, const std::string& machine) {
  std::ifstream in(path);
  if (!in) {
    if (::access(path.c_str(), F_OK) != 0) return std::nullopt;
    throw std::runtime_error("state file '" + path + "' cannot be read");
  }
  std::stringstream text;
  text << in.rdbuf();
  const std::string expected = "; expected {\"machine\": \"" + machine +
                               "\", \"acked\": <seq>} as messmqtt writes it (delete the file to start from the "
                               "oldest hit in messd's journal)";
  nlohmann::json j;
  try {
    j = jsontext::parse_strict(text.str(), path);
  } catch (const jsontext::JsonTextError& e) {
    throw std::runtime_error(std::string("state file ") + e.what() + expected);
  }
  if (!j.is_object() || !j.contains("acked") || !j.at("acked").is_number_unsigned() || !j.contains("machine") ||
      !j.at("machine").is_string())
    throw std::runtime_error("state file '" + path + "' is not of messmqtt's form" + expected);
  if (j.at("machine").get<std::string>() != machine)
    throw std::runtime_error("state file '" + path + "' belongs to the machine '" + j.at("machine").get<std::string>() +
                             "', not '" + machine + "'" + expected);
  return j.at("acked").get<std::uint64_t>();
}

void save_acked(const std::string& path, const std::string& machine, std::uint64_t acked) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << nlohmann::json{{"machine", machine}, {"acked", acked}}.dump() << "\n";
    out.flush();
    if (!out) throw std::runtime_error("state file '" + tmp + "' cannot be written");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw std::runtime_error("state file '" + tmp + "' cannot be renamed to '" + path + "'");
}

}  // namespace imess::mqtt
