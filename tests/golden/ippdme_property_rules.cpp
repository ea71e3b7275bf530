// The I++ DME properties' rules (listed in test_ippdme_properties.cpp's header), judged on what
// the clients of a replayed script received.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <set>
#include <sstream>

#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "imess/ippdme/parser.hpp"
#include "ippdme_properties.hpp"
#include "property_support.hpp"

namespace imess::golden::ippdme_properties {

void Counts::add(const Counts& o) {
  lines_sent += o.lines_sent, accepted += o.accepted, garbled += o.garbled, tag_errors += o.tag_errors;
  completed += o.completed, errors_seen += o.errors_seen, goto_done += o.goto_done, goto_limit += o.goto_limit;
  ptmeas_points += o.ptmeas_points, ptmeas_errors += o.ptmeas_errors, aborts_in_motion += o.aborts_in_motion;
  error_state_refusals += o.error_state_refusals, warnings_0504 += o.warnings_0504, move_reports += o.move_reports;
  drops += o.drops, drops_mid_move += o.drops_mid_move, rest_checked += o.rest_checked, rest_skipped += o.rest_skipped;
  control_given_back += o.control_given_back, refused_209 += o.refused_209, panel_moves_ok += o.panel_moves_ok;
  positions_checked += o.positions_checked, refused_clients += o.refused_clients, final_checks += o.final_checks;
  slow_retracts += o.slow_retracts;
  arrivals_checked += o.arrivals_checked;
  report_gaps_checked += o.report_gaps_checked;
  arrival_max_off = std::max(arrival_max_off, o.arrival_max_off);
  rest_max_ms = std::max(rest_max_ms, o.rest_max_ms);
  retract_max_ms = std::max(retract_max_ms, o.retract_max_ms);
  virtual_ms += o.virtual_ms;
  travel_max_excess = std::max(travel_max_excess, o.travel_max_excess);
}

std::string Counts::text() const {
  std::ostringstream o;
  o << lines_sent << " I++ lines (" << accepted << " accepted, " << garbled << " garbled, " << tag_errors << " tag errors), "
    << completed << " completed, " << errors_seen << " errors; GoTo done " << goto_done << " / 2500 " << goto_limit
    << "; PtMeas points " << ptmeas_points << " / errors " << ptmeas_errors << "; AbortE in motion " << aborts_in_motion
    << "; 0514 " << error_state_refusals << "; 0504 " << warnings_0504 << "; move reports " << move_reports << " (" << report_gaps_checked << " gaps within their Time); drops "
    << drops << " (mid-move " << drops_mid_move << "); rest checked " << rest_checked << " (skipped " << rest_skipped
    << ", longest " << rest_max_ms << " ms to stand; still retracting " << slow_retracts << ", at rest within "
    << retract_max_ms << " ms); control given back " << control_given_back << "; Err 209 "
    << refused_209 << "; panel moves accepted " << panel_moves_ok << "; positions checked " << positions_checked
    << " (furthest " << num(travel_max_excess * 1000, 1) << " µm past a travel end); GoTo arrivals checked " << arrivals_checked << " (furthest "
    << num(arrival_max_off, 4) << " mm off); refused clients " << refused_clients
    << "; final sessions " << final_checks << "; " << virtual_ms / 1000 << " s of virtual time";
  return o.str();
}

namespace {

// mm: the measured position may pass a move's end at a travel's end while the simulated servo
// settles (up to 41 µm at 150 mm/s on the servo card, MESSD's GoTo alike): the setpoints keep
// to the travel, the encoder overshoots.
constexpr double kTravelTolerance = 0.05;
constexpr double kArrivalTolerance = 0.2;   // mm: the drive kit of map A counts 0.1 mm
constexpr long kQueueLimit = 64;            // commands queued before the server stops reading (ipp_server.cpp)
// A retract from a hit ends by RetractTime (5 s by default, docs/protocol.md) when its tip
// does not report free earlier; on the 0.1 mm drive kit of sim-portio-drive-map-a a hit a hair
// off an axis keeps State retract for seconds (the motion core's, not the I++ server's).
constexpr long kRetractWithinMs = 6000;

// ---------------------------------------------------------------- what was received

struct Line {
  int step = 0;
  long t = 0;  // virtual ms since the start
  bool sent = false;
  std::string text;
};

struct Session {
  std::map<int, std::vector<Line>> streams;  // per client: what it sent and received, in order
  std::vector<long> step_time;               // virtual ms at the end of each step
  std::map<int, int> closed_at;              // client -> step the script closed it
};

Session read_session(const std::vector<Entry>& out, long period_us) {
  Session s;
  int step = -1;
  long t_us = 0, stamp = 0;
  bool advancing = false;
  for (const auto& e : out) {
    if (e.kind == EntryKind::Comment) continue;
    if (!observed(e)) {
      if (!(e.kind == EntryKind::Send && e.joined)) {
        ++step;
        advancing = e.kind == EntryKind::Advance;
        if (e.kind == EntryKind::Send) t_us += period_us;  // one motion cycle per step
        if (advancing)
          for (const long end = t_us + e.ms * 1000; t_us < end;) t_us += period_us;
        s.step_time.push_back(t_us / 1000);
      }
      if (e.kind == EntryKind::Send) s.streams[e.client].push_back({step, t_us / 1000, true, e.text});
      if (e.kind == EntryKind::Close) s.closed_at[e.client] = step;
      continue;
    }
    if (e.kind == EntryKind::Time) {
      stamp = e.ms;
      continue;
    }
    s.streams[e.client].push_back({step, advancing ? stamp : t_us / 1000, false, e.text});
  }
  return s;
}

// "00012 ! Error(3, 2500, GoTo, "text")" -> severity, number, text.
struct ErrorLine {
  int severity = -1, number = -1;
  std::string cause, text;  // F3 (a method name, unquoted) and F4
};

std::optional<ErrorLine> parse_error(const std::string& payload) {
  if (!starts(payload, "Error(") || payload.back() != ')') return std::nullopt;
  ErrorLine e;
  char number[5] = {};
  if (std::sscanf(payload.c_str(), "Error(%d, %4[0-9],", &e.severity, number) != 2 || std::string(number).size() != 4) return std::nullopt;
  e.number = std::atoi(number);
  const auto open = payload.rfind(", \"");
  if (open == std::string::npos || payload.size() < open + 5 || payload[payload.size() - 2] != '"') return std::nullopt;
  e.text = payload.substr(open + 3, payload.size() - open - 5);
  const auto cause = payload.find(", ", payload.find(", ") + 2) + 2;
  if (cause < open) e.cause = payload.substr(cause, open - cause);
  return e;
}

// The parser's verdict on a line the client sent: what the server must answer.
ippdme::LineResult parse_sent(const std::string& text) {
  ippdme::LineFramer framer;
  std::optional<ippdme::LineResult> result;
  framer.feed(text + "\r\n", [&](const ippdme::FramedLine& l) {
    if (!result) result = ippdme::parse_framed(l);
  });
  return *result;
}

// X(v), Y(v), Z(v) of a data payload: axis index -> value.
std::map<int, double> coordinates(const std::string& payload) {
  std::map<int, double> out;
  for (std::size_t i = 0; i + 2 < payload.size(); ++i) {
    const char c = payload[i];
    if ((c != 'X' && c != 'Y' && c != 'Z') || payload[i + 1] != '(' || (i > 0 && std::isalpha(static_cast<unsigned char>(payload[i - 1]))))
      continue;
    out[c - 'X'] = std::strtod(payload.c_str() + i + 2, nullptr);
  }
  return out;
}

// The error state (docs/ippdme.md): an error of severity 2 or more, except a refusal (the line
// not executed for what it says: 0001 0002 0007 0008, 0501 0502 0505-0510, 0513 0515, 1007
// 1010) and except any error of a query (Get…, Enum…, FindTool …: it changes nothing).
bool enters_error_state(const ErrorLine& e) {
  static const std::set<int> refusals{1, 2, 7, 8, 501, 502, 505, 506, 507, 508, 509, 510, 513, 515, 1007, 1010};
  static const std::set<std::string> queries{"GetErrorInfo", "GetProp", "GetPropE", "EnumProp", "EnumAllProp",
                                             "GetDMEVersion", "IsHomed", "IsUserEnabled", "GetMachineClass",
                                             "GetErrStatusE", "GetXtdErrStatus", "Get", "EnumTools", "FindTool",
                                             "GetChangeToolAction", "GetCoordSystem", "GetCsyTransformation"};
  return e.severity >= 2 && !refusals.count(e.number) && !queries.count(e.cause);
}

// The tag a sent line carries: its first five characters when a space follows them.
std::optional<std::string> sent_tag(const std::string& line) {
  if (line.size() < 6 || line[5] != ' ') return std::nullopt;
  return line.substr(0, 5);
}

template <class T>
bool holds(const ippdme::Command& c) {
  return std::holds_alternative<T>(c);
}

class Checker {
 public:
  Checker(const Machine& m, const Script& script, const Session& s) : m_(m), script_(script), s_(s) {}

