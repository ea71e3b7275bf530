// What messipp does with one line typed (or piped) by a person: nothing (a blank line), quit,
// send it with its tag, or refuse it with the error the server would answer — so a typing
// mistake does not put the session into the error state. Pure.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "imess/ippdme/tag.hpp"
#include "tagger.hpp"

namespace imess::messipp {

enum class LineAction { Ignore, Quit, Send, Refuse };

struct TypedLine {
  LineAction action = LineAction::Ignore;
  std::string text;                                 // Send: the line without CR LF; Refuse: as typed
  ippdme::TagKind kind = ippdme::TagKind::Command;  // Send, Refuse: command or event tag (the queue)
  std::optional<ippdme::Tag> tag;                   // Send: its tag when it is a client's (not 00000)
  bool typed_tag = false;                           // Send: the person typed the tag
  std::string error;                                // Refuse: Error(3, 0008, GetProp, "Protocol error")
};

// `typed` without its line end; blanks around it do not count. An empty line is Ignore, `quit`
// is Quit. A line without a tag gets tagger.next(); unless `raw`, ippdme::parse_line must read
// the line as tagged, else Refuse with the library's error.
TypedLine read_typed_line(std::string_view typed, const Tagger& tagger, const Tagger::IsOpen& is_open, bool raw);

}  // namespace imess::messipp
