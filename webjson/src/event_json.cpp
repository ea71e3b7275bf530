// messd's lines as JSON events and back. Each event type is one row of kEvents: its fields in
// the order of the line, each a kind that says how the word reads and prints. A line is
// mapped by its row only when printing the fields back gives the very same line; anything
// else (data lines such as Help's, an unexpected shape) is a "Data" event with the verb and
// the text, so nothing is ever lost or guessed.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "imess/webjson/web_json.hpp"

namespace imess::webjson {
namespace {

using Json = nlohmann::ordered_json;

enum class Kind { Whole, Fixed, Word, Rest, Ratio, Literal, Words, AxisValues };

struct Field {
  Kind kind;
  const char* name;   // the JSON key; for Ratio the first of two ("block"), Literal: the word itself
  int decimals = 0;   // Fixed, AxisValues
  const char* second = nullptr;  // Ratio: the key of the number after the slash
};

struct EventRow {
  const char* type;
  std::vector<Field> fields;
};

Field whole(const char* n) { return {Kind::Whole, n}; }
Field fixed(const char* n, int d) { return {Kind::Fixed, n, d}; }
Field word(const char* n) { return {Kind::Word, n}; }
Field rest(const char* n) { return {Kind::Rest, n}; }
Field literal(const char* w) { return {Kind::Literal, w}; }

// docs/protocol.md, "Daemon -> clients (events)", and the replies.
const std::vector<EventRow>& events() {
  static const std::vector<EventRow> rows = {
      {"CurrCor", {fixed("x", 3), fixed("y", 3), fixed("z", 3)}},
      {"AxPos", {{Kind::AxisValues, "axes", 3}}},
      {"Hit", {whole("seq"), whole("id"), fixed("x", 4), fixed("y", 4), fixed("z", 4), fixed("i", 6), fixed("j", 6),
               fixed("k", 6), fixed("r", 4), fixed("t", 6)}},
      {"Scan", {whole("seq"), whole("id"), fixed("x", 4), fixed("y", 4), fixed("z", 4), fixed("i", 6), fixed("j", 6),
                fixed("k", 6), fixed("r", 4), fixed("t", 6)}},
      {"MeasPt", {fixed("x", 3), fixed("y", 3), fixed("z", 3)}},
      {"PartPt", {whole("seq"), word("frame"), fixed("x", 4), fixed("y", 4), fixed("z", 4), fixed("i", 6),
                  fixed("j", 6), fixed("k", 6)}},
      {"State", {word("state")}},
      {"Limit", {word("axis"), word("side")}},
      {"Warn", {word("name"), rest("text")}},
      {"Fault", {word("name"), rest("text")}},
      {"Homed", {}},
      {"Control", {word("name"), word("host")}},  // "Control none": both null
      {"Done", {whole("id")}},
      {"Failed", {whole("id"), word("reason"), rest("text")}},
      {"Block", {word("name"), whole("src_line"), {Kind::Ratio, "block", 0, "blocks"}}},
      {"ProgPause", {word("name"), whole("src_line"), rest("reason")}},
      {"ProgEnd", {word("name"), word("result"), whole("src_line"), rest("text")}},
      {"Frame", {word("name")}},
      {"Qualified", {literal("TipRadius"), fixed("tip_radius", 4), literal("Offset"), fixed("dx", 4), fixed("dy", 4),
                     fixed("dz", 4), literal("Form"), fixed("form", 4)}},
      {"Inspected", {word("part"), whole("in"), whole("out"), word("result")}},
      {"Ok", {word("verb"), {Kind::Words, "args"}}},
      {"Err", {whole("code"), rest("text")}},
  };
  return rows;
}

const EventRow* row_of(std::string_view type) {
  for (const auto& r : events())
    if (type == r.type) return &r;
  return nullptr;
}

std::string print_fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::optional<double> read_fixed(std::string_view w) {
  if (w.empty() || w.size() > 40) return std::nullopt;
  std::string text(w);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<std::uint64_t> read_whole(std::string_view w) {
  std::uint64_t v = 0;
  if (w.empty() || w[0] == '+' || w[0] == '-') return std::nullopt;
  auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  if (ec != std::errc() || p != w.data() + w.size()) return std::nullopt;
  return v;
}

// The next word of `s` from `at` (up to a space); `at` moves past that space.
std::string_view next_word(std::string_view s, std::size_t& at) {
  if (at > s.size()) return {};
  const std::size_t sp = s.find(' ', at);
  const std::size_t end = sp == std::string_view::npos ? s.size() : sp;
  std::string_view w = s.substr(at, end - at);
  at = sp == std::string_view::npos ? s.size() + 1 : sp + 1;
  return w;
}

// The fields of `row` read from `args`; false when the words do not fit the row.
bool read_fields(const EventRow& row, std::string_view args, Json& j) {
  std::size_t at = args.empty() ? 1 : 0;  // no arguments at all: nothing to read
  for (const auto& f : row.fields) {
    switch (f.kind) {
      case Kind::Rest:
        j[f.name] = at <= args.size() ? std::string(args.substr(at)) : std::string();
        at = args.size() + 1;
        continue;
      case Kind::Words: {
        Json words = Json::array();
        while (at <= args.size()) words.push_back(std::string(next_word(args, at)));
        j[f.name] = std::move(words);
        continue;
      }
      case Kind::AxisValues: {  // "X250.000 C-30.000": the letters in "axes", the values in "pos"
        Json axes = Json::array(), pos = Json::array();
        while (at <= args.size()) {
          const auto w = next_word(args, at);
          if (w.size() < 2) return false;
          const auto v = read_fixed(w.substr(1));
          if (!v) return false;
          axes.push_back(std::string(w.substr(0, 1)));
          pos.push_back(*v);
        }
        j[f.name] = std::move(axes);
        j["pos"] = std::move(pos);
        continue;
      }
      default:
        break;
    }
    if (at > args.size()) return false;  // a word is missing
    const auto w = next_word(args, at);
    switch (f.kind) {
      case Kind::Whole: {
        const auto v = read_whole(w);
        if (!v) return false;
        j[f.name] = *v;
        break;
      }
      case Kind::Fixed: {
        const auto v = read_fixed(w);
        if (!v) return false;
        j[f.name] = *v;
        break;
      }
      case Kind::Word:
        if (w.empty()) return false;
        j[f.name] = std::string(w);
        break;
      case Kind::Literal:
        if (w != f.name) return false;
        break;
      case Kind::Ratio: {
        const auto slash = w.find('/');
        if (slash == std::string_view::npos) return false;
        const auto a = read_whole(w.substr(0, slash)), b = read_whole(w.substr(slash + 1));
        if (!a || !b) return false;
        j[f.name] = *a;
        j[f.second] = *b;
        break;
      }
      default:
        break;
    }
  }
  return at > args.size();  // every word read
}

// The fields of `row` printed back; nullopt when a key is missing or of the wrong type.
std::optional<std::string> print_fields(const EventRow& row, const nlohmann::json& j) {
  std::string out = row.type;
  auto add = [&](const std::string& w) { out += ' ' + w; };
  for (const auto& f : row.fields) {
    if (f.kind == Kind::Literal) {
      add(f.name);
      continue;
    }
    auto it = j.find(f.name);
    if (it == j.end()) return std::nullopt;
    switch (f.kind) {
      case Kind::Whole:
        if (!it->is_number_unsigned()) return std::nullopt;
        add(std::to_string(it->get<std::uint64_t>()));
        break;
      case Kind::Fixed:
        if (!it->is_number()) return std::nullopt;
        add(print_fixed(it->get<double>(), f.decimals));
        break;
      case Kind::Word:
        if (!it->is_string() || it->get_ref<const std::string&>().empty()) return std::nullopt;
        add(it->get<std::string>());
        break;
      case Kind::Rest:
        if (!it->is_string()) return std::nullopt;
        if (!it->get_ref<const std::string&>().empty()) add(it->get<std::string>());
        break;
      case Kind::Words:
        if (!it->is_array()) return std::nullopt;
        for (const auto& w : *it) {
          if (!w.is_string()) return std::nullopt;
          add(w.get<std::string>());
        }
        break;
      case Kind::AxisValues: {
        auto pos = j.find("pos");
        if (!it->is_array() || pos == j.end() || !pos->is_array() || pos->size() != it->size()) return std::nullopt;
        for (std::size_t a = 0; a < it->size(); ++a) {
          const auto& axis = (*it)[a];
          const auto& v = (*pos)[a];
          if (!axis.is_string() || axis.get_ref<const std::string&>().size() != 1 || !v.is_number()) return std::nullopt;
          add(axis.get<std::string>() + print_fixed(v.get<double>(), f.decimals));
        }
        break;
      }
      case Kind::Ratio: {
        auto second = j.find(f.second);
        if (!it->is_number_unsigned() || second == j.end() || !second->is_number_unsigned()) return std::nullopt;
        add(std::to_string(it->get<std::uint64_t>()) + "/" + std::to_string(second->get<std::uint64_t>()));
        break;
      }
      case Kind::Literal:
        break;
    }
  }
  return out;
}

Json data_event(std::string_view verb, std::string_view text) {
  Json j;
  j["type"] = "Data";
  j["verb"] = std::string(verb);
  j["text"] = std::string(text);
  return j;
}

}  // namespace

nlohmann::ordered_json event_json(std::string_view line) {
  const std::size_t sp = line.find(' ');
  const std::string_view verb = line.substr(0, sp);
  const std::string_view args = sp == std::string_view::npos ? std::string_view{} : line.substr(sp + 1);
  Json j;
  // messd writes printable ASCII; a line with any other byte (it would be replaced in the
  // JSON text, so no field could stand for it) is Data.
  bool printable = true;
  for (unsigned char c : line) printable = printable && c >= 32 && c <= 126;
  if (!printable) {
    j = data_event(verb, args);
  } else if (verb == "Control" && args == "none") {
    j["type"] = "Control";
    j["name"] = nullptr;
    j["host"] = nullptr;
  } else if (const EventRow* row = row_of(verb)) {
    j["type"] = row->type;
    if (!read_fields(*row, args, j)) j = data_event(verb, args);
  } else {
    j = data_event(verb, args);
  }
  // Only a mapping that prints back to the very line stands for it.
  if (j["type"] != "Data" && event_line(j) != line) j = data_event(verb, args);
  j["line"] = std::string(line);
  return j;
}

std::string event_text(std::string_view line) {
  return event_json(line).dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string event_line(const nlohmann::json& event) {
  if (!event.is_object()) return {};
  auto type = event.find("type");
  if (type == event.end() || !type->is_string()) return {};
  const std::string& t = type->get_ref<const std::string&>();
  if (t == "Data") {
    auto verb = event.find("verb"), text = event.find("text");
    if (verb == event.end() || !verb->is_string() || text == event.end() || !text->is_string()) return {};
    const std::string& v = verb->get_ref<const std::string&>();
    const std::string& x = text->get_ref<const std::string&>();
    return x.empty() ? v : v + ' ' + x;
  }
  if (t == "Control") {
    auto name = event.find("name");
    if (name != event.end() && name->is_null()) return "Control none";
  }
  const EventRow* row = row_of(t);
  if (!row) return {};
  return print_fields(*row, event).value_or(std::string());
}

std::vector<std::string_view> event_types() {
  std::vector<std::string_view> out;
  for (const auto& r : events()) out.emplace_back(r.type);
  return out;
}

}  // namespace imess::webjson
