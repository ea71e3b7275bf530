// Tagger: the tag messipp puts in front of a method call typed without one — `GoTo(X(10))`
// goes out as `00002 GoTo(X(10))`. Command tags (00001, 00002, …) and event tags (E0001, …)
// count up separately; which a method takes is its queue in the library's command table, a name
// the table does not know takes a command tag (the server answers it). Pure: the caller says
// which tags are still open, so a count that comes round again skips them.
#pragma once
#include <cstdint>
#include <functional>
#include <string_view>

#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/tag.hpp"

namespace imess::messipp {

// True when the person typed a tag: the line starts with a digit, or with E and a digit. No
// method name does (names start with a letter, and none is E followed by digits), so such a
// line goes out as typed and a malformed tag meets the parser's 0001 or 0002, not a second tag.
bool starts_with_tag(std::string_view line);

// The queue of the method a call names (the text up to '(' or a blank); Normal when the command
// table does not know the name.
ippdme::Queue queue_of(std::string_view call);

class Tagger {
 public:
  using IsOpen = std::function<bool(ippdme::Tag)>;

  // The tag `call` gets now: the next number of its queue's count that is not open, wrapping
  // after 99999 (E9999) to 00001 (E0001). Nothing is used up until sent().
  ippdme::Tag next(std::string_view call, const IsOpen& is_open = {}) const;

  // A line went out with the tag next() gave: its kind's count goes on after it.
  void sent(ippdme::Tag tag);
  // A line went out with a tag the person typed: the count goes on after it when the tag is at
  // or ahead of the count (type 00010 and the next is 00011), and stays otherwise.
  void sent_typed(ippdme::Tag tag);

 private:
  std::uint32_t next_command_ = 1;
  std::uint32_t next_event_ = 1;
};

}  // namespace imess::messipp
