// Splitting a program into upload lines and checking each.
#include "upload.hpp"

#include <cctype>

#include "imess/protocol/line_framer.hpp"
#include "program_file.hpp"

namespace imess::messprog {
namespace {

const char* extension_of(programs::Language lang) {
  switch (lang) {
    case programs::Language::Gcode: return ".nc";
    case programs::Language::Hpgl: return ".plt";
    case programs::Language::Mrm: return ".mrm";
  }
  return "";
}

}  // namespace

std::string upload_name(const std::string& path, programs::Language lang) {
  std::string name = base_name(path);
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-' && c != '+') c = '_';
  if (programs::language_of(name) != lang) name += extension_of(lang);
  return name;
}

Upload prepare_upload(const std::string& path, std::string_view text, programs::Language lang) {
  if (text.size() > kMaxUploadBytes)
    throw UploadError(path + ": " + std::to_string(text.size()) + " bytes; messd accepts programs of at most 16 MiB");
  Upload u{upload_name(path, lang), {}};
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string where = path + ":" + std::to_string(u.lines.size() + 1) + ": ";
    if (line == ".")
      throw UploadError(where + "a line holding only '.' ends an Upload on the wire and cannot be sent; "
                                "it is no program word either: remove it");
    if (line.size() > protocol::kMaxLineLength)
      throw UploadError(where + "line of " + std::to_string(line.size()) + " characters; messd accepts lines of at most " +
                        std::to_string(protocol::kMaxLineLength));
    for (char c : line)
      if (c == '\0' || c == '\r' || static_cast<unsigned char>(c) == 0xFF)
        throw UploadError(where + "a NUL, CR or 0xFF byte inside the line; accepted: text without them");
    u.lines.emplace_back(line);
    if (u.lines.size() > kMaxUploadLines)
      throw UploadError(path + ": more than " + std::to_string(kMaxUploadLines) + " lines; messd accepts at most that many");
    start = end + 1;
  }
  return u;
}

}  // namespace imess::messprog
