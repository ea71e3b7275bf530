// The generic command parser: finds the verb's declaration (verb_table.cpp), checks the
// arguments against its grammar and builds the typed command. Every reject names what was
// wrong and what is accepted.
#include "imess/protocol/verbs.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

#include "imess/protocol/numbers.hpp"
#include "imess/protocol/words.hpp"

namespace imess::protocol {
namespace {

// A range bound as people write it: whole values without a fraction, others as %g.
std::string bound(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The declared refusal text with {min}, {max}, {got} and {usage} filled in.
ParseError refusal(const VerbSpec& v, const ArgSpec& a, std::string_view got) {
  std::string text;
  std::string_view r = a.refusal;
  while (!r.empty()) {
    auto open = r.find('{');
    auto close = r.find('}', open);
    if (open == std::string_view::npos || close == std::string_view::npos) {
      text.append(r);
      break;
    }
    text.append(r.substr(0, open));
    auto key = r.substr(open + 1, close - open - 1);
    if (key == "min") text += bound(a.min);
    else if (key == "max") text += a.kind == ArgKind::Sequence ? std::to_string(kMaxSequenceNumber) : bound(a.max);
    else if (key == "got") text.append(a.kind == ArgKind::Choice ? got.substr(0, 16) : got);  // a stray word: its start
    else if (key == "usage") text += usage(v);
    else text.append(r.substr(open, close - open + 1));
    r.remove_prefix(close + 1);
  }
  return {ErrorCode::BadValue, text};
}

ParseError count_error(const VerbSpec& v, std::size_t got) {
  const std::string a = usage_args(v);
  return {ErrorCode::BadArguments, std::string(v.name) + " takes " + (a.empty() ? std::string("no arguments") : "'" + a + "'") +
                                       ", got " + std::to_string(got) + "; usage: " + usage(v)};
}

ParseError number_error(const VerbSpec& v, std::string_view token) {
  return {ErrorCode::BadNumber,
          "'" + std::string(token) + "' is not a number; usage: " + usage(v) + " (decimal numbers, e.g. -12.5)"};
}

bool in_range(const ArgSpec& a, double x) {
  if (a.or_zero && x == 0) return true;
  if (a.whole && x != std::floor(x)) return false;
  return (a.above_min ? x > a.min : x >= a.min) && x <= a.max;
}

// "X10" etc.: each letter of the declared set at most once, each with a number; a vector
// letter ("N 0 0 1") alone, then three numbers, kept as three words with that letter.
std::optional<ParseError> read_axis_words(const VerbSpec& v, const ArgSpec& a, std::span<const std::string_view> tokens,
                                          Args& out) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const auto t = tokens[i];
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(t[0])));
    bool repeated = false;
    for (const auto& w : out.axis_words) repeated = repeated || w.letter == letter;
    if (a.words.find(letter) == std::string_view::npos || repeated) return refusal(v, a, t);
    if (a.vectors.find(letter) != std::string_view::npos) {
      if (t.size() != 1 || i + 3 >= tokens.size())
        return ParseError{ErrorCode::BadArguments, std::string(v.name) + " takes " + std::string(1, letter) +
                                                       " alone followed by three numbers (" + std::string(1, letter) +
                                                       " i j k), got '" + std::string(t) + "'; usage: " + usage(v)};
      for (int k = 1; k <= 3; ++k) {
        auto n = parse_number(tokens[i + k]);
        if (!n) return number_error(v, tokens[i + k]);
        out.axis_words.push_back({letter, *n});
      }
      i += 3;
      continue;
    }
    auto n = parse_number(t.substr(1));
    if (!n) return number_error(v, t);
    out.axis_words.push_back({letter, *n});
  }
  return std::nullopt;
}

