// Reading a program whole, and naming its language.
#include "program_file.hpp"

#include <cerrno>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "imess/client/usage_error.hpp"

namespace imess::messprog {

std::string read_program(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw FileError("cannot read '" + path + "': it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::string why = std::strerror(errno);
    if (!why.empty()) why[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(why[0])));
    throw FileError("cannot read '" + path + "': " + why);
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw FileError("cannot read '" + path + "': read error");
  return text.str();
}

std::string base_name(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

programs::Language language_for(const std::string& path, std::optional<programs::Language> forced) {
  if (forced) return *forced;
  if (const auto lang = programs::language_of(base_name(path))) return *lang;
  const std::string name = base_name(path);
  const auto dot = name.rfind('.');
  const std::string what = dot == std::string::npos ? "has no extension" : "has the unknown extension '" + name.substr(dot) + "'";
  throw client::UsageError("program '" + path + "' " + what +
                           "; accepted: .nc .ngc .gcode .tap (G-code), .plt .hpgl (HPGL), .mrm (MRM), "
                           "or --lang gcode|hpgl|mrm");
}

}  // namespace imess::messprog
