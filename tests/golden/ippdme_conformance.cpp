// The conformance replay's rules (ippdme_conformance.hpp): framing on every line the I++ client
// received, then the file's own `#? ` expectations.
#include "ippdme_conformance.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/parser.hpp"

namespace imess::golden {
namespace {

constexpr int kIppClient = 2;
constexpr double kTolerance = 0.05;  // mm: a position read after a move (the servo's following error)
const std::string kServerTag = "E0000";

enum class Phase { Sent, Acked, Done };

struct Transaction {
  Phase phase = Phase::Sent;
  bool daemon = false;  // OnMoveReportE: `#` lines follow its `%`
  std::vector<std::string> lines;
};

struct ErrorFields {
  int severity = -1, number = -1;
  std::string text;
};

std::optional<ErrorFields> error_fields(const std::string& payload) {
  ErrorFields e;
  char number[5] = {};
  if (std::sscanf(payload.c_str(), "Error(%d, %4[0-9], ", &e.severity, number) != 2) return std::nullopt;
  e.number = std::atoi(number);
  const auto open = payload.rfind(", \"");
  if (open == std::string::npos || payload.size() < open + 5 || payload.substr(payload.size() - 2) != "\")") return std::nullopt;
  e.text = payload.substr(open + 3, payload.size() - open - 5);
  return e;
}

std::string method_of(const std::string& sent) {
  if (sent.size() < 7) return {};
  const std::string call = sent.substr(6);
  const auto end = call.find_first_of("( ");
  return end == std::string::npos ? std::string() : call.substr(0, end);
}

bool is_command_tag(const std::string& tag) { return !tag.empty() && tag[0] != 'E'; }

class Checker {
 public:
  explicit Checker(ConformanceReport& report) : r_(report) {}

  void sent(const std::string& text) {
    r_.methods.insert(method_of(text));
    const auto readable = ippdme::readable_tag(text);
    if (!readable) return;  // answered on E0000 alone
    const std::string tag = text.substr(0, 5);
    auto it = open_.find(tag);
    if (it != open_.end() && (it->second.phase != Phase::Done || it->second.daemon)) return;  // open: E0000 0001
    Transaction t;
    t.daemon = text.find(" OnMoveReportE(") == 5;
    open_[tag] = t;
    if (is_command_tag(tag)) order_sent_.push_back(tag);
  }

  void received(const std::string& line) {
    r_.received.push_back(line);
    if (line.find("[no CR]") != std::string::npos || line.size() < 7 || line[5] != ' ')
      return fail("not a response line (tag, space, &#!%, CR LF): " + line);
    const std::string tag = line.substr(0, 5);
    const char kind = line[6];
    const bool bare = kind == '&' || kind == '%';
    if ((kind != '&' && kind != '#' && kind != '!' && kind != '%') || (bare && line.size() != 7) ||
        (!bare && (line.size() < 9 || line[7] != ' ')))
      return fail("not a response line: " + line);
    if (kind == '!') check_error(line.substr(8), line);
    if (tag == kServerTag) {
      if (bare) fail("E0000 carries no & or %: " + line);
      server_lines_.push_back(line);
      return;
    }
    auto it = open_.find(tag);
    if (it == open_.end()) return fail("a line on a tag the client never sent: " + line);
    Transaction& t = it->second;
    t.lines.push_back(line);
    all_[tag].push_back(line);
    switch (t.phase) {
      case Phase::Sent:
        if (kind != '&') return fail("answered before its Ack: " + line);
        t.phase = Phase::Acked;
        return;
      case Phase::Acked:
        if (kind == '&') return fail("a second Ack: " + line);
        if (kind == '%') {
          t.phase = Phase::Done;
          if (is_command_tag(tag)) order_done_.push_back(tag);
        }
        return;
      case Phase::Done:
        if (!(t.daemon && kind == '#')) fail("a line after the transaction's %: " + line);
        return;
    }
  }

  void finish() {
    for (const auto& [tag, t] : open_)
      if (t.phase != Phase::Done) fail(tag + ": never completed (no %)");
    if (order_done_ != order_sent_) fail("command tags completed out of the order sent");
  }

