// The automatic tags: one count per queue, open tags skipped.
#include "tagger.hpp"

namespace imess::messipp {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::uint32_t max_of(ippdme::TagKind kind) {
  return kind == ippdme::TagKind::Command ? ippdme::kMaxCommandTag : ippdme::kMaxEventTag;
}

std::uint32_t after(std::uint32_t number, ippdme::TagKind kind) { return number >= max_of(kind) ? 1 : number + 1; }

}  // namespace

bool starts_with_tag(std::string_view line) {
  if (line.empty()) return false;
  if (is_digit(line[0])) return true;
  return line.size() > 1 && line[0] == 'E' && is_digit(line[1]);
}

ippdme::Queue queue_of(std::string_view call) {
  const auto end = call.find_first_of("( \t");
  const auto* spec = ippdme::find_command(call.substr(0, end));
  return spec ? spec->queue : ippdme::Queue::Normal;
}

ippdme::Tag Tagger::next(std::string_view call, const IsOpen& is_open) const {
  const auto kind = queue_of(call) == ippdme::Queue::Fast ? ippdme::TagKind::Event : ippdme::TagKind::Command;
  ippdme::Tag tag{kind, kind == ippdme::TagKind::Command ? next_command_ : next_event_};
  if (!is_open) return tag;
  // Every number open is a session nobody types by hand; then the count's own tag goes, and
  // the server's 0001 says so.
  for (std::uint32_t tries = 0; tries < max_of(kind) && is_open(tag); ++tries) tag.number = after(tag.number, kind);
  return is_open(tag) ? ippdme::Tag{kind, kind == ippdme::TagKind::Command ? next_command_ : next_event_} : tag;
}

void Tagger::sent(ippdme::Tag tag) {
  if (tag.number == 0 || tag.number > max_of(tag.kind)) return;
  (tag.kind == ippdme::TagKind::Command ? next_command_ : next_event_) = after(tag.number, tag.kind);
}

void Tagger::sent_typed(ippdme::Tag tag) {
  const auto count = tag.kind == ippdme::TagKind::Command ? next_command_ : next_event_;
  if (tag.number >= count) sent(tag);
}

}  // namespace imess::messipp
