// Matching the server's lines to the lines sent, by tag.
#include "transactions.hpp"

#include <algorithm>

#include "imess/ippdme/tag.hpp"

namespace imess::messipp {

void Transactions::sent(std::string_view tag) { open_.push_back({std::string(tag), false}); }

bool Transactions::received(std::string_view line) {
  // "TTTTT X" or "TTTTT X …": a tag, a space, the kind of line in column 7.
  if (line.size() < ippdme::kTagLength + 2 || line[ippdme::kTagLength] != ' ') return false;
  const std::string_view tag = line.substr(0, ippdme::kTagLength);
  const char kind = line[ippdme::kTagLength + 1];
  if (tag == ippdme::tag_text(ippdme::kServerTag)) {
    // The server answers a line whose tag it cannot use with an error on E0000 and nothing on
    // the tag. Lines go out one Ack at a time, so it answers the one line still unanswered;
    // without one it is an event (an unsolicited error).
    if (kind != '!') return false;
    const auto it = std::find_if(open_.begin(), open_.end(), [](const Open& o) { return !o.answered; });
    if (it == open_.end()) return false;
    open_.erase(it);
    return true;
  }
  // The oldest open transaction of that tag: a reused tag's second line is the one answered
  // on E0000, so what comes on the tag belongs to the first.
  const auto it = std::find_if(open_.begin(), open_.end(), [&](const Open& o) { return o.tag == tag; });
  if (it == open_.end()) return false;
  // Only the Ack lets the next line go: a line the server refuses at once gets `!` and `%`
  // without one, and waiting for that `%` keeps the transcript in the order it happened.
  if (kind == '%')
    open_.erase(it);
  else if (kind == '&')
    it->answered = true;
  else if (kind != '#' && kind != '!')
    return false;
  return true;
}

bool Transactions::last_answered() const { return open_.empty() || open_.back().answered; }

bool Transactions::is_open(std::string_view tag) const {
  return std::any_of(open_.begin(), open_.end(), [&](const Open& o) { return o.tag == tag; });
}

std::vector<std::string> Transactions::open_tags() const {
  std::vector<std::string> tags;
  for (const auto& o : open_) tags.push_back(o.tag);
  return tags;
}

}  // namespace imess::messipp
