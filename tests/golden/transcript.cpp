// Reading and writing the golden transcript format (tests/golden/README.md).
#include "transcript.hpp"

#include <cctype>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace imess::golden {

namespace {

// "2>" -> client 2 and the rest after the marker; a marker without a number is client 1.
bool client_marker(const std::string& line, char marker, int& client, std::string& rest) {
  std::size_t i = 0;
  while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
  if (i >= line.size() || line[i] != marker) return false;
  client = i == 0 ? 1 : std::stoi(line.substr(0, i));
  rest = line.substr(i + 1);
  return true;
}

void drop_layout_blank(std::string& rest) {
  if (rest.rfind(' ', 0) == 0) rest.erase(0, 1);  // one blank after the marker is layout
}

long milliseconds(const std::string& rest, const std::string& where) {
  std::istringstream in(rest);
  long ms = -1;
  std::string unit, more;
  in >> ms >> unit;
  if (ms < 0 || unit != "ms" || (in >> more)) throw std::runtime_error(where + ": expected '<whole number> ms'");
  return ms;
}

}  // namespace

bool observed(const Entry& e) { return e.kind == EntryKind::Receive || e.kind == EntryKind::Time; }

std::string escape_line(const std::string& bytes) {
  std::string out;
  for (unsigned char c : bytes) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c < 0x20 || c > 0x7e) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string unescape_line(const std::string& text, const std::string& where) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out += text[i];
    } else if (i + 1 < text.size() && text[i + 1] == '\\') {
      out += '\\';
      ++i;
    } else if (i + 3 < text.size() && text[i + 1] == 'x' && std::isxdigit(static_cast<unsigned char>(text[i + 2])) &&
               std::isxdigit(static_cast<unsigned char>(text[i + 3]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 2, 2), nullptr, 16));
      i += 3;
    } else {
      throw std::runtime_error(where + ": a backslash starts \\xHH or \\\\ only");
    }
  }
  return out;
}

std::vector<Entry> parse_transcript(const std::string& text, const std::string& name) {
  std::vector<Entry> entries;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    const std::string where = name + ":" + std::to_string(++number);
    Entry e{EntryKind::Comment, 1, "", 0};
    int client = 1;
    std::string rest;
    if (line.empty() || line[0] == '#') {
      e.text = line;
    } else if (line.rfind("@ ", 0) == 0) {
      e = {EntryKind::Config, 1, line.substr(2)};
    } else if (line.rfind("= ", 0) == 0) {
      e = {EntryKind::Advance, 1, "", milliseconds(line.substr(2), where)};
    } else if (line.rfind("~ ", 0) == 0) {
      e = {EntryKind::Time, 1, "", milliseconds(line.substr(2), where)};
    } else if ((line[0] == '+' || line[0] == '-') && line.size() > 1 && std::isdigit(static_cast<unsigned char>(line[1]))) {
      std::istringstream words(line.substr(1));
      words >> client >> rest;
      e = {line[0] == '+' ? EntryKind::Connect : EntryKind::Close, client, rest};
      if (e.kind == EntryKind::Close && !rest.empty()) throw std::runtime_error(where + ": '-N' takes no address");
    } else if (client_marker(line, '>', client, rest)) {
      const bool joined = rest.rfind('>', 0) == 0;
      if (joined) rest.erase(0, 1);
      drop_layout_blank(rest);
      e = {EntryKind::Send, client, unescape_line(rest, where), 0, joined};
    } else if (client_marker(line, '<', client, rest)) {
      drop_layout_blank(rest);
      e = {EntryKind::Receive, client, unescape_line(rest, where)};
    } else {
      throw std::runtime_error(where + ": not a transcript line (see tests/golden/README.md): " + line);
    }
    if (client < 1) throw std::runtime_error(where + ": clients are numbered from 1");
    entries.push_back(e);
  }
  return entries;
}

std::string format_transcript(const std::vector<Entry>& entries) {
  std::string out;
  auto marker = [](int client, char m) { return (client == 1 ? std::string() : std::to_string(client)) + m; };
  for (const auto& e : entries) {
    switch (e.kind) {
      case EntryKind::Comment: out += e.text; break;
      case EntryKind::Config: out += "@ " + e.text; break;
      case EntryKind::Connect: out += "+" + std::to_string(e.client) + (e.text.empty() ? "" : " " + e.text); break;
      case EntryKind::Close: out += "-" + std::to_string(e.client); break;
      case EntryKind::Send: out += marker(e.client, '>') + (e.joined ? ">" : "") + " " + escape_line(e.text); break;
      case EntryKind::Advance: out += "= " + std::to_string(e.ms) + " ms"; break;
      case EntryKind::Receive: out += marker(e.client, '<') + " " + escape_line(e.text); break;
      case EntryKind::Time: out += "~ " + std::to_string(e.ms) + " ms"; break;
    }
    out += '\n';
  }
  return out;
}

}  // namespace imess::golden
