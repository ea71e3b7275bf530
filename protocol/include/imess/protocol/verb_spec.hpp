// The vocabulary of a verb declaration: argument kinds with their ranges, the parsed values,
// and VerbSpec (name, grammar, help, the function building the typed command).
// The declarations themselves are in verb_table.cpp; the generic parser in verbs.cpp.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "imess/protocol/commands.hpp"

namespace imess::protocol {

enum class ArgKind : std::uint8_t {
  Number,      // a finite decimal number within [min, max] (see ArgSpec)
  Word,        // any word, kept as typed (a client name, a parameter name or value)
  Choice,      // one word of `words`, case-insensitive; the value is its index
  Sequence,    // a hit sequence number: plain digits, 0 ... kMaxSequenceNumber
  AxisWords,   // the rest of the line as letter+number words (X10 C90 F20), letters from `words`;
               // a letter of `vectors` stands alone and takes the next three numbers (N 0 0 1)
};

// One argument. `refusal` is the BadValue text; it may name {min}, {max}, {got}, {usage},
// which are filled in from this declaration, so the numbers are written once ({got}: the
// token as typed; for a Choice its first 16 characters).
struct ArgSpec {
  ArgKind kind = ArgKind::Word;
  std::string_view name;         // as shown in the usage ("vx", "speed", "force")
  bool optional = false;         // may be left out; only trailing arguments are optional
  double min = 0, max = 0;       // Number: accepted range
  bool above_min = false;        // Number: min itself is refused (a speed must be > 0)
  bool whole = false;            // Number: no fraction
  bool or_zero = false;          // Number: 0 is accepted too (an "off" value outside the range)
  std::string_view words;        // Choice: accepted words, blank-separated; AxisWords: letters
  std::string_view refusal;      // BadValue text
  std::string_view vectors;      // AxisWords: letters written alone and followed by three
                                 // numbers ("N 0 0 1"), given as three AxisWords in order
};

// A letter and its number from an AxisWords argument ("X10" -> {'X', 10}).
struct AxisWord {
  char letter;
  double value;
};

// The values of one parsed line, by argument position; absent optionals are not present.
struct ArgValue {
  bool present = false;
  double number = 0;         // Number
  std::uint64_t sequence = 0;  // Sequence
  std::size_t choice = 0;    // Choice: index into the words
  std::string_view text;     // the token as typed (every kind)
};

inline constexpr std::size_t kMaxArgs = 13;  // ScanCirc has the most

struct Args {
  std::array<ArgValue, kMaxArgs> at{};
  std::vector<AxisWord> axis_words;  // AxisWords, in the order given
  double number(std::size_t i) const { return at[i].number; }
  bool has(std::size_t i) const { return at[i].present; }
};

struct ArgList {
  std::array<ArgSpec, kMaxArgs> items{};
  std::size_t size = 0;
};

// Who may send a verb (docs/protocol.md, "Control"); the daemon enforces it.
enum class Access : std::uint8_t {
  Open,         // anyone: it neither moves nor changes the machine
  Controlling,  // the client in control (the first such command takes control when free)
  Moving,       // as Controlling, and it moves the machine: refused while a program runs
  Stop,         // anyone, always (StopMv)
  Own,          // changes who controls (Take, Release)
  Operator,     // any client on a host that may control, without taking control (Key: the operator's keys)
};

struct VerbSpec {
  std::string_view name;   // canonical spelling; matched case-insensitively, at most 8 characters
  ArgList args;            // the grammar; the usage is made from it
  std::string_view help;   // one line
  bool since_1996;         // part of the original MESSD protocol
  Access access;           // who may send it
  std::size_t command;     // index of the typed command in the Command variant
  Command (*build)(const Args&);  // typed command from checked values
};

// ---- helpers that make a declaration read like its usage -----------------------------------

template <class... A>
constexpr ArgList args(A... a) {
  static_assert(sizeof...(A) <= kMaxArgs, "raise kMaxArgs");
  return ArgList{{a...}, sizeof...(A)};
}
constexpr ArgSpec number(std::string_view name, double min, double max, std::string_view refusal) {
  return {ArgKind::Number, name, false, min, max, false, false, false, {}, refusal, {}};
}
constexpr ArgSpec word(std::string_view name) {
  return {ArgKind::Word, name, false, 0, 0, false, false, false, {}, {}, {}};
}
constexpr ArgSpec choice(std::string_view name, std::string_view words, std::string_view refusal) {
  return {ArgKind::Choice, name, false, 0, 0, false, false, false, words, refusal, {}};
}
constexpr ArgSpec sequence(std::string_view name, std::string_view refusal) {
  return {ArgKind::Sequence, name, false, 0, 0, false, false, false, {}, refusal, {}};
}
constexpr ArgSpec axis_words(std::string_view name, std::string_view letters, std::string_view refusal) {
  return {ArgKind::AxisWords, name, false, 0, 0, false, false, false, letters, refusal, {}};
}
constexpr ArgSpec with_vectors(ArgSpec a, std::string_view letters) { a.vectors = letters; return a; }
constexpr ArgSpec optional(ArgSpec a) { a.optional = true; return a; }
constexpr ArgSpec above_min(ArgSpec a) { a.above_min = true; return a; }
constexpr ArgSpec whole(ArgSpec a) { a.whole = true; return a; }
constexpr ArgSpec or_zero(ArgSpec a) { a.or_zero = true; return a; }

template <class T, class V = Command, std::size_t I = 0>
constexpr std::size_t command_index() {
  static_assert(I < std::variant_size_v<V>, "not a Command alternative");
  if constexpr (std::is_same_v<T, std::variant_alternative_t<I, V>>) return I;
  else return command_index<T, V, I + 1>();
}

}  // namespace imess::protocol
