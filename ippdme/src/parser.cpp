// The line parser: tag, column 6, call syntax, method lookup and queue, then the argument
// shape of the method's declaration (one reader per Shape) builds its typed command.
#include "imess/ippdme/parser.hpp"

#include <cctype>
#include <cmath>

#include "imess/ippdme/syntax.hpp"
#include "scan_args.hpp"

namespace imess::ippdme {
namespace {

constexpr std::size_t kMaxCauseLength = 64;

struct Fail {
  ErrorCode code;
};
using Step = std::optional<Fail>;  // nullopt: the shape read its arguments

std::string cause_from(std::string_view text) {
  std::string out(text.substr(0, kMaxCauseLength));
  for (char& c : out)
    if (c < 32 || c > 126 || c == '"') c = '?';
  return out;
}

bool has_bad_byte(std::string_view line) {
  for (char ch : line) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 32 || c > 126) return true;
  }
  return false;
}

// ---- item lists ---------------------------------------------------------------------------

struct ItemName {
  std::string_view name;
  Item item;
};
constexpr ItemName kItems[] = {{"X", Item::X},         {"Y", Item::Y},         {"Z", Item::Z},
                               {"R", Item::R},         {"Tool.A", Item::ToolA}, {"Tool.B", Item::ToolB},
                               {"Tool.C", Item::ToolC}, {"IJK", Item::IJK},     {"ER", Item::ER},
                               {"Q", Item::Q}};

std::optional<Item> item_named(std::string_view name) {
  for (const auto& i : kItems)
    if (i.name == name) return i.item;
  return std::nullopt;
}
bool report_only(Item i) { return i == Item::IJK || i == Item::ER || i == Item::Q; }
// An item asked for twice (`Get(X(), X())`) is refused (0502), as a repeated GoTo axis is.
bool repeated(const std::vector<Item>& items, Item i) {
  for (Item seen : items)
    if (seen == i) return true;
  return false;
}

// Get: known position items with empty parentheses.
Step read_get_items(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  for (const auto& a : call.args) {
    if (a.kind != ValueKind::Call) return Fail{ErrorCode::IncorrectArguments};
    auto item = item_named(a.text);
    if (!item) return Fail{ErrorCode::ArgumentNotRecognized};
    if (report_only(*item)) return Fail{ErrorCode::BadContext};
    if (!a.args.empty() || repeated(out.items, *item)) return Fail{ErrorCode::IncorrectArguments};
    out.items.push_back(*item);
  }
  return std::nullopt;
}

// OnPtMeasReport: any item, empty parentheses; anything else is a bad property (0510).
Step read_ptmeas_report(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::BadProperty};
  for (const auto& a : call.args) {
    auto item = a.kind == ValueKind::Call ? item_named(a.text) : std::nullopt;
    if (!item) return Fail{ErrorCode::BadProperty};
    if (!a.args.empty() || repeated(out.items, *item)) return Fail{ErrorCode::IncorrectArguments};
    out.items.push_back(*item);
  }
  return std::nullopt;
}

std::optional<double> single_number(const Value& call) {
  if (call.args.size() != 1 || call.args[0].kind != ValueKind::Number) return std::nullopt;
  return call.args[0].number;
}

// OnMoveReportE: Time(s) and Dis(d) at most once each (not negative), position items.
Step read_move_report(const Value& call, Checked& out) {
  for (const auto& a : call.args) {
    if (a.kind == ValueKind::Call && (a.text == "Time" || a.text == "Dis")) {
      auto& slot = a.text == "Time" ? out.time : out.dis;
      auto v = single_number(a);
      if (!v || slot) return Fail{ErrorCode::IncorrectArguments};
      if (*v < 0) return Fail{ErrorCode::BadArgument};
      slot = *v;
      continue;
    }
    auto item = a.kind == ValueKind::Call ? item_named(a.text) : std::nullopt;
    if (!item) return Fail{ErrorCode::BadProperty};
    if (report_only(*item)) return Fail{ErrorCode::BadContext};
    if (!a.args.empty() || repeated(out.items, *item)) return Fail{ErrorCode::IncorrectArguments};
    out.items.push_back(*item);
  }
  if (out.items.empty()) return Fail{ErrorCode::BadProperty};
  return std::nullopt;
}

