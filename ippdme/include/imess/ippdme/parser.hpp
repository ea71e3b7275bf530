// Client lines -> tagged typed commands, or the error the spec answers (IPPDME.md §§1-4).
// Pure and exception-free: every input gives a Request or a LineError.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/commands.hpp"
#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "imess/ippdme/tag.hpp"

namespace imess::ippdme {

struct Request {
  Tag tag;
  Command command;
};

struct LineError {
  // The client's tag when it can be read (columns 1-5 a tag, column 6 a space or the line's
  // end): the server acknowledges it, then answers the error on it. nullopt: answer on E0000
  // (a line whose tag cannot be read).
  std::optional<Tag> tag;
  ErrorCode code;
  std::string cause;  // F3: the method name when it was read, else the start of the line
};

using LineResult = std::variant<Request, LineError>;

// One line without its CR LF. Checks, in this order: bytes (IllegalCharacter), tag
// (IllegalTag), column 6 (NoSpaceAtPos6), call syntax (ProtocolError), method name
// (IllegalCommand), queue (IllegalTag), support (UnsupportedCommand), arguments (per shape).
// Tag reuse is the session's check: TagTracker.
LineResult parse_line(std::string_view line);
// A framed line: its fault first (IllegalCharacter, or ProtocolError for an overlong line).
LineResult parse_framed(const FramedLine& line);

// The client's tag of a line, when it can be read (see LineError::tag).
std::optional<Tag> readable_tag(std::string_view line);

// The tag an error is sent on: the client's, unless there is none or it is already open.
Tag answer_tag(const LineError& error, const TagTracker& open_tags);

}  // namespace imess::ippdme