  std::vector<std::string> problems;
  Counts counts;

  void run() {
    panel();
    for (int c : script_.ipp_clients) ipp_client(c);
    for (int c : script_.refused_clients) refused(c);
    rest();
    final_session();
  }

  // Rule 2 for the motion core after the last step.
  void core_position(const core::Snapshot& snap) {
    for (int c = 0; c < 3; ++c) within_travel(c, snap.position[m_.axis[c]], "the motion core after the last step");
  }

 private:
  void fail(const std::string& what) { problems.push_back(what); }
  static std::string at(int step) { return "step " + std::to_string(step) + ": "; }

  void within_travel(int c, double v, const std::string& where) {
    ++counts.positions_checked;
    const double excess = std::max(m_.lo[c] - v, v - m_.hi[c]);
    counts.travel_max_excess = std::max(counts.travel_max_excess, excess);
    if (excess > kTravelTolerance)
      fail(where + ": " + std::string(1, "XYZ"[c]) + " " + num(v, 4) + " outside its travel [" + num(m_.lo[c]) + ", " + num(m_.hi[c]) + "]");
  }

  // ------------------------------------------------ client 1: control, 209, Status (rules 2, 5)
  void panel() {
    static const std::set<std::string> moving = {"GoTo", "StartMv", "MoveTo", "Reset"};
    std::string holder = "none";
    std::deque<std::pair<int, std::string>> waiting;
    for (const auto& l : s_.streams.at(1)) {
      while (static_cast<int>(holder_after_.size()) < l.step) holder_after_.push_back(holder);  // [i]: after step i
      if (l.sent) {
        waiting.push_back({l.step, l.text});
        const auto w = words(l.text);
        if (!w.empty() && moving.count(w[0])) panel_moves_[l.step] = {l.text, holder};
        continue;
      }
      const auto w = words(l.text);
      if (w.size() >= 2 && w[0] == "Control") {
        holder = w[1];
        control_lines_[l.step].push_back(l.text);
      }
      if (w.empty() || (w[0] != "Ok" && w[0] != "Err")) continue;
      if (waiting.empty()) {
        fail(at(l.step) + "client 1 got a reply to nothing: " + l.text);
        continue;
      }
      const auto [sent_step, command] = waiting.front();
      waiting.pop_front();
      panel_replies_[sent_step] = l.text;
      if (auto st = parse_status(l.text)) {
        statuses_[sent_step] = *st;
        for (int c = 0; c < 3 && c < static_cast<int>(st->pos.size()); ++c)
          within_travel(c, st->pos[static_cast<std::size_t>(m_.axis[c])], at(l.step) + l.text);
      }
    }
    while (holder_after_.size() < s_.step_time.size()) holder_after_.push_back(holder);
    for (const auto& [w, c] : waiting) fail(at(w) + "client 1's " + c + " never answered");
    // Rule 5: the holder before the step a motion command was sent in.
    for (const auto& [sent_step, m] : panel_moves_) {
      const auto it = panel_replies_.find(sent_step);
      if (it == panel_replies_.end()) continue;
      if (m.second == "ippdme") {
        if (starts(it->second, "Err 209 ")) ++counts.refused_209;
        else fail(at(sent_step) + "client 1's " + m.first + " while the I++ session held control: " + it->second);
      } else if (starts(it->second, "Ok ") && m.first != "StartMv 0 0 0" && m.first != "Reset") {
        ++counts.panel_moves_ok;
      }
    }
  }
  std::string holder_before(int step) const {
    return step <= 0 || holder_after_.empty() ? "none" : holder_after_[static_cast<std::size_t>(std::min<int>(step, static_cast<int>(holder_after_.size())) - 1)];
  }
  // Client 1 heard control leave the session in `step`: `Control none`, or a take-over by the
  // panel (Take force just before the EndSession ran) — whatever came after it in the step
  // (a StartSession queued behind the EndSession takes it again).
  bool control_left_in(int step) const {
    const auto it = control_lines_.find(step);
    if (it == control_lines_.end()) return false;
    return std::any_of(it->second.begin(), it->second.end(), [](const std::string& l) { return !starts(l, "Control ippdme "); });
  }

