// Formatting and parsing of daemon -> client lines.
#include "imess/protocol/messages.hpp"

#include <charconv>

#include "imess/protocol/numbers.hpp"
#include "imess/protocol/words.hpp"

namespace imess::protocol {
namespace {

// The text after the first n words.
std::string rest_after(std::string_view line, std::size_t n) {
  std::size_t i = 0;
  for (std::size_t w = 0; w < n; ++w) {
    while (i < line.size() && line[i] == ' ') ++i;
    while (i < line.size() && line[i] != ' ') ++i;
  }
  while (i < line.size() && line[i] == ' ') ++i;
  return std::string(line.substr(i));
}

bool xyz(const std::vector<std::string_view>& w, Xyz& p) {
  if (w.size() != 4) return false;
  auto x = parse_number(w[1]), y = parse_number(w[2]), z = parse_number(w[3]);
  if (!x || !y || !z) return false;
  p = {*x, *y, *z};
  return true;
}

// "Hit seq id x y z i j k r t" (or "Scan …"): exactly 11 words, whole numbers for seq and id.
bool hit(const std::vector<std::string_view>& w, HitMsg& h) {
  if (w.size() != 11) return false;
  auto seq = parse_sequence_number(w[1]), id = parse_sequence_number(w[2]);
  if (!seq || !id) return false;
  double v[8];
  for (int i = 0; i < 8; ++i) {
    auto n = parse_number(w[3 + i]);
    if (!n) return false;
    v[i] = *n;
  }
  h = HitMsg{*seq, *id, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7], w[0] == "Scan"};
  return true;
}

}  // namespace

std::string format_hit(const HitMsg& h) {
  std::string s = (h.scan ? "Scan " : "Hit ") + std::to_string(h.seq) + " " + std::to_string(h.id);
  for (double v : {h.p.x, h.p.y, h.p.z}) {
    s.push_back(' ');
    append_fixed(s, v, 4);
  }
  for (double v : {h.dir.x, h.dir.y, h.dir.z}) {
    s.push_back(' ');
    append_fixed(s, v, 6);
  }
  s.push_back(' ');
  append_fixed(s, h.radius, 4);
  s.push_back(' ');
  append_fixed(s, h.time, 6);
  s.push_back('\n');
  return s;
}

std::string format_xyz(std::string_view verb, const Xyz& p) {
  std::string s(verb);
  for (double v : {p.x, p.y, p.z}) {
    s.push_back(' ');
    append_mm(s, v);
  }
  s.push_back('\n');
  return s;
}

std::string format_ok(std::string_view verb, std::string_view data) {
  std::string s = "Ok ";
  s.append(verb);
  if (!data.empty()) s.append(" ").append(data);
  s.push_back('\n');
  return s;
}

std::string format_err(ErrorCode code, std::string_view text) {
  return "Err " + std::to_string(static_cast<int>(code)) + " " + std::string(text) + "\n";
}

std::string format_event(std::string_view verb, std::string_view text) {
  std::string s(verb);
  if (!text.empty()) s.append(" ").append(text);
  s.push_back('\n');
  return s;
}

Message parse_message(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  auto w = split_words(line);
  if (w.empty()) return OtherMsg{std::string(line)};
  auto verb = w[0];
  Xyz p;
  if (verb == "CurrCor" && xyz(w, p)) return CurrCorMsg{p};
  if (verb == "MeasPt" && xyz(w, p)) return MeasPtMsg{p};
  if (HitMsg h; (verb == "Hit" || verb == "Scan") && hit(w, h)) return h;
  if (verb == "State" && w.size() == 2) return StateMsg{std::string(w[1])};
  if (verb == "Limit" && w.size() == 3) return LimitMsg{std::string(w[1]), std::string(w[2])};
  if (verb == "Warn" && w.size() >= 2) return WarnMsg{std::string(w[1]), rest_after(line, 2)};
  if (verb == "Fault" && w.size() >= 2) return FaultMsg{std::string(w[1]), rest_after(line, 2)};
  if (verb == "Homed") return HomedMsg{};
  if (verb == "Ok" && w.size() >= 2) {
    OkMsg ok{std::string(w[1]), {}};
    for (std::size_t i = 2; i < w.size(); ++i) ok.args.emplace_back(w[i]);
    return ok;
  }
  if (verb == "Err" && w.size() >= 2) {
    ErrMsg e;
    auto [ptr, ec] = std::from_chars(w[1].data(), w[1].data() + w[1].size(), e.code);
    if (ec == std::errc{} && ptr == w[1].data() + w[1].size()) {
      e.text = rest_after(line, 2);
      return e;
    }
  }
  if (verb == "Help" || verb == "Replay") return DataMsg{std::string(verb), rest_after(line, 1)};
  return OtherMsg{std::string(line)};
}

std::string format_replay_lost(std::uint64_t first, std::uint64_t last) {
  return "Replay Lost " + std::to_string(first) + " " + std::to_string(last) + " damaged or missing in the journal\n";
}

std::optional<LostHits> parse_replay_lost(std::string_view data) {
  auto w = split_words(data);
  if (w.size() < 3 || w[0] != "Lost") return std::nullopt;
  auto first = parse_sequence_number(w[1]), last = parse_sequence_number(w[2]);
  if (!first || !last || *last < *first) return std::nullopt;
  return LostHits{*first, *last};
}

}  // namespace imess::protocol
