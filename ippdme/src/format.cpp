// Response lines and client command lines. Commands are written from their typed form, one
// overload per struct (the std::visit does not compile without one), in the declared shape.
#include "imess/ippdme/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "imess/ippdme/command_spec.hpp"
#include "scan_args.hpp"

namespace imess::ippdme {
namespace {

std::string line(Tag tag, char kind, std::string_view payload, bool with_payload) {
  std::string out;
  out.reserve(kTagLength + 4 + payload.size());
  append_tag(out, tag);
  out += ' ';
  out += kind;
  if (with_payload) {
    out += ' ';
    out += payload;
  }
  out += kLineEnd;
  return out;
}

std::vector<Value> items_of(const std::vector<Item>& items) {
  std::vector<Value> out;
  for (Item i : items) out.push_back(Value::call(item_name(i)));
  return out;
}

void add_axis(std::vector<Value>& out, std::string_view name, const std::optional<double>& v) {
  if (v) out.push_back(Value::call(name, {Value::of_number(*v)}));
}
std::vector<Value> axes_of(const Axes& a) {
  std::vector<Value> out;
  add_axis(out, "X", a.x);
  add_axis(out, "Y", a.y);
  add_axis(out, "Z", a.z);
  add_axis(out, "Tool.A", a.tool_a);
  add_axis(out, "Tool.B", a.tool_b);
  add_axis(out, "Tool.C", a.tool_c);
  return out;
}
std::vector<Value> paths_of(const std::vector<std::string>& paths) {
  std::vector<Value> out;
  for (const auto& p : paths) out.push_back(Value::call(p));
  return out;
}
std::vector<Value> settings_of(const std::vector<PropertySetting>& settings) {
  std::vector<Value> out;
  for (const auto& s : settings) out.push_back(Value::call(s.path, {Value::of_number(s.value)}));
  return out;
}
std::vector<Value> one(Value v) {
  std::vector<Value> out;
  out.push_back(std::move(v));
  return out;
}

// Arguments of each command, in its declared shape.
template <class T>
std::vector<Value> args_of(const T&) {  // the commands without arguments
  static_assert(std::is_empty_v<T>, "a command with fields needs its own args_of");
  return {};
}
std::vector<Value> args_of(const StopDaemon& c) {
  Value v = Value::of_word(tag_text(c.daemon));
  v.kind = ValueKind::EventTag;
  return one(std::move(v));
}
std::vector<Value> args_of(const GetErrorInfo& c) { return one(Value::of_integer(c.number)); }
std::vector<Value> args_of(const GetProp& c) { return paths_of(c.paths); }
std::vector<Value> args_of(const GetPropE& c) { return paths_of(c.paths); }
std::vector<Value> args_of(const SetProp& c) { return settings_of(c.settings); }
std::vector<Value> args_of(const SetPropE& c) { return settings_of(c.settings); }
std::vector<Value> args_of(const EnumProp& c) { return one(Value::call(c.path)); }
std::vector<Value> args_of(const EnumAllProp& c) { return one(Value::call(c.path)); }
std::vector<Value> args_of(const OnPtMeasReport& c) { return items_of(c.items); }
std::vector<Value> args_of(const OnMoveReportE& c) {
  std::vector<Value> out;
  add_axis(out, "Time", c.time);
  add_axis(out, "Dis", c.dis);
  for (auto& v : items_of(c.items)) out.push_back(std::move(v));
  return out;
}
std::vector<Value> args_of(const Get& c) { return items_of(c.items); }
std::vector<Value> args_of(const GoTo& c) { return axes_of(c.target); }
std::vector<Value> args_of(const PtMeas& c) {
  std::vector<Value> out = axes_of(c.nominal);
  if (c.ijk)
    out.push_back(Value::call("IJK", {Value::of_number(c.ijk->i), Value::of_number(c.ijk->j), Value::of_number(c.ijk->k)}));
  return out;
}
std::vector<Value> args_of(const ChangeTool& c) { return one(Value::of_string(c.name)); }
std::vector<Value> args_of(const SetTool& c) { return one(Value::of_string(c.name)); }
std::vector<Value> args_of(const FindTool& c) { return one(Value::of_string(c.name)); }
std::vector<Value> args_of(const GetChangeToolAction& c) { return one(Value::of_string(c.name)); }
std::vector<Value> args_of(const SetCoordSystem& c) { return one(Value::of_word(coord_system_name(c.csy))); }
std::vector<Value> args_of(const SetCsyTransformation& c) {
  const auto& t = c.transform;
  return {Value::of_word(csy_target_name(c.csy)), Value::of_number(t.x0),    Value::of_number(t.y0),
          Value::of_number(t.z0),                 Value::of_number(t.theta), Value::of_number(t.psi),
          Value::of_number(t.phi)};
}
std::vector<Value> args_of(const GetCsyTransformation& c) { return one(Value::of_word(csy_target_name(c.csy))); }
template <ScanMethod T>
std::vector<Value> args_of(const T& c) {  // scan_args.cpp
  return scan_args(c);
}

}  // namespace

std::string format_ack(Tag tag) { return line(tag, '&', {}, false); }
std::string format_done(Tag tag) { return line(tag, '%', {}, false); }
std::string format_data(Tag tag, std::string_view payload) { return line(tag, '#', payload, true); }
std::string format_data(Tag tag, const std::vector<Value>& items) { return format_data(tag, format_values(items)); }

std::string error_payload(ErrorCode code, std::string_view cause, CauseStyle style) {
  const ErrorInfo& info = error_info(code);
  char head[32];
  std::snprintf(head, sizeof head, "Error(%d, %04d, ", severity_number(info.severity), number_of(code));
  std::string out = head;
  if (style == CauseStyle::Bare && is_name(cause)) {
    out += cause;
  } else {
    out += format_value(Value::of_string(cause));
  }
  out += ", \"";
  out += info.text;
  out += "\")";
  return out;
}

std::string format_error(Tag tag, ErrorCode code, std::string_view cause, CauseStyle style) {
  return line(tag, '!', error_payload(code, cause, style), true);
}

std::string format_error(const LineError& error, const TagTracker& open_tags, CauseStyle style) {
  return format_error(answer_tag(error, open_tags), error.code, error.cause, style);
}

Value command_call(const Command& cmd) {
  return Value::call(method_name(cmd), std::visit([](const auto& c) { return args_of(c); }, cmd));
}

std::size_t scan_values_per_point(const std::vector<Item>& items) {
  std::size_t n = 0;
  for (Item i : items) n += i == Item::IJK ? 3 : 1;
  return n;
}

std::string format_scan_data(Tag tag, const std::vector<Item>& items, std::span<const ScanPoint> points) {
  if (points.empty()) return {};
  std::string payload;
  auto put = [&](const std::string& number) {
    if (!payload.empty()) payload += ',';
    payload += number;
  };
  for (const ScanPoint& p : points)
    for (Item i : items) {
      switch (i) {
        case Item::X: put(format_fixed(p.xyz[0], kScanLengthDecimals)); break;
        case Item::Y: put(format_fixed(p.xyz[1], kScanLengthDecimals)); break;
        case Item::Z: put(format_fixed(p.xyz[2], kScanLengthDecimals)); break;
        case Item::IJK:
          for (double v : {p.ijk.i, p.ijk.j, p.ijk.k}) put(format_fixed(v, kScanVectorDecimals));
          break;
        case Item::ER: put(format_fixed(p.er, kScanLengthDecimals)); break;
        case Item::Q: put(std::to_string(std::isfinite(p.q) ? std::clamp(std::lround(p.q), 0L, 100L) : 100L)); break;
        case Item::R: put(format_fixed(p.r, kScanLengthDecimals)); break;
        case Item::ToolA: put(format_fixed(p.tool_a, kScanLengthDecimals)); break;
        case Item::ToolB: put(format_fixed(p.tool_b, kScanLengthDecimals)); break;
        case Item::ToolC: put(format_fixed(p.tool_c, kScanLengthDecimals)); break;
      }
    }
  return format_data(tag, payload);
}

std::optional<std::vector<ScanPoint>> read_scan_data(std::string_view payload, const std::vector<Item>& items) {
  std::vector<double> values;
  while (true) {
    const auto comma = payload.find(',');
    std::string_view token = payload.substr(0, comma);
    while (!token.empty() && token.front() == ' ') token.remove_prefix(1);
    while (!token.empty() && token.back() == ' ') token.remove_suffix(1);
    const auto v = parse_number_token(token);
    if (!v) return std::nullopt;
    values.push_back(*v);
    if (comma == std::string_view::npos) break;
    payload.remove_prefix(comma + 1);
  }
  const std::size_t width = scan_values_per_point(items);
  if (width == 0 || values.size() % width != 0) return std::nullopt;
  std::vector<ScanPoint> points(values.size() / width);
  std::size_t at = 0;
  for (ScanPoint& p : points)
    for (Item i : items) {
      switch (i) {
        case Item::X: p.xyz[0] = values[at++]; break;
        case Item::Y: p.xyz[1] = values[at++]; break;
        case Item::Z: p.xyz[2] = values[at++]; break;
        case Item::IJK:
          p.ijk = {values[at], values[at + 1], values[at + 2]};
          at += 3;
          break;
        case Item::ER: p.er = values[at++]; break;
        case Item::Q: p.q = values[at++]; break;
        case Item::R: p.r = values[at++]; break;
        case Item::ToolA: p.tool_a = values[at++]; break;
        case Item::ToolB: p.tool_b = values[at++]; break;
        case Item::ToolC: p.tool_c = values[at++]; break;
      }
    }
  return points;
}

std::string format_command(Tag tag, const Command& cmd) {
  std::string out;
  append_tag(out, tag);
  out += ' ';
  append_value(out, command_call(cmd));
  out += kLineEnd;
  return out;
}

}  // namespace imess::ippdme
