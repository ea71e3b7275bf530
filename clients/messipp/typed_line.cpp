// One typed line: trimmed, tagged, checked by the library's parser.
#include "typed_line.hpp"

#include <variant>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"

namespace imess::messipp {
namespace {

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

TypedLine read_typed_line(std::string_view typed, const Tagger& tagger, const Tagger::IsOpen& is_open, bool raw) {
  TypedLine out;
  const std::string_view line = trimmed(typed);
  if (line.empty()) return out;
  if (line == "quit") {
    out.action = LineAction::Quit;
    return out;
  }
  if (starts_with_tag(line)) {
    out.typed_tag = true;
    out.text = std::string(line);
    out.kind = line[0] == 'E' ? ippdme::TagKind::Event : ippdme::TagKind::Command;
    out.tag = ippdme::parse_client_tag(line.substr(0, ippdme::kTagLength));
  } else {
    const ippdme::Tag tag = tagger.next(line, is_open);
    out.text = ippdme::tag_text(tag) + " " + std::string(line);
    out.kind = tag.kind;
    out.tag = tag;
  }
  out.action = LineAction::Send;
  if (raw) return out;
  const auto parsed = ippdme::parse_line(out.text);
  if (const auto* e = std::get_if<ippdme::LineError>(&parsed)) {
    out.action = LineAction::Refuse;
    out.text = std::string(line);
    out.tag.reset();
    out.error = ippdme::error_payload(e->code, e->cause);
  }
  return out;
}

}  // namespace imess::messipp