  // ------------------------------------------------ an I++ client (rules 1, 2, 3)
  struct Transaction {
    ippdme::Tag tag;
    ippdme::Command command;
    int opened = 0;         // step of its `&`
    std::size_t order = 0;  // the how-manieth accepted command tag
    bool first_seen = false, error = false, daemon = false;
    std::optional<int> refused;  // a line the parser refused (its tag readable): acknowledged, then this error
    int data_lines = 0;
    std::vector<int> codes;
  };

  struct ClientState {
    std::map<std::string, Transaction> open;  // by tag text
    ippdme::TagTracker tracker;               // the same set, as the server's parser reads it
    std::deque<std::pair<int, std::string>> awaiting;  // sent lines not yet answered
    std::set<std::string> sent_tags;          // every tag the client sent
    bool in_session = false, error_state = false;
    std::size_t accepted = 0;
    std::optional<long> last_report_t;        // the move daemon's last line
    std::optional<Transaction> last_done;     // the last command transaction completed, when a GoTo without error
    bool broken = false;                      // stop checking after the first mismatch
  };

  void ipp_client(int client) {
    ClientState st;
    const auto it = s_.streams.find(client);
    if (it == s_.streams.end()) return;
    const auto& lines = it->second;
    const auto closing = s_.closed_at.find(client);
    int step = -1;
    for (std::size_t i = 0; i < lines.size() && !st.broken; ++i) {
      const Line& l = lines[i];
      if (l.step != step) {  // a new step: every line of the last one was answered in it
        if (!st.awaiting.empty() && !all_wait_for_room(st)) {
          fail(at(step) + "client " + std::to_string(client) + ": '" + escape_line(st.awaiting.front().second) + "' got no answer in its step");
          st.awaiting.clear();
        }
        step = l.step;
      }
      if (l.sent) {
        ++counts.lines_sent;
        if (auto t = sent_tag(l.text)) st.sent_tags.insert(*t);
        st.awaiting.push_back({l.step, l.text});
        continue;
      }
      received(client, st, l);
    }
    if (!st.awaiting.empty() && !st.broken && !all_wait_for_room(st))
      fail(at(step) + "client " + std::to_string(client) + ": '" + escape_line(st.awaiting.front().second) + "' got no answer in its step");
    if (st.broken) return;
    if (closing != s_.closed_at.end() && !script_.clean_clients.count(client)) {
      drop_checks(client, closing->second, st);
      return;
    }
    // Not dropped (it left after its EndSession, or stays): everything it started ended.
    for (const auto& [tag, t] : st.open)
      fail("client " + std::to_string(client) + ": " + tag + " " + std::string(ippdme::method_name(t.command)) + " (step " +
           std::to_string(t.opened) + ") never got its %");
  }

