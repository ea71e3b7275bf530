// Reading a markdown table of docs/*.md in tests, so the docs can be checked against the code.
#pragma once
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace imess::testing {

inline std::string read_source_file(const std::string& relative) {
  std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/" + relative);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The rows of the first markdown table after `heading`: first cell -> all cells after it.
// Cells are trimmed and lose their backticks, an escaped bar reads as a bar; the header and separator rows are skipped.
inline std::map<std::string, std::vector<std::string>> doc_table(const std::string& doc, const std::string& heading) {
  std::map<std::string, std::vector<std::string>> rows;
  auto at = doc.find(heading);
  if (at == std::string::npos) return rows;
  std::istringstream in(doc.substr(at));
  std::string line;
  bool in_table = false, header = true;
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < line.size(); ++i) {
      if (line[i] == '|' && line[i - 1] != '\\') {
        while (!cell.empty() && cell.front() == ' ') cell.erase(0, 1);
        while (!cell.empty() && cell.back() == ' ') cell.pop_back();
        cells.push_back(cell);
        cell.clear();
      } else if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
        // "\|": a bar inside a cell, read as "|"
      } else if (line[i] != '`') {
        cell += line[i];
      }
    }
    if (header || cells.empty() || cells[0].find("---") != std::string::npos) {
      header = false;
      continue;
    }
    rows[cells[0]] = std::vector<std::string>(cells.begin() + 1, cells.end());
  }
  return rows;
}

}  // namespace imess::testing
