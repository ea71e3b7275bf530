// The verbs: their declarations (verb_table.cpp, one entry each) drive parsing, Help and the
// protocol docs. Adding a verb: its struct in commands.hpp, its entry in verb_table.cpp.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "imess/protocol/commands.hpp"
#include "imess/protocol/error_code.hpp"
#include "imess/protocol/verb_spec.hpp"

namespace imess::protocol {

std::span<const VerbSpec> verb_table();

struct ParseError {
  ErrorCode code;
  std::string text;  // says what was wrong and what is accepted
};

using ParseResult = std::variant<Command, ParseError>;

// Parses one framed line (without terminator). Empty or blank lines are not commands:
// callers skip them before calling (see is_blank).
ParseResult parse_command(std::string_view line);
// The same against another table of declarations (a second line protocol's verbs): the
// first word is looked up case-insensitively in `table` only.
ParseResult parse_command(std::string_view line, std::span<const VerbSpec> table);

// Parses a line against one declaration (its first word is taken as the verb, not compared):
// how tests check an argument kind before any verb of the table uses it.
ParseResult parse_with(const VerbSpec& verb, std::string_view line);

bool is_blank(std::string_view line);

// The declaration a command was built from (null only for a Command nobody declared, which
// the verb tests rule out).
const VerbSpec* declaration_of(const Command& cmd);
// Whether the command moves the machine, as its declaration says (Access::Moving).
bool moves_machine(const Command& cmd);

// The canonical verb name of a command (for `Ok <verb>` replies).
std::string_view verb_name(const Command& cmd);

// The arguments as documented, made from the grammar: "x y z [speed]"; empty without any.
std::string usage_args(const VerbSpec& verb);
// "<Name> <args>", e.g. "GoTo x y z [speed]".
std::string usage(const VerbSpec& verb);

// "Help" data lines: "<Name> <args> - <help>", one per verb.
std::string help_line(const VerbSpec& verb);

}  // namespace imess::protocol
