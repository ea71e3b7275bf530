// The verb table: one entry per command drives parsing, Help and the protocol docs.
// Adding a verb is one entry in verbs.cpp plus its struct in commands.hpp.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "imess/protocol/commands.hpp"
#include "imess/protocol/error_code.hpp"

namespace imess::protocol {

struct VerbSpec {
  std::string_view name;   // canonical spelling; matched case-insensitively, at most 8 characters
  std::string_view args;   // usage, e.g. "x y z [speed]"
  std::string_view help;   // one line
  bool since_1996;         // part of the original MESSD protocol
};

std::span<const VerbSpec> verb_table();

struct ParseError {
  ErrorCode code;
  std::string text;  // says what was wrong and what is accepted
};

using ParseResult = std::variant<Command, ParseError>;

// Parses one framed line (without terminator). Empty or blank lines are not commands:
// callers skip them before calling (see is_blank).
ParseResult parse_command(std::string_view line);

bool is_blank(std::string_view line);

// The canonical verb name of a command (for `Ok <verb>` replies).
std::string_view verb_name(const Command& cmd);

// "Help" data lines: "<Name> <args> - <help>", one per verb.
std::string help_line(const VerbSpec& verb);

}  // namespace imess::protocol
