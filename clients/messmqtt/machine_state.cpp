// messd's lines into the retained state and the events (machine_state.hpp).
#include "machine_state.hpp"

#include <charconv>
#include <cstdlib>
#include <variant>
#include <vector>

#include "imess/protocol/messages.hpp"
#include "imess/protocol/words.hpp"

namespace imess::mqtt {

namespace {

std::vector<std::string> words_of(std::string_view line) {
  std::vector<std::string> w;
  for (const auto word : protocol::split_words(line)) w.emplace_back(word);
  return w;
}

// The text after the first `n` words.
std::string after_words(std::string_view line, int n) {
  std::size_t i = 0;
  for (int k = 0; k < n; ++k) {
    while (i < line.size() && line[i] == ' ') ++i;
    while (i < line.size() && line[i] != ' ') ++i;
  }
  while (i < line.size() && line[i] == ' ') ++i;
  return std::string(line.substr(i));
}

long to_long(const std::string& s) {
  long v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

bool set(std::string& field, const std::string& value) {
  if (field == value) return false;
  field = value;
  return true;
}

void fold_status(MachineState& s, const std::vector<std::string>& a, Folded& f) {
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    if (a[i] == "State") f.changed |= set(s.state, a[i + 1]);
    if (a[i] == "Control") f.changed |= set(s.control, a[i + 1]);
    if (a[i] == "Pos" && i + 3 < a.size()) {
      std::array<double, 3> p{std::strtod(a[i + 1].c_str(), nullptr), std::strtod(a[i + 2].c_str(), nullptr), std::strtod(a[i + 3].c_str(), nullptr)};
      if (s.position != p) f.changed = true, s.position = p;
    }
  }
}

void fold_program(MachineState& s, const std::vector<std::string>& a, Folded& f) {
  // Ok Program <name>|none <state> Line <n> Block <i>/<total>
  if (a.size() < 2) return;
  MachineState::Program p = s.program;
  p.name = a[0];
  p.state = a[1];
  for (std::size_t i = 2; i + 1 < a.size(); ++i) {
    if (a[i] == "Line") p.line = to_long(a[i + 1]);
    if (a[i] == "Block") p.block = a[i + 1];
  }
  if (p.name != s.program.name || p.state != s.program.state || p.line != s.program.line || p.block != s.program.block) {
    s.program = p;
    f.changed = true;
  }
}

}  // namespace

Folded fold_line(MachineState& s, std::string_view line, const std::string& now) {
  Folded f;
  const auto msg = protocol::parse_message(line);
  if (const auto* c = std::get_if<protocol::CurrCorMsg>(&msg)) {
    std::array<double, 3> p{c->p.x, c->p.y, c->p.z};
    if (s.position != p) {
      s.position = p;
      f.changed = f.only_position = true;
    }
  } else if (const auto* st = std::get_if<protocol::StateMsg>(&msg)) {
    f.changed = set(s.state, st->state);
  } else if (const auto* h = std::get_if<protocol::HitMsg>(&msg)) {
    if (!s.last_hit || h->seq >= s.last_hit->seq) {
      s.last_hit = MachineState::LastHit{h->seq, {h->p.x, h->p.y, h->p.z}, now};
      f.changed = true;
    }
  } else if (const auto* fa = std::get_if<protocol::FaultMsg>(&msg)) {
    s.last_fault = MachineState::Fault{fa->name, fa->text, now};
    f.changed = true;
    f.event = nlohmann::json{{"type", "fault"}, {"name", fa->name}, {"text", fa->text}};
  } else if (const auto* wa = std::get_if<protocol::WarnMsg>(&msg)) {
    f.event = nlohmann::json{{"type", "warn"}, {"name", wa->name}, {"text", wa->text}};
  } else if (const auto* l = std::get_if<protocol::LimitMsg>(&msg)) {
    f.event = nlohmann::json{{"type", "limit"}, {"axis", l->axis}, {"side", l->side}};
  } else if (std::holds_alternative<protocol::HomedMsg>(msg)) {
    f.event = nlohmann::json{{"type", "homed"}};
  } else if (const auto* ok = std::get_if<protocol::OkMsg>(&msg)) {
    if (ok->verb == "Status") fold_status(s, ok->args, f);
    if (ok->verb == "Program") fold_program(s, ok->args, f);
  } else if (std::holds_alternative<protocol::OtherMsg>(msg)) {
    const auto w = words_of(line);
    if (w.empty()) return f;
    if (w[0] == "Control" && w.size() >= 2) {
      f.changed = set(s.control, w[1] == "none" ? "none" : w[1] + "@" + (w.size() > 2 ? w[2] : "?"));
    } else if (w[0] == "Block" && w.size() >= 4) {
      s.program.name = w[1];
      s.program.state = "running";
      s.program.line = to_long(w[2]);
      s.program.block = w[3];
      s.program.result.clear();
      f.changed = true;
    } else if (w[0] == "ProgPause" && w.size() >= 3) {
      s.program.name = w[1];
      s.program.state = "paused";
      s.program.line = to_long(w[2]);
      f.changed = true;
      f.event = nlohmann::json{{"type", "program_pause"}, {"program", w[1]}, {"line", to_long(w[2])},
                               {"reason", after_words(line, 3)}};
    } else if (w[0] == "ProgEnd" && w.size() >= 4) {
      s.program.name = w[1];
      s.program.state = "ended";
      s.program.line = to_long(w[3]);
      s.program.result = w[2];
      f.changed = true;
      f.event = nlohmann::json{{"type", "program_end"}, {"program", w[1]}, {"result", w[2]},
                               {"line", to_long(w[3])}, {"text", after_words(line, 4)}};
    } else if (w[0] == "Qualified") {
      f.event = nlohmann::json{{"type", "qualified"}, {"text", after_words(line, 1)}};
    } else if (w[0] == "Inspected" && w.size() >= 5) {  // Inspected part in out pass|fail (messcap inspect)
      f.event = nlohmann::json{{"type", "inspection"}, {"plan", w[1]}, {"in", to_long(w[2])}, {"out", to_long(w[3])},
                               {"result", w[4]}};
    }
  }
  return f;
}

}  // namespace imess::mqtt