// ---- positions ----------------------------------------------------------------------------

std::optional<double>* axis_slot(Axes& axes, std::string_view name, bool with_tool_axes) {
  if (name == "X") return &axes.x;
  if (name == "Y") return &axes.y;
  if (name == "Z") return &axes.z;
  if (!with_tool_axes) return nullptr;
  if (name == "Tool.A") return &axes.tool_a;
  if (name == "Tool.B") return &axes.tool_b;
  if (name == "Tool.C") return &axes.tool_c;
  return nullptr;
}

Step read_axis(const Value& a, Checked& out, bool with_tool_axes) {
  if (a.kind != ValueKind::Call) return Fail{ErrorCode::IncorrectArguments};
  auto* slot = axis_slot(out.axes, a.text, with_tool_axes);
  if (!slot) return Fail{ErrorCode::ArgumentNotRecognized};
  auto v = single_number(a);
  if (!v || slot->has_value()) return Fail{ErrorCode::IncorrectArguments};
  *slot = *v;
  return std::nullopt;
}

Step read_goto(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  for (const auto& a : call.args)
    if (auto f = read_axis(a, out, true)) return f;
  return std::nullopt;
}

Step read_ptmeas(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  for (const auto& a : call.args) {
    if (a.kind == ValueKind::Call && a.text == "IJK") {
      if (a.args.size() != 3 || out.ijk) return Fail{ErrorCode::IncorrectArguments};
      for (const auto& n : a.args)
        if (n.kind != ValueKind::Number) return Fail{ErrorCode::IncorrectArguments};
      out.ijk = Vector3{a.args[0].number, a.args[1].number, a.args[2].number};
      continue;
    }
    if (auto f = read_axis(a, out, false)) return f;
  }
  const Axes& n = out.axes;
  if (!n.x && !n.y && !n.z) return Fail{ErrorCode::IncorrectArguments};  // IJK alone is not a target
  if (out.ijk) {
    const double norm = std::hypot(out.ijk->i, out.ijk->j, out.ijk->k);
    if (!(norm > 0) || !std::isfinite(norm)) return Fail{ErrorCode::VectorHasNoNorm};
  }
  return std::nullopt;
}

// ---- properties ---------------------------------------------------------------------------

bool is_property_path(std::string_view name) { return name.find('.') != std::string_view::npos; }

Step read_property_queries(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  for (const auto& a : call.args) {
    if (a.kind != ValueKind::Call || !a.args.empty()) return Fail{ErrorCode::IncorrectArguments};
    if (!is_property_path(a.text)) return Fail{ErrorCode::BadProperty};
    out.paths.push_back(a.text);
  }
  return std::nullopt;
}

