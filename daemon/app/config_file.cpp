// Configuration files into memory: every failure names the file and says what is expected.
#include "config_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "json_object.hpp"

namespace imess::app {

std::string read_config_file(const std::string& path, const std::string& what, const std::string& flag) {
  namespace fs = std::filesystem;
  const std::string expected = "; " + flag + " takes the path of a readable " + what;
  if (path.empty()) throw ConfigError("an empty file name was given" + expected);
  std::error_code ec;
  auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    throw ConfigError(path + ": cannot open the " + what + ": " +
                      (ec ? ec.message() : std::string("no such file")) + expected);
  }
  if (fs::is_directory(status)) throw ConfigError(path + ": is a directory, not a " + what + expected);
  if (!fs::is_regular_file(status)) throw ConfigError(path + ": is not a regular file" + expected);
  auto size = fs::file_size(path, ec);
  if (!ec && size > kMaxConfigFileBytes)
    throw ConfigError(path + ": is " + std::to_string(size) + " bytes long; a " + what + " has at most " +
                      std::to_string(kMaxConfigFileBytes) + " bytes");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot read the " + what + ": " + std::strerror(errno ? errno : EACCES) + expected);
  std::string text;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxConfigFileBytes)
      throw ConfigError(path + ": is longer than " + std::to_string(kMaxConfigFileBytes) + " bytes; a " + what +
                        " is at most that long");
  }
  if (in.bad()) throw ConfigError(path + ": cannot read the " + what + ": read error" + expected);
  return text;
}

}  // namespace imess::app