  // The server's flow control: with this many commands in its normal queue the Acks of the
  // normal queue's lines wait until one completes; a line answered at once — an event tag's
  // (IPPDME.md §6), a garbled one, a reused tag — overtakes them.
  static bool queue_full(const ClientState& st) {
    const auto queued = std::count_if(st.open.begin(), st.open.end(), [](const auto& o) { return o.second.tag.kind == ippdme::TagKind::Command; });
    return queued >= kQueueLimit;
  }
  // Whether a sent line waits for room in the normal queue: a command-tag line (a request, or
  // a refused line whose tag is readable) whose tag is not open.
  static bool waits_for_room(const ClientState& st, std::size_t i) {
    const auto verdict = parse_sent(st.awaiting[i].second);
    std::optional<ippdme::Tag> tag;
    if (const auto* req = std::get_if<ippdme::Request>(&verdict)) tag = req->tag;
    else tag = std::get<ippdme::LineError>(verdict).tag;
    return tag && tag->kind == ippdme::TagKind::Command && !st.tracker.is_open(*tag) && !held(st, ippdme::tag_text(*tag), i);
  }
  // Whether a line sent before awaiting[i] and still waiting for its Ack holds `tag`: the
  // server opened it when it read that line, so the tag is reused (0001 on E0000).
  static bool held(const ClientState& st, const std::string& tag, std::size_t i) {
    for (std::size_t j = 0; j < i && j < st.awaiting.size(); ++j)
      if (sent_tag(st.awaiting[j].second) == tag) return true;
    return false;
  }
  // Whether every line still unanswered waits for room (then silence is the flow control).
  static bool all_wait_for_room(const ClientState& st) {
    if (!queue_full(st)) return false;
    for (std::size_t i = 0; i < st.awaiting.size(); ++i)
      if (!waits_for_room(st, i)) return false;
    return true;
  }

  void drop_checks(int client, int step, const ClientState& st) {
    if (st.in_session) ++counts.drops;
    for (const auto& [tag, t] : st.open)
      if (holds<ippdme::GoTo>(t.command) || holds<ippdme::PtMeas>(t.command)) {
        ++counts.drops_mid_move;
        break;
      }
    // Rule 3: the session's control is given back as the connection goes.
    if (holder_before(step) == "ippdme") {
      if (control_left_in(step)) ++counts.control_given_back;
      else fail(at(step) + "client " + std::to_string(client) + " dropped while its session held control, and control stayed with it");
    }
  }

  void mismatch(ClientState& st, const Line& l, const std::string& why) {
    fail(at(l.step) + "'" + escape_line(l.text) + "': " + why);
    st.broken = true;
  }