Step read_property_settings(const Value& call, Checked& out) {
  if (call.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  for (const auto& a : call.args) {
    if (a.kind != ValueKind::Call) return Fail{ErrorCode::IncorrectArguments};
    auto v = single_number(a);
    if (!v) return Fail{ErrorCode::IncorrectArguments};
    if (!is_property_path(a.text)) return Fail{ErrorCode::BadProperty};
    out.settings.push_back(PropertySetting{a.text, *v});
  }
  return std::nullopt;
}

Step read_property_pointer(const Value& call, Checked& out) {
  if (call.args.size() != 1) return Fail{ErrorCode::IncorrectArguments};
  const Value& a = call.args[0];
  if (a.kind != ValueKind::Call || !a.args.empty()) return Fail{ErrorCode::IncorrectArguments};
  out.text = a.text;
  return std::nullopt;
}

// ---- the rest -----------------------------------------------------------------------------

Step read_tool_name(const Value& call, Checked& out) {
  if (call.args.size() != 1 || call.args[0].kind != ValueKind::String) return Fail{ErrorCode::IncorrectArguments};
  if (call.args[0].text.empty()) return Fail{ErrorCode::BadArgument};
  out.text = call.args[0].text;
  return std::nullopt;
}

Step read_error_number(const Value& call, Checked& out) {
  auto v = single_number(call);
  if (!v) return Fail{ErrorCode::IncorrectArguments};
  if (*v < 0 || *v > 9999 || std::floor(*v) != *v) return Fail{ErrorCode::BadArgument};
  out.integer = static_cast<int>(*v);
  return std::nullopt;
}

Step read_event_tag(const Value& call, Checked& out) {
  if (call.args.size() != 1 || call.args[0].kind != ValueKind::EventTag) return Fail{ErrorCode::IncorrectArguments};
  auto tag = parse_event_tag(call.args[0].text);
  if (!tag) return Fail{ErrorCode::BadArgument};  // E0000 names no daemon
  out.tag = *tag;
  return std::nullopt;
}

template <class E, std::size_t N>
std::optional<E> word_of(const Value& v, const E (&choices)[N], std::string_view (*name)(E)) {
  if (v.kind != ValueKind::Word) return std::nullopt;
  for (E e : choices)
    if (name(e) == v.text) return e;
  return std::nullopt;
}
constexpr CoordSystem kCoordSystems[] = {CoordSystem::MachineCsy, CoordSystem::MoveableMachineCsy,
                                         CoordSystem::MultipleArmCsy, CoordSystem::PartCsy};
constexpr CsyTarget kCsyTargets[] = {CsyTarget::PartCsy,       CsyTarget::MoveableMachineCsy,
                                     CsyTarget::MultipleArmCsy, CsyTarget::JogDisplayCsy,
                                     CsyTarget::JogMoveCsy,    CsyTarget::SensorCsy};

Step read_coord_system(const Value& call, Checked& out) {
  if (call.args.size() != 1) return Fail{ErrorCode::IncorrectArguments};
  auto c = word_of(call.args[0], kCoordSystems, coord_system_name);
  if (!c) return Fail{ErrorCode::BadArgument};
  out.coord_system = *c;
  return std::nullopt;
}

Step read_csy_word(const Value& call, Checked& out) {
  if (call.args.size() != 1) return Fail{ErrorCode::IncorrectArguments};
  auto c = word_of(call.args[0], kCsyTargets, csy_target_name);
  if (!c) return Fail{ErrorCode::BadArgument};
  out.csy = *c;
  return std::nullopt;
}

Step read_csy_transformation(const Value& call, Checked& out) {
  if (call.args.size() != 7) return Fail{ErrorCode::IncorrectArguments};
  auto c = word_of(call.args[0], kCsyTargets, csy_target_name);
  if (!c) return Fail{ErrorCode::BadArgument};
  double n[6];
  for (std::size_t i = 0; i < 6; ++i) {
    if (call.args[i + 1].kind != ValueKind::Number) return Fail{ErrorCode::IncorrectArguments};
    n[i] = call.args[i + 1].number;
  }
  if (n[3] < 0 || n[3] > 180) return Fail{ErrorCode::ThetaOutOfRange};
  for (std::size_t i = 0; i < 3; ++i)
    if (!(std::abs(n[i]) <= kMaxCsyOffset)) return Fail{ErrorCode::BadArgument};
  out.csy = *c;
  out.transform = CsyTransformation{n[0], n[1], n[2], n[3], n[4], n[5]};
  return std::nullopt;
}

Step read_shape(Shape shape, const Value& call, Checked& out) {
  switch (shape) {
    case Shape::None: return call.args.empty() ? Step{} : Step{Fail{ErrorCode::IncorrectArguments}};
    case Shape::ErrorNumber: return read_error_number(call, out);
    case Shape::EventTag: return read_event_tag(call, out);
    case Shape::GetItems: return read_get_items(call, out);
    case Shape::PtMeasReportItems: return read_ptmeas_report(call, out);
    case Shape::MoveReport: return read_move_report(call, out);
    case Shape::GoToTargets: return read_goto(call, out);
    case Shape::PtMeasArgs: return read_ptmeas(call, out);
    case Shape::PropertyQueries: return read_property_queries(call, out);
    case Shape::PropertySettings: return read_property_settings(call, out);
    case Shape::PropertyPointer: return read_property_pointer(call, out);
    case Shape::ToolName: return read_tool_name(call, out);
    case Shape::CoordSystemWord: return read_coord_system(call, out);
    case Shape::CsyTransformation: return read_csy_transformation(call, out);
    case Shape::CsyWord: return read_csy_word(call, out);
    case Shape::ScanArgs:
      if (auto code = read_scan_args(call, out)) return Fail{*code};
      return std::nullopt;
    case Shape::NotImplemented: return Fail{ErrorCode::UnsupportedCommand};
  }
  return Fail{ErrorCode::ProtocolError};
}

// The method name at the start of the call text, for F3 when the call itself is garbled.
std::string_view leading_name(std::string_view text) {
  std::size_t n = 0;
  while (n < text.size() && text[n] != '(' && text[n] != ' ') ++n;
  return is_name(text.substr(0, n)) ? text.substr(0, n) : std::string_view{};
}

}  // namespace

