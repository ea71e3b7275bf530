// Verb table and command parser. Every reject names what was wrong and what is accepted.
#include "imess/protocol/verbs.hpp"

#include <array>
#include <cctype>
#include <vector>

#include "imess/protocol/numbers.hpp"

namespace imess::protocol {
namespace {

constexpr std::array kVerbs{
    VerbSpec{"StartMv", "vx vy vz", "jog: per-axis speed in % of MaxSpeed (x SpeedLevel), sign = direction", true},
    VerbSpec{"StopMv", "", "stop any motion (jog, GoTo, Home)", true},
    VerbSpec{"ForcePt", "", "measure here: broadcast the current position as MeasPt, no radius correction", true},
    VerbSpec{"Hello", "[name]", "protocol version and capabilities; names this client in the log", false},
    VerbSpec{"Help", "", "list every command with its usage", false},
    VerbSpec{"Status", "", "state, position, loops, tip, limits, homed, tip radius, speed level", false},
    VerbSpec{"GoTo", "x y z [speed]", "straight move to an absolute position (mm), speed in mm/s", false},
    VerbSpec{"Home", "", "reference search on all axes; zero at the encoder index", false},
    VerbSpec{"Free", "", "open the position loops now so the machine can be moved by hand", false},
    VerbSpec{"Reset", "", "clear a fault after its cause was removed", false},
    VerbSpec{"Set", "name value", "set a runtime parameter (Get lists them)", false},
    VerbSpec{"Get", "[name]", "read one runtime parameter, or all of them", false},
    VerbSpec{"Stats", "", "motion-loop period, wake-up latency percentiles, overruns, cycles", false},
    VerbSpec{"HandMv", "dx dy dz [speed]", "simulator only: push the carriage by hand (loops open), mm and mm/s", false},
    VerbSpec{"Quit", "", "close this connection", false},
    VerbSpec{"Replay", "from-seq", "re-send the journaled hits from this sequence number (Hit lines), at most 1000", false},
    VerbSpec{"Take", "[force]", "take control of the machine; force (configured hosts only) stops it and takes over", false},
    VerbSpec{"Release", "", "stop the machine and give up control", false},
    VerbSpec{"Watch", "ms", "dead-man: stop the machine when this controlling client is silent for ms (50-60000; 0 = off)", false},
};

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::string usage(const VerbSpec& v) {
  std::string u(v.name);
  if (!v.args.empty()) u.append(" ").append(v.args);
  return u;
}

ParseError arg_count_error(const VerbSpec& v, std::size_t got) {
  return {ErrorCode::BadArguments,
          std::string(v.name) + " takes " + (v.args.empty() ? std::string("no arguments") : "'" + std::string(v.args) + "'") +
              ", got " + std::to_string(got) + "; usage: " + usage(v)};
}

// Parses tokens[first..] as numbers into out; on failure names the bad token.
std::optional<ParseError> numbers(const VerbSpec& v, std::span<const std::string_view> tokens, double* out) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    auto n = parse_number(tokens[i]);
    if (!n)
      return ParseError{ErrorCode::BadNumber, "'" + std::string(tokens[i]) +
                                                  "' is not a number; usage: " + usage(v) + " (decimal numbers, e.g. -12.5)"};
    out[i] = *n;
  }
  return std::nullopt;
}