  // Rule 1, one received line.
  void received(int client, ClientState& st, const Line& l) {
    const std::string& text = l.text;
    if (text == "[connection closed]") {
      mismatch(st, l, "messd closed the connection of I++ client " + std::to_string(client));
      return;
    }
    for (const char* mark : {" [no CR]", " [no line end]"})  // the harness's marks (golden_harness.cpp, collect)
      if (text.size() >= std::strlen(mark) && text.compare(text.size() - std::strlen(mark), std::string::npos, mark) == 0)
        return mismatch(st, l, "a line without its CR LF");
    for (unsigned char ch : text)
      if (ch < 32 || ch > 126) return mismatch(st, l, "a byte outside 32-126");
    if (text.size() < 7 || text[5] != ' ' || std::string("&%#!").find(text[6]) == std::string::npos)
      return mismatch(st, l, "not 'tag &', 'tag %', 'tag # …' or 'tag ! …'");
    const char kind = text[6];
    if ((kind == '&' || kind == '%') != (text.size() == 7) || (text.size() > 7 && (text[7] != ' ' || text.size() < 9)))
      return mismatch(st, l, "& and % stand alone, # and ! are followed by a space and a payload");
    const std::string tag = text.substr(0, 5), payload = text.size() > 8 ? text.substr(8) : "";
    if (tag != "E0000" && !st.sent_tags.count(tag)) return mismatch(st, l, "a line on a tag the client never sent");
    std::optional<ErrorLine> err;
    if (kind == '!') {
      err = parse_error(payload);
      if (!err) return mismatch(st, l, "not Error(F1, F2, F3, \"text\")");
      const auto* info = ippdme::find_error(err->number);
      if (!info || ippdme::severity_number(info->severity) != err->severity || info->text != err->text)
        return mismatch(st, l, "severity or text not the library's for that number");
      ++counts.errors_seen;
      if (err->number == 504) ++counts.warnings_0504;
      if (err->number == 514) ++counts.error_state_refusals;
    }
    if (tag == "E0000") {
      if (kind == '#') {
        if (!starts(payload, "PtMeas(") && !starts(payload, "KeyPress("))
          mismatch(st, l, "an E0000 event that is neither the operator's PtMeas nor a KeyPress");
        return;
      }
      if (kind != '!') return mismatch(st, l, "E0000 carries only events and errors");
      first_answer(st, l, tag, kind, err);
      if (enters_error_state(*err)) st.error_state = st.in_session;  // outside a session there is no error state
      return;
    }
    auto open = st.open.find(tag);
    if (open == st.open.end()) {
      if (kind == '#' || kind == '%') return mismatch(st, l, "a line on a tag with no open transaction");
      if (kind == '!') return mismatch(st, l, "an error on a readable tag before its &");
      first_answer(st, l, tag, kind, err);
      return;
    }
    Transaction& t = open->second;
    if (kind == '&') return mismatch(st, l, "a second & on an open tag");
    if (t.daemon) {
      if (kind != '#') return mismatch(st, l, "after its %, a move daemon sends only # lines");
      move_report(st, l, t, payload);
      return;
    }
    if (!t.first_seen) first_result(st, l, t, kind, err);
    if (kind == '#') {
      ++t.data_lines;
      data_line(st, l, t, payload);
      return;
    }
    if (kind == '!') {
      t.codes.push_back(err->number);
      if (enters_error_state(*err)) st.error_state = st.in_session;
      if (err->severity >= 2) t.error = true;
      return;
    }
    complete(st, l, t);
  }

  // The first line a sent line got: what the parser and the open tags say it must be.
  void first_answer(ClientState& st, const Line& l, const std::string& tag, char kind, const std::optional<ErrorLine>& err) {
    if (st.awaiting.empty()) return mismatch(st, l, "an answer to no line sent");
    // While the normal queue is full, the first line that does not wait for room answers first.
    std::size_t pick = 0;
    if (queue_full(st))
      while (pick + 1 < st.awaiting.size() && waits_for_room(st, pick) &&
             tag != st.awaiting[pick].second.substr(0, 5))
        ++pick;
    const std::string sent = st.awaiting[pick].second;
    const bool reused = sent_tag(sent) && held(st, *sent_tag(sent), pick);
    st.awaiting.erase(st.awaiting.begin() + static_cast<long>(pick));
    const auto verdict = parse_sent(sent);
    std::string want_tag;
    int want_code = -1;
    std::optional<int> refused;
    if (const auto* req = std::get_if<ippdme::Request>(&verdict)) {
      if (st.tracker.is_open(req->tag) || reused) {
        want_tag = "E0000", want_code = ippdme::number_of(ippdme::ErrorCode::IllegalTag);
      } else {
        want_tag = ippdme::tag_text(req->tag);
      }
    } else {  // refused: acknowledged first when its tag is readable, else one E0000 line
      const auto& e = std::get<ippdme::LineError>(verdict);
      want_tag = reused ? std::string("E0000") : ippdme::tag_text(ippdme::answer_tag(e, st.tracker));
      if (want_tag == "E0000") want_code = ippdme::number_of(e.code);
      else refused = ippdme::number_of(e.code);
    }
    const bool want_ack = want_code < 0;
    if (tag != want_tag || (kind == '&') != want_ack || (kind == '!' && (!err || err->number != want_code)))
      return mismatch(st, l, "the answer to '" + escape_line(sent) + "' should be " + want_tag + (want_ack ? " &" : " ! " + zero_padded(want_code, 4)));
    if (want_ack && refused) {
      ++counts.garbled;
      const auto& e = std::get<ippdme::LineError>(verdict);
      st.tracker.try_open(*e.tag);
      Transaction t;
      t.tag = *e.tag;
      t.refused = refused;
      t.opened = l.step;
      if (e.tag->kind == ippdme::TagKind::Command) t.order = ++st.accepted;
      st.open.emplace(tag, std::move(t));
    } else if (want_ack) {
      const auto& req = std::get<ippdme::Request>(verdict);
      ++counts.accepted;
      if (holds<ippdme::AbortE>(req.command))
        for (const auto& [other_tag, other] : st.open)
          if (holds<ippdme::GoTo>(other.command) || holds<ippdme::PtMeas>(other.command)) {
            ++counts.aborts_in_motion;
            break;
          }
      st.tracker.try_open(req.tag);
      Transaction t;
      t.tag = req.tag;
      t.command = req.command;
      t.opened = l.step;
      if (req.tag.kind == ippdme::TagKind::Command) t.order = ++st.accepted;
      st.open.emplace(tag, std::move(t));
    } else {
      ++counts.tag_errors;
    }
  }

