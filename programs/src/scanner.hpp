// Shared lexical pieces of the translators: program text split into lines, decimal numbers
// of the plain form program languages use ([+-]digits[.digits], no exponent), error building.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "imess/programs/program.hpp"

namespace imess::programs::detail {

// The lines of `text` (split at \n; a trailing \r is dropped).
std::vector<std::string_view> split_lines(std::string_view text);

// Reads a number at s[i] (after optional spaces/tabs when skip_blanks): sign, digits, point,
// digits; at least one digit. On success advances i past it. Values above 1e12 are refused.
bool scan_number(std::string_view s, std::size_t& i, double& out, bool skip_blanks = true);

// The text of the character at s[i] for an error ("'#'", "end of line", "byte 0x07").
std::string char_text(std::string_view s, std::size_t i);

Translation fail(ErrorKind kind, int line, int column, std::string found, std::string accepted);

// Inside a translator the first error unwinds to its entry point, which returns it.
struct Failure {
  Error error;
};
[[noreturn]] void raise(ErrorKind kind, int line, int column, std::string found, std::string accepted);

// A translator's entry point: every item of the text, or its first error (a Failure thrown
// inside). Set-up errors from the translator's constructor (bad options) propagate.
template <class Translator>
Translation translate_with(Translator& t, std::string_view text) {
  try {
    Translation r;
    r.items = t.run(text);
    if constexpr (requires { t.notes(); }) r.notes = t.notes();
    if constexpr (requires { t.frames(); }) r.frames = t.frames();
    if constexpr (requires { t.offset_writes(); }) r.offset_writes = t.offset_writes();
    return r;
  } catch (const Failure& f) {
    return fail(f.error.kind, f.error.line, f.error.column, f.error.found, f.error.accepted);
  }
}

// Trims trailing zeros: 1.500000 -> 1.5, -0 -> 0 (6 decimals).
std::string num(double v);

inline bool is_blank(char c) { return c == ' ' || c == '\t'; }
inline char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
inline bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

}  // namespace imess::programs::detail