ParseResult build(const VerbSpec& v, std::size_t index, std::span<const std::string_view> args) {
  auto count = [&](std::size_t lo, std::size_t hi) { return args.size() >= lo && args.size() <= hi; };
  double n[4] = {0, 0, 0, 0};
  switch (index) {
    case 0:  // StartMv
      if (!count(3, 3)) return arg_count_error(v, args.size());
      if (auto e = numbers(v, args, n)) return *e;
      for (double p : {n[0], n[1], n[2]})
        if (p < -100.0 || p > 100.0)
          return ParseError{ErrorCode::BadValue, "StartMv speeds are percent of MaxSpeed, -100 to 100"};
      return StartMv{{n[0], n[1], n[2]}};
    case 1: return args.empty() ? ParseResult{StopMv{}} : ParseResult{arg_count_error(v, args.size())};
    case 2: return args.empty() ? ParseResult{ForcePt{}} : ParseResult{arg_count_error(v, args.size())};
    case 3:
      if (!count(0, 1)) return arg_count_error(v, args.size());
      return Hello{args.empty() ? std::string{} : std::string(args[0])};
    case 4: return args.empty() ? ParseResult{Help{}} : ParseResult{arg_count_error(v, args.size())};
    case 5: return args.empty() ? ParseResult{Status{}} : ParseResult{arg_count_error(v, args.size())};
    case 6: {  // GoTo
      if (!count(3, 4)) return arg_count_error(v, args.size());
      if (auto e = numbers(v, args, n)) return *e;
      GoTo g{{n[0], n[1], n[2]}, std::nullopt};
      if (args.size() == 4) {
        if (n[3] <= 0) return ParseError{ErrorCode::BadValue, "GoTo speed must be greater than 0 mm/s"};
        g.speed = n[3];
      }
      return g;
    }
    case 7: return args.empty() ? ParseResult{Home{}} : ParseResult{arg_count_error(v, args.size())};
    case 8: return args.empty() ? ParseResult{Free{}} : ParseResult{arg_count_error(v, args.size())};
    case 9: return args.empty() ? ParseResult{Reset{}} : ParseResult{arg_count_error(v, args.size())};
    case 10:
      if (!count(2, 2)) return arg_count_error(v, args.size());
      return Set{std::string(args[0]), std::string(args[1])};
    case 11:
      if (!count(0, 1)) return arg_count_error(v, args.size());
      return Get{args.empty() ? std::string{} : std::string(args[0])};
    case 12: return args.empty() ? ParseResult{Stats{}} : ParseResult{arg_count_error(v, args.size())};
    case 13: {  // HandMv
      if (!count(3, 4)) return arg_count_error(v, args.size());
      if (auto e = numbers(v, args, n)) return *e;
      HandMv h{{n[0], n[1], n[2]}, std::nullopt};
      if (args.size() == 4) {
        if (n[3] <= 0) return ParseError{ErrorCode::BadValue, "HandMv speed must be greater than 0 mm/s"};
        h.speed = n[3];
      }
      return h;
    }
    case 14: return args.empty() ? ParseResult{Quit{}} : ParseResult{arg_count_error(v, args.size())};
    case 15: {  // Replay
      if (!count(1, 1)) return arg_count_error(v, args.size());
      auto seq = parse_sequence_number(args[0]);
      if (!seq)
        return ParseError{ErrorCode::BadValue, "Replay takes a hit sequence number, a whole number from 0 to " +
                                                   std::to_string(kMaxSequenceNumber) + ", got '" + std::string(args[0]) + "'"};
      return Replay{*seq};
    }
    case 16:  // Take
      if (!count(0, 1)) return arg_count_error(v, args.size());
      if (args.empty()) return Take{false};
      if (iequals(args[0], "force")) return Take{true};
      return ParseError{ErrorCode::BadValue, "Take takes nothing or the word 'force', got '" +
                                                 std::string(args[0].substr(0, 16)) + "'; usage: " + usage(v)};
    case 17: return args.empty() ? ParseResult{Release{}} : ParseResult{arg_count_error(v, args.size())};
    case 18: {  // Watch
      if (!count(1, 1)) return arg_count_error(v, args.size());
      if (auto e = numbers(v, args, n)) return *e;
      if (n[0] != 0 && (n[0] < kWatchMinMs || n[0] > kWatchMaxMs || n[0] != static_cast<int>(n[0])))
        return ParseError{ErrorCode::BadValue, "Watch takes whole milliseconds from " + std::to_string(kWatchMinMs) +
                                                   " to " + std::to_string(kWatchMaxMs) + ", or 0 to switch it off"};
      return Watch{static_cast<int>(n[0])};
    }
  }
  return ParseError{ErrorCode::Internal, "verb table and parser disagree"};
}

}  // namespace

std::span<const VerbSpec> verb_table() { return kVerbs; }

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t") == std::string_view::npos; }

ParseResult parse_command(std::string_view line) {
  for (char c : line) {
    auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && u != '\t') || u > 0x7e)
      return ParseError{ErrorCode::BadCharacter,
                        "the line holds a control or non-ASCII byte (code " + std::to_string(u) +
                            "); commands are plain ASCII words and numbers"};
  }
  auto tokens = split(line);
  if (tokens.empty()) return ParseError{ErrorCode::UnknownCommand, "empty command; Help lists the commands"};
  for (std::size_t i = 0; i < kVerbs.size(); ++i)
    if (iequals(tokens[0], kVerbs[i].name))
      return build(kVerbs[i], i, std::span(tokens).subspan(1));
  std::string shown(tokens[0].substr(0, 16));
  return ParseError{ErrorCode::UnknownCommand, "unknown command '" + shown + "'; Help lists the commands"};
}

std::string_view verb_name(const Command& cmd) { return kVerbs[cmd.index()].name; }

std::string help_line(const VerbSpec& verb) {
  std::string line = "Help ";
  line.append(usage(verb)).append(" - ").append(verb.help);
  return line;
}

}  // namespace imess::protocol