  // Rule 1, the error state and the session: judged at a command's first result line (it ran
  // then; motion steps excepted, whose lines come when they end).
  void first_result(ClientState& st, const Line& l, Transaction& t, char kind, const std::optional<ErrorLine>& err) {
    t.first_seen = true;
    const auto& c = t.command;
    if (err && err->number == 6) return;  // aborted before it ran
    if (t.refused) {  // its own error in its turn, in or out of a session and the error state
      if (kind != '!' || !err || err->number != *t.refused)
        mismatch(st, l, "a refused line's first answer after its & must be its error " + zero_padded(*t.refused, 4));
      return;
    }
    const bool session_verb = holds<ippdme::StartSession>(c) || holds<ippdme::EndSession>(c);
    const bool motion = holds<ippdme::GoTo>(c) || holds<ippdme::PtMeas>(c) || holds<ippdme::Home>(c);
    const bool exempt = session_verb || holds<ippdme::ClearAllErrors>(c) || holds<ippdme::GetXtdErrStatus>(c) ||
                        holds<ippdme::AbortE>(c) || holds<ippdme::GetErrStatusE>(c);
    const int code = kind == '!' && err ? err->number : -1;
    const std::string name(ippdme::method_name(c));
    if (!st.in_session && !session_verb) {
      if (code != 8) mismatch(st, l, name + " outside a session must get 0008");
      return;
    }
    if (code == 514 && (!st.error_state || exempt)) return mismatch(st, l, "0514 outside the error state, or for " + name);
    if (motion) return;
    if (st.error_state && !exempt && code != 514) return mismatch(st, l, name + " ran in the error state without 0514");
    if (holds<ippdme::GetErrStatusE>(c) && kind == '#') {
      const std::string want = std::string("ErrStatus(") + (st.error_state ? "1" : "0") + ")";
      if (l.text.substr(8) != want) mismatch(st, l, "the error state is " + want);
    }
    if (holds<ippdme::StartSession>(c) && st.in_session && code != 8) mismatch(st, l, "StartSession inside a session must get 0008");
    const bool daemon_on = std::any_of(st.open.begin(), st.open.end(), [](const auto& o) { return o.second.daemon; });
    if (holds<ippdme::OnMoveReportE>(c) && !st.error_state && daemon_on && code != 515)
      mismatch(st, l, "a second move daemon must get 0515");
  }

  void data_line(ClientState& st, const Line& l, const Transaction& t, const std::string& payload) {
    if (holds<ippdme::Get>(t.command)) {
      const auto got = coordinates(payload);
      if (machine_frame_)
        for (const auto& [c, v] : got) within_travel(c, v, at(l.step) + l.text);
      if (st.last_done && st.last_done->order + 1 == t.order) arrived(l, *st.last_done, got);
    } else if (holds<ippdme::PtMeas>(t.command)) {
      ++counts.ptmeas_points;
      if (t.data_lines > 1) mismatch(st, l, "a second point for one PtMeas");
    } else if (holds<ippdme::OnMoveReportE>(t.command)) {  // a report before its %
      move_report(st, l, t, payload);
    }
  }

  // A move daemon's line: at most 10 a second, and with Time(s) one at least every s (at
  // least 0.1 s) for as long as it runs — AbortE, ClearAllErrors and errors do not stop it.
  void move_report(ClientState& st, const Line& l, const Transaction& daemon, const std::string& payload) {
    ++counts.move_reports;
    if (machine_frame_)
      for (const auto& [c, v] : coordinates(payload)) within_travel(c, v, at(l.step) + l.text);
    if (st.last_report_t) {
      const long gap = l.t - *st.last_report_t;
      const auto time = std::get<ippdme::OnMoveReportE>(daemon.command).time;
      if (gap < 99) fail(at(l.step) + "move reports " + std::to_string(gap) + " ms apart: " + l.text);
      if (time && gap > std::lround(std::max(*time, 0.1) * 1000) + 5)
        fail(at(l.step) + "a move daemon of Time(" + num(*time, 2) + ") silent for " + std::to_string(gap) + " ms: " + l.text);
      else if (time) ++counts.report_gaps_checked;
    }
    st.last_report_t = l.t;
  }

  // Rule 6: a Get queued right behind a GoTo that completed without an error reads the
  // GoTo's target on every axis it named (the machine's own resolution and settling aside).
  void arrived(const Line& l, const Transaction& go_to, const std::map<int, double>& got) {
    const auto& target = std::get<ippdme::GoTo>(go_to.command).target;
    const std::optional<double> want[3] = {target.x, target.y, target.z};
    for (const auto& [c, v] : got) {
      if (!want[c]) continue;
      ++counts.arrivals_checked;
      const double off = std::abs(v - *want[c]);
      counts.arrival_max_off = std::max(counts.arrival_max_off, off);
      if (off > kArrivalTolerance)
        fail(at(l.step) + l.text + ": " + std::string(1, "XYZ"[c]) + " " + num(off, 4) + " mm from the target of " + ippdme::tag_text(go_to.tag));
    }
  }

