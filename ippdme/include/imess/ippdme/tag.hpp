// Tags (IPPDME.md §2): command tags 00001..99999 for the normal queue, event tags E0001..E9999
// for the fast queue, E0000 for lines the server sends on its own; and the tracker of open tags.
#pragma once
#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace imess::ippdme {

enum class TagKind : std::uint8_t { Command, Event };

struct Tag {
  TagKind kind = TagKind::Command;
  std::uint32_t number = 0;  // Command: 1..99999; Event: 0..9999 (0 only from the server)
  friend bool operator==(const Tag&, const Tag&) = default;
};

inline constexpr std::uint32_t kMaxCommandTag = 99999;
inline constexpr std::uint32_t kMaxEventTag = 9999;
inline constexpr Tag kServerTag{TagKind::Event, 0};  // E0000: events, unsolicited errors, tag errors
inline constexpr std::size_t kTagLength = 5;

// A tag as a client may send it: exactly five characters, "00001".."99999" or "E0001".."E9999"
// (00000 and E0000 are refused). nullopt for anything else.
std::optional<Tag> parse_client_tag(std::string_view text);
// An event tag as an argument (StopDaemon(E0005)): E0001..E9999.
std::optional<Tag> parse_event_tag(std::string_view text);

// The five characters of a tag: "00042", "E0042", "E0000". Numbers beyond the kind's range are
// written modulo its range, so the result is always five characters.
std::string tag_text(Tag tag);
void append_tag(std::string& out, Tag tag);

// Which tags have an open transaction. The session opens a tag when it accepts a command and
// closes it after the command's `%`; a tag that is open is refused (IllegalTag on E0000, as the
// NIST server does). Fixed size, no allocation after construction.
class TagTracker {
 public:
  // Opens the tag; false (and nothing changes) when it is already open or not a client tag.
  bool try_open(Tag tag);
  void close(Tag tag);
  bool is_open(Tag tag) const;
  std::size_t open_count() const { return commands_.count() + events_.count(); }
  void clear();

 private:
  std::bitset<kMaxCommandTag + 1> commands_;
  std::bitset<kMaxEventTag + 1> events_;
};

}  // namespace imess::ippdme
