// MachineLink: requests, queued moves and probes over messd's protocol (machine_link.hpp).
#include "machine_link.hpp"

#include <cstdio>
#include <sstream>

#include "imess/client/connect_error.hpp"

namespace imess::messcap {
namespace {

constexpr auto kReplyTimeout = std::chrono::seconds{10};

bool starts_with(std::string_view line, std::string_view prefix) { return line.substr(0, prefix.size()) == prefix; }

double number_word(const std::string& word, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(word, &used);
    if (used == word.size()) return v;
  } catch (const std::exception&) {
  }
  throw MachineError("messd answered '" + word + "' for " + what + ", not a number");
}

}  // namespace

std::string xyz_words(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "X%.4f Y%.4f Z%.4f", p.x(), p.y(), p.z());
  return buf;
}

MachineLink::MachineLink(const client::Endpoint& endpoint) {
  try {
    link_ = std::make_unique<client::Connection>(client::Connection::open(endpoint));
  } catch (const client::ConnectError& e) {
    throw MachineError(e.what());
  }
}

void MachineLink::send(const std::string& line) {
  if (!link_->send_line(line)) throw MachineError("messd went away (" + link_->close_reason() + ")");
}

// Reads lines until `done` holds, handling every event on the way.
template <class Pred>
void MachineLink::read_until(Pred done, std::chrono::seconds timeout, const std::string& waiting_for) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline)
      throw MachineError("no answer from messd within " + std::to_string(timeout.count()) + " s while waiting for " + waiting_for);
    const auto status = link_->poll_lines(std::chrono::milliseconds{200}, [this](std::string_view l) { on_line(l); });
    if (status == client::ReadStatus::Closed)
      throw MachineError("messd closed the connection (" + link_->close_reason() + ") while waiting for " + waiting_for);
  }
}

std::string MachineLink::try_request(const std::string& line) {
  reply_.reset();
  send(line);
  read_until([this] { return reply_.has_value(); }, kReplyTimeout, "the reply to '" + line + "'");
  return *reply_;
}

std::string MachineLink::request(const std::string& line) {
  const std::string reply = try_request(line);
  if (starts_with(reply, "Err ")) throw MachineError("messd refused '" + line + "': " + reply);
  return reply;
}

void MachineLink::on_line(std::string_view line) {
  if (starts_with(line, "Ok ") || line == "Ok" || starts_with(line, "Err ")) {
    reply_ = std::string(line);
    return;
  }
  if (starts_with(line, "Done ") || starts_with(line, "Failed ")) {
    std::istringstream words{std::string(line)};
    std::string verb;
    std::uint64_t id = 0;
    if (words >> verb >> id) ended_[id] = std::string(line);
    return;
  }
  if (starts_with(line, "Fault ")) fault_ = std::string(line);
  auto message = protocol::parse_message(line);
  if (auto* hit = std::get_if<protocol::HitMsg>(&message); hit && hit->id != 0) {
    hits_[hit->id].push_back(*hit);
    return;
  }
  if (on_event) on_event(line);
}

std::uint64_t MachineLink::queued(const std::string& verb, const std::string& words, std::chrono::seconds timeout) {
  const std::uint64_t id = next_id_++;
  const std::string line = verb + " " + std::to_string(id) + " " + words;
  request(line);
  read_until([&] { return ended_.count(id) > 0; }, timeout, "the end of '" + line + "'");
  const std::string end = ended_[id];
  if (!starts_with(end, "Done ")) {
    std::istringstream w(end);
    std::string failed, number, reason;
    w >> failed >> number >> reason;
    throw MoveFailed("'" + line + "' ended with '" + end + "'" + (fault_.empty() ? "" : " (" + fault_ + ")"), reason);
  }
  return id;
}

protocol::HitMsg MachineLink::probe(const std::string& words) {
  const std::uint64_t id = queued("Probe", words);
  const auto it = hits_.find(id);
  const std::size_t count = it == hits_.end() ? 0 : it->second.size();
  if (count != 1)
    throw MachineError("Probe " + std::to_string(id) + " " + words + " ended with " + std::to_string(count) +
                       " hits (expected 1)");
  return it->second.front();
}

std::vector<protocol::HitMsg> MachineLink::scan(const std::string& verb, const std::string& words,
                                                std::chrono::seconds timeout) {
  const std::uint64_t id = queued(verb, words, timeout);
  std::vector<protocol::HitMsg> points;
  if (auto it = hits_.find(id); it != hits_.end()) {
    for (auto& h : it->second)
      if (h.scan) points.push_back(h);
    hits_.erase(it);
  }
  if (points.empty())
    throw MachineError(verb + " " + std::to_string(id) + " " + words + " ended with no Scan points");
  return points;
}

double MachineLink::get_number(const std::string& name) {
  std::istringstream words(request("Get " + name));
  std::string ok, get, got, value;
  if (!(words >> ok >> get >> got >> value) || got != name)
    throw MachineError("messd's reply to 'Get " + name + "' holds no value of " + name);
  return number_word(value, name);
}

std::vector<std::string> MachineLink::status_words() {
  std::istringstream in(request("Status"));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

double MachineLink::status_number(const std::string& word) {
  const auto words = status_words();
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (words[i] == word) return number_word(words[i + 1], "Status " + word);
  throw MachineError("messd's Status holds no " + word);
}

Eigen::Vector3d MachineLink::status_position() {
  const auto words = status_words();
  for (std::size_t i = 0; i + 3 < words.size(); ++i)
    if (words[i] == "Pos")
      return {number_word(words[i + 1], "Status Pos"), number_word(words[i + 2], "Status Pos"),
              number_word(words[i + 3], "Status Pos")};
  throw MachineError("messd's Status holds no Pos");
}

void MachineLink::finish() { link_->finish(); }

}  // namespace imess::messcap