  // A transaction's `%`: in order, and what it changes of the session.
  void complete(ClientState& st, const Line& l, Transaction& t) {
    const auto& c = t.command;
    ++counts.completed;
    if (t.tag.kind == ippdme::TagKind::Command)
      for (const auto& [tag, other] : st.open)
        if (other.tag.kind == ippdme::TagKind::Command && other.order < t.order)
          return mismatch(st, l, "completes before " + tag + " (accepted earlier, still open)");
    const bool ok = !t.error;
    bool daemon = false;
    if (t.refused) {
      if (t.codes.empty()) return mismatch(st, l, "a refused line completed without its error");
      st.last_done.reset();
      st.tracker.close(t.tag);
      st.open.erase(ippdme::tag_text(t.tag));
      return;
    }
    if (t.tag.kind == ippdme::TagKind::Command) st.last_done = ok && holds<ippdme::GoTo>(c) ? std::optional(t) : std::nullopt;
    if (holds<ippdme::PtMeas>(c) && ok && t.data_lines != 1)
      return mismatch(st, l, "a PtMeas completed without an error and without its point");
    if (holds<ippdme::AbortE>(c) && t.codes.empty())
      for (const auto& [tag, other] : st.open)
        if (other.tag.kind == ippdme::TagKind::Command) return mismatch(st, l, "AbortE's % while " + tag + " is still open");
    if (holds<ippdme::GoTo>(c)) {
      if (ok) ++counts.goto_done;
      if (std::count(t.codes.begin(), t.codes.end(), 2500)) ++counts.goto_limit;
    } else if (holds<ippdme::PtMeas>(c) && !ok) {
      ++counts.ptmeas_errors;
    } else if (holds<ippdme::AbortE>(c)) {
      st.error_state = true;
    } else if (ok && holds<ippdme::ClearAllErrors>(c)) {
      st.error_state = false;
    } else if (ok && holds<ippdme::StartSession>(c)) {
      st.in_session = true, st.error_state = false;
    } else if (ok && holds<ippdme::EndSession>(c) && st.in_session) {
      st.in_session = false, st.error_state = false;
      stop_daemons(st, std::nullopt);
      ended_sessions_.push_back({l.step, holder_before(l.step)});
    } else if (ok && holds<ippdme::StopDaemon>(c)) {
      stop_daemons(st, ippdme::tag_text(std::get<ippdme::StopDaemon>(c).daemon));
    } else if (ok && holds<ippdme::StopAllDaemons>(c)) {
      stop_daemons(st, std::nullopt);
    } else if (ok && holds<ippdme::OnMoveReportE>(c)) {
      daemon = true;
    } else if (ok && holds<ippdme::SetCoordSystem>(c)) {  // frames outlive sessions and clients
      machine_frame_ = std::get<ippdme::SetCoordSystem>(c).csy == ippdme::CoordSystem::MachineCsy;
    }
    if (daemon) {
      t.daemon = true;
      return;
    }
    st.tracker.close(t.tag);
    st.open.erase(ippdme::tag_text(t.tag));
  }

  void stop_daemons(ClientState& st, const std::optional<std::string>& only) {
    for (auto it = st.open.begin(); it != st.open.end();) {
      if (it->second.daemon && (!only || *only == it->first)) {
        st.tracker.close(it->second.tag);
        it = st.open.erase(it);
        st.last_report_t.reset();
      } else {
        ++it;
      }
    }
  }

  // A second I++ client: one E0000 0511 line, then closed.
  void refused(int client) {
    const auto it = s_.streams.find(client);
    std::vector<std::string> got;
    if (it != s_.streams.end())
      for (const auto& l : it->second) got.push_back(l.text);
    const std::vector<std::string> want = {"E0000 ! Error(3, 0511, OneSessionAtATime, \"Error processing method\")", "[connection closed]"};
    if (got != want) fail("the second I++ client " + std::to_string(client) + " was not refused as one session at a time");
    else ++counts.refused_clients;
  }

  // ------------------------------------------------ rule 3: the machine stands
  void rest() {
    for (const auto& p : script_.probes) {
      const auto status = statuses_.find(p.status_step);
      if (status == statuses_.end()) {
        fail(at(p.status_step) + "the Status of a rest probe got no Status reply");
        continue;
      }
      if ((p.kind == RestProbe::End && !ended_within(p.trigger_step, p.status_step)) || (p.kind == RestProbe::Abort && !abort_taken(p))) {
        ++counts.rest_skipped;  // its EndSession still waits behind a move, its AbortE came outside a session
        continue;
      }
      const auto& st = status->second;
      ++counts.rest_checked;
      const long t0 = s_.step_time[static_cast<std::size_t>(p.trigger_step)];
      const std::string what = std::string(p.kind == RestProbe::Abort ? "AbortE" : p.kind == RestProbe::End ? "EndSession" : "drop") +
                               " of step " + std::to_string(p.trigger_step);
      if (st.state == "retract") {
        // Backing off a hit: the motion core's own retract, which it ends by RetractTime.
        const auto stood = stood_at(p.trigger_step);
        if (!stood || *stood - t0 > kRetractWithinMs)
          fail(at(p.status_step) + "State retract after the " + what + ", and no rest within " + std::to_string(kRetractWithinMs) + " ms");
        else ++counts.slow_retracts, counts.retract_max_ms = std::max(counts.retract_max_ms, *stood - t0);
      } else if (st.state != "idle" && st.state != "free" && st.state != "fault") {
        fail(at(p.status_step) + "State " + st.state + " " + std::to_string(s_.step_time[static_cast<std::size_t>(p.status_step)] - t0) +
             " ms after the " + what);
      } else {
        counts.rest_max_ms = std::max(counts.rest_max_ms, standing_after(p.trigger_step, p.status_step) - t0);
      }
      if (p.kind != RestProbe::Abort && st.control != "none" && starts(st.control, "ippdme"))
        fail(at(p.status_step) + "control still with the I++ session after its " + (p.kind == RestProbe::End ? "EndSession" : "drop"));
    }
    for (const auto& [step, holder] : ended_sessions_) {
      if (holder != "ippdme") continue;
      if (control_left_in(step)) ++counts.control_given_back;
      else fail(at(step) + "EndSession while the session held control, and control stayed with it");
    }
  }

