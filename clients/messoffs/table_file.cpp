// Table files in by extension, output files out whole.
#include "table_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "table_csv.hpp"
#include "table_json.hpp"

namespace imess::messoffs {
namespace {

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

OffsetTable load_table(const std::string& path) {
  const bool json = ends_with(path, ".json");
  if (!json && !ends_with(path, ".csv"))
    throw TableError("'" + path + "': unknown table format; accepted: .json, .csv (see messoffs --help)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TableError("'" + path + "': cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return json ? parse_table_json(text.str(), path) : parse_table_csv(text.str(), path);
}

void write_output_file(const std::string& path, const std::string& text, bool replace) {
  std::error_code ec;
  if (!replace && std::filesystem::exists(path, ec))
    throw std::runtime_error("'" + path + "' exists; add --force to replace it");
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + tmp + "' for writing");
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + tmp + "'");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot replace '" + path + "': " + why);
  }
}

}  // namespace imess::messoffs