  void expect(const std::string& spec) {
    std::istringstream in(spec);
    std::string tag, what;
    in >> tag >> what;
    std::string rest;
    std::getline(in, rest);
    if (!rest.empty() && rest[0] == ' ') rest.erase(0, 1);
    if (tag == kServerTag) return expect_server(what, rest, spec);
    const auto& lines = all_[tag];
    auto has = [&](const std::string& l) {
      for (const auto& x : lines)
        if (x == l) return true;
      return false;
    };
    auto count = [&](char kind) {
      int n = 0;
      for (const auto& x : lines) n += x[6] == kind;
      return n;
    };
    const bool framed = !lines.empty() && lines.front() == tag + " &" && has(tag + " %");
    if (what == "none") {
      if (!lines.empty()) fail(spec + ": got " + lines.front());
    } else if (what == "ok") {
      if (!framed || count('!') != 0) fail(spec + ": " + describe(lines));
    } else if (what == "error") {
      const int number = std::atoi(rest.c_str());
      r_.expected_errors.insert(number);
      if (number == 514) allowed_514_.insert(tag);
      bool found = false;
      for (const auto& x : lines)
        if (x[6] == '!')
          if (auto e = error_fields(x.substr(8)); e && e->number == number) found = true;
      if (!framed || !found) fail(spec + ": " + describe(lines));
    } else if (what == "data") {
      if (!has(tag + " # " + rest)) fail(spec + ": " + describe(lines));
    } else if (what == "near") {
      bool found = false;
      for (const auto& x : lines)
        if (x[6] == '#' && near_payload(rest, x.substr(8), kTolerance)) found = true;
      if (!found) fail(spec + ": " + describe(lines));
    } else if (what == "lines") {
      if (count('#') != std::atoi(rest.c_str())) fail(spec + ": " + describe(lines));
    } else if (what == "reports") {
      const auto done = std::find(lines.begin(), lines.end(), tag + " %");
      const long after = done == lines.end() ? 0 : static_cast<long>(lines.end() - done) - 1;
      if (after < std::atol(rest.c_str())) fail(spec + ": " + describe(lines));
    } else {
      fail("unknown expectation: " + spec);
    }
  }

  void no_unexpected_514() {
    for (const auto& [tag, lines] : all_)
      for (const auto& l : lines)
        if (l.find("! Error(2, 0514,") != std::string::npos && !allowed_514_.count(tag))
          fail("the error state refused a command the file does not expect refused: " + l);
  }

 private:
  void fail(const std::string& why) { r_.failures.push_back(why); }

  void check_error(const std::string& payload, const std::string& line) {
    const auto e = error_fields(payload);
    if (!e) return fail("not Error(F1, F2, F3, \"text\"): " + line);
    const auto* info = ippdme::find_error(e->number);
    if (!info || ippdme::severity_number(info->severity) != e->severity || info->text != e->text)
      fail("severity or text not the spec's for that number: " + line);
  }

  void expect_server(const std::string& what, const std::string& rest, const std::string& spec) {
    bool found = false;
    for (const auto& l : server_lines_) {
      if (what == "error" && l[6] == '!') {
        auto e = error_fields(l.substr(8));
        found = found || (e && e->number == std::atoi(rest.c_str()));
      }
      if (what == "event" && l[6] == '#') found = found || l.compare(8, rest.size(), rest) == 0;
    }
    if (what == "error") r_.expected_errors.insert(std::atoi(rest.c_str()));
    if (what != "error" && what != "event") return fail("unknown expectation: " + spec);
    if (!found) fail(spec + ": not among the E0000 lines (" + std::to_string(server_lines_.size()) + ")");
  }

  static std::string describe(const std::vector<std::string>& lines) {
    std::string out = "got [";
    for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? " | " : "") + lines[i];
    return out + "]";
  }

  ConformanceReport& r_;
  std::map<std::string, Transaction> open_;
  std::map<std::string, std::vector<std::string>> all_;  // every line on a tag, across reuses
  std::vector<std::string> order_sent_, order_done_, server_lines_;
  std::set<std::string> allowed_514_;
};

}  // namespace

bool near_payload(const std::string& expected, const std::string& actual, double tolerance) {
  std::size_t i = 0, j = 0;
  auto number_at = [](const std::string& s, std::size_t& p, double& v) {
    const char* start = s.c_str() + p;
    char* end = nullptr;
    const bool starts = std::isdigit(static_cast<unsigned char>(s[p])) || ((s[p] == '-' || s[p] == '+') && p + 1 < s.size());
    if (!starts) return false;
    v = std::strtod(start, &end);
    if (end == start) return false;
    p += static_cast<std::size_t>(end - start);
    return true;
  };
  while (i < expected.size() && j < actual.size()) {
    double a = 0, b = 0;
    std::size_t ii = i, jj = j;
    if (number_at(expected, ii, a) && number_at(actual, jj, b)) {
      if (!(std::fabs(a - b) <= tolerance)) return false;
      i = ii;
      j = jj;
      continue;
    }
    if (expected[i] != actual[j]) return false;
    ++i;
    ++j;
  }
  return i == expected.size() && j == actual.size();
}

ConformanceReport check_conformance(const std::vector<Entry>& script, const std::vector<Entry>& replayed) {
  ConformanceReport report;
  Checker c(report);
  for (const auto& e : replayed) {
    if (e.client != kIppClient) continue;
    if (e.kind == EntryKind::Send) c.sent(e.text);
    if (e.kind == EntryKind::Receive) c.received(e.text);
  }
  c.finish();
  for (const auto& e : script)
    if (e.kind == EntryKind::Comment && e.text.rfind("#? ", 0) == 0) c.expect(e.text.substr(3));
  c.no_unexpected_514();
  return report;
}

}  // namespace imess::golden