LineResult parse_line(std::string_view line) {
  const std::optional<Tag> readable = readable_tag(line);
  if (has_bad_byte(line)) return LineError{readable, ErrorCode::IllegalCharacter, cause_from(line)};
  if (!readable) {
    // A tag that goes on past column 5 (`012345 GoTo(…)`) is no tag; another byte in column 6
    // leaves the tag unreadable too: both are answered on E0000, never on a tag not sent.
    const bool tag_like = line.size() > kTagLength && parse_client_tag(line.substr(0, kTagLength));
    const bool longer_tag = tag_like && std::isdigit(static_cast<unsigned char>(line[kTagLength]));
    return LineError{std::nullopt, tag_like && !longer_tag ? ErrorCode::NoSpaceAtPos6 : ErrorCode::IllegalTag, cause_from(line)};
  }
  const Tag tag = *readable;
  if (line.size() <= kTagLength) return LineError{tag, ErrorCode::NoSpaceAtPos6, cause_from(line)};
  const std::string_view text = line.substr(kTagLength + 1);

  CallResult read = parse_call(text);
  if (!read.call) {
    const std::string_view name = leading_name(text);
    ErrorCode code = read.error ? read.error->code : ErrorCode::ProtocolError;
    // Wrong arguments of a method this library does not know: the method is the fault.
    if (code == ErrorCode::IncorrectArguments && !find_command(name)) code = ErrorCode::IllegalCommand;
    return LineError{tag, code, cause_from(name.empty() ? text : name)};
  }
  const Value& call = *read.call;
  const CommandSpec* spec = find_command(call.text);
  if (!spec) return LineError{tag, ErrorCode::IllegalCommand, cause_from(call.text)};
  const bool fast_tag = tag.kind == TagKind::Event;
  if (fast_tag != (spec->queue == Queue::Fast)) return LineError{tag, ErrorCode::IllegalTag, cause_from(call.text)};
  Checked checked;
  if (auto fail = read_shape(spec->shape, call, checked)) return LineError{tag, fail->code, std::string(spec->name)};
  if (!spec->build) return LineError{tag, ErrorCode::UnsupportedCommand, std::string(spec->name)};
  return Request{tag, spec->build(std::move(checked))};
}

std::optional<Tag> readable_tag(std::string_view line) {
  if (line.size() < kTagLength || (line.size() > kTagLength && line[kTagLength] != ' ')) return std::nullopt;
  return parse_client_tag(line.substr(0, kTagLength));
}

LineResult parse_framed(const FramedLine& line) {
  if (line.fault == LineFault::None) return parse_line(line.text);
  const std::optional<Tag> readable = readable_tag(line.text);
  const ErrorCode code = line.fault == LineFault::TooLong ? ErrorCode::ProtocolError : ErrorCode::IllegalCharacter;
  return LineError{readable, code, cause_from(line.text)};
}

Tag answer_tag(const LineError& error, const TagTracker& open_tags) {
  if (!error.tag || open_tags.is_open(*error.tag)) return kServerTag;
  return *error.tag;
}

}  // namespace imess::ippdme