// Checks the tokens against the grammar: the count first, then the syntax of every number,
// then the values — so a line with both a non-number and a value out of range is Err 102.
ParseResult parse_args(const VerbSpec& v, std::span<const std::string_view> tokens) {
  const auto specs = std::span(v.args.items).first(v.args.size);
  std::size_t required = 0;
  bool variadic = false;
  for (const auto& a : specs) {
    required += a.optional ? 0 : 1;
    variadic = variadic || a.kind == ArgKind::AxisWords;
  }
  if (tokens.size() < required || (!variadic && tokens.size() > specs.size())) return count_error(v, tokens.size());
  Args out;
  for (std::size_t i = 0; i < specs.size() && i < tokens.size(); ++i) {
    if (specs[i].kind != ArgKind::Number) continue;
    auto n = parse_number(tokens[i]);
    if (!n) return number_error(v, tokens[i]);
    out.at[i].number = *n;
  }
  for (std::size_t i = 0; i < specs.size() && i < tokens.size(); ++i) {
    const ArgSpec& a = specs[i];
    ArgValue& value = out.at[i];
    value.present = true;
    value.text = tokens[i];
    switch (a.kind) {
      case ArgKind::Number:
        if (!in_range(a, value.number)) return refusal(v, a, tokens[i]);
        break;
      case ArgKind::Word: break;
      case ArgKind::Choice: {
        value.choice = 0;
        bool found = false;
        for (auto w : split_words(a.words, " \t")) {
          if (iequals(w, tokens[i])) { found = true; break; }
          ++value.choice;
        }
        if (!found) return refusal(v, a, tokens[i]);
        break;
      }
      case ArgKind::Sequence: {
        auto seq = parse_sequence_number(tokens[i]);
        if (!seq) return refusal(v, a, tokens[i]);
        value.sequence = *seq;
        break;
      }
      case ArgKind::AxisWords:
        if (auto e = read_axis_words(v, a, tokens.subspan(i), out)) return *e;
        break;
    }
  }
  return v.build(out);
}

}  // namespace

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t") == std::string_view::npos; }

ParseResult parse_command(std::string_view line) { return parse_command(line, verb_table()); }

ParseResult parse_command(std::string_view line, std::span<const VerbSpec> table) {
  for (char c : line) {
    auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && u != '\t') || u > 0x7e)
      return ParseError{ErrorCode::BadCharacter,
                        "the line holds a control or non-ASCII byte (code " + std::to_string(u) +
                            "); commands are plain ASCII words and numbers"};
  }
  auto tokens = split_words(line, " \t");
  if (tokens.empty()) return ParseError{ErrorCode::UnknownCommand, "empty command; Help lists the commands"};
  for (const auto& v : table)
    if (iequals(tokens[0], v.name)) return parse_args(v, std::span(tokens).subspan(1));
  std::string shown(tokens[0].substr(0, 16));
  return ParseError{ErrorCode::UnknownCommand, "unknown command '" + shown + "'; Help lists the commands"};
}

ParseResult parse_with(const VerbSpec& verb, std::string_view line) {
  auto tokens = split_words(line, " \t");
  if (tokens.empty()) return ParseError{ErrorCode::UnknownCommand, "empty command; Help lists the commands"};
  return parse_args(verb, std::span(tokens).subspan(1));
}

const VerbSpec* declaration_of(const Command& cmd) {
  for (const auto& v : verb_table())
    if (v.command == cmd.index()) return &v;
  return nullptr;
}

bool moves_machine(const Command& cmd) {
  const VerbSpec* v = declaration_of(cmd);
  return v && v->access == Access::Moving;
}

std::string_view verb_name(const Command& cmd) {
  const VerbSpec* v = declaration_of(cmd);
  return v ? v->name : "?";
}

std::string usage_args(const VerbSpec& verb) {
  std::string u;
  for (std::size_t i = 0; i < verb.args.size; ++i) {
    const ArgSpec& a = verb.args.items[i];
    if (!u.empty()) u += ' ';
    u += a.optional ? "[" + std::string(a.name) + "]" : std::string(a.name);
  }
  return u;
}

std::string usage(const VerbSpec& verb) {
  std::string u(verb.name);
  if (verb.args.size > 0) u.append(" ").append(usage_args(verb));
  return u;
}

std::string help_line(const VerbSpec& verb) {
  std::string line = "Help ";
  line.append(usage(verb)).append(" - ").append(verb.help);
  return line;
}

}  // namespace imess::protocol
