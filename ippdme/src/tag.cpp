// Tag reading, writing and the open-tag tracker.
#include "imess/ippdme/tag.hpp"

namespace imess::ippdme {
namespace {
bool all_digits(std::string_view s) {
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return !s.empty();
}
std::uint32_t digits_value(std::string_view s) {
  std::uint32_t v = 0;
  for (char c : s) v = v * 10 + static_cast<std::uint32_t>(c - '0');
  return v;
}
bool valid(Tag tag) {
  return tag.number >= 1 && tag.number <= (tag.kind == TagKind::Command ? kMaxCommandTag : kMaxEventTag);
}
}  // namespace

std::optional<Tag> parse_event_tag(std::string_view text) {
  if (text.size() != kTagLength || text[0] != 'E' || !all_digits(text.substr(1))) return std::nullopt;
  Tag tag{TagKind::Event, digits_value(text.substr(1))};
  if (!valid(tag)) return std::nullopt;
  return tag;
}

std::optional<Tag> parse_client_tag(std::string_view text) {
  if (text.size() != kTagLength) return std::nullopt;
  if (text[0] == 'E') return parse_event_tag(text);
  if (!all_digits(text)) return std::nullopt;
  Tag tag{TagKind::Command, digits_value(text)};
  if (!valid(tag)) return std::nullopt;
  return tag;
}

void append_tag(std::string& out, Tag tag) {
  const bool event = tag.kind == TagKind::Event;
  std::uint32_t n = tag.number % (event ? kMaxEventTag + 1 : kMaxCommandTag + 1);
  char digits[5];
  for (int i = 4; i >= 0; --i) {
    digits[i] = static_cast<char>('0' + n % 10);
    n /= 10;
  }
  if (event) {
    out.push_back('E');
    out.append(digits + 1, 4);
  } else {
    out.append(digits, 5);
  }
}

std::string tag_text(Tag tag) {
  std::string s;
  append_tag(s, tag);
  return s;
}

bool TagTracker::try_open(Tag tag) {
  if (!valid(tag) || is_open(tag)) return false;
  if (tag.kind == TagKind::Command)
    commands_.set(tag.number);
  else
    events_.set(tag.number);
  return true;
}

void TagTracker::close(Tag tag) {
  if (!valid(tag)) return;
  if (tag.kind == TagKind::Command)
    commands_.reset(tag.number);
  else
    events_.reset(tag.number);
}

bool TagTracker::is_open(Tag tag) const {
  if (!valid(tag)) return false;
  return tag.kind == TagKind::Command ? commands_.test(tag.number) : events_.test(tag.number);
}

void TagTracker::clear() {
  commands_.reset();
  events_.reset();
}

}  // namespace imess::ippdme