  bool ended_within(int from, int to) const {
    for (const auto& [step, holder] : ended_sessions_)
      if (step >= from && step < to) return true;
    return false;
  }

  // When client 1 heard the machine come to rest after step `from` (for the report): its
  // time when the machine stood at the end of that step.
  long standing_after(int from, int until) const {
    std::string state = "free";
    for (const auto& l : s_.streams.at(1)) {
      if (l.sent || l.step >= until || !starts(l.text, "State ")) continue;
      const std::string now = l.text.substr(6);
      const bool stands = now == "idle" || now == "free" || now == "fault";
      if (l.step > from && stands && state != "idle" && state != "free" && state != "fault") return l.t;
      state = now;
    }
    return s_.step_time[static_cast<std::size_t>(from)];
  }

  // When client 1 heard the machine stand after step `from`, with no motion starting before.
  std::optional<long> stood_at(int from) const {
    for (const auto& l : s_.streams.at(1)) {
      if (l.sent || l.step <= from || !starts(l.text, "State ")) continue;
      const std::string now = l.text.substr(6);
      if (now == "idle" || now == "free" || now == "fault") return l.t;
      if (now != "retract" && now != "stopping") return std::nullopt;
    }
    return std::nullopt;
  }

  // Whether the AbortE of a rest probe was taken (`%` without `!`: in a session).
  bool abort_taken(const RestProbe& p) const {
    bool refused = false;
    for (const auto& l : s_.streams.at(p.client)) {
      if (l.sent || l.step != p.trigger_step || !starts(l.text, p.tag + " ")) continue;
      if (l.text == p.tag + " %") return !refused;
      if (l.text[6] == '!') refused = true;
    }
    return false;
  }

  // ------------------------------------------------ rule 4
  // The new client's StartSession, SetCoordSystem, Get and EndSession without an error, its
  // position within the travel; client 1's last Status answered.
  void final_session() {
    const auto reply = panel_replies_.find(script_.final_status_step);
    if (reply == panel_replies_.end() || !starts(reply->second, "Ok Status ")) fail("client 1's last Status got no Ok Status");
    std::vector<std::string> got;
    if (const auto it = s_.streams.find(script_.final_client); it != s_.streams.end())
      for (const auto& l : it->second)
        if (!l.sent) got.push_back(l.text);
    const auto position = std::find_if(got.begin(), got.end(), [](const std::string& l) { return l.size() > 9 && l.substr(5, 4) == " # X"; });
    const bool errors = std::any_of(got.begin(), got.end(), [](const std::string& l) { return l.size() > 6 && l[6] == '!'; });
    if (got.size() != 9 || errors || position == got.end()) {
      fail("the last I++ client could not start a session and read its position: " + std::to_string(got.size()) + " lines" +
           (got.empty() ? std::string() : ", the first '" + got[0] + "'") + (errors ? ", errors" : ""));
      return;
    }
    ++counts.final_checks;
    for (const auto& [c, v] : coordinates(position->substr(8))) within_travel(c, v, "the last client's Get");
  }

  const Machine& m_;
  const Script& script_;
  const Session& s_;
  std::vector<std::string> holder_after_;
  std::map<int, std::vector<std::string>> control_lines_;                // client 1's Control lines per step
  std::map<int, std::pair<std::string, std::string>> panel_moves_;       // step -> command, holder before
  std::map<int, std::string> panel_replies_;                             // step sent -> reply
  std::map<int, StatusReply> statuses_;                                  // step sent -> Status
  bool machine_frame_ = true;  // the sessions' coordinate system is the machine's: positions to check against the travel
  std::vector<std::pair<int, std::string>> ended_sessions_;              // step of EndSession's %, holder before
};

}  // namespace

Verdict check_session(const Machine& m, const Script& script, const std::vector<Entry>& out, const std::optional<core::Snapshot>& end) {
  const Session session = read_session(out, m.period_us);
  Checker check(m, script, session);
  check.run();
  if (end) check.core_position(*end);
  check.counts.virtual_ms = session.step_time.empty() ? 0 : session.step_time.back();
  return {check.problems, check.counts};
}

}  // namespace imess::golden::ippdme_properties
