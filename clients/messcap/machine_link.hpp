// MachineLink: a measuring client's conversation with messd, one command at a time — a request
// answered Ok or Err, a queued move (MoveTo, Probe, ScanCirc, ScanLine) waited for until its
// Done, the Hit of a Probe and the Scan points of a scan collected by its id. Shared by
// `messcap inspect` and `messcap qualify`.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "imess/client/connection.hpp"
#include "imess/client/endpoint.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::messcap {

// messd unreachable, a refused command, a failed move or probe: the message says which and why.
class MachineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A queued command that ended Failed: `reason` is messd's word (PartNotFound, UnexpectedHit, …).
class MoveFailed : public MachineError {
 public:
  MoveFailed(const std::string& what, std::string reason) : MachineError(what), reason_(std::move(reason)) {}
  const std::string& reason() const noexcept { return reason_; }

 private:
  std::string reason_;
};

// "X1.0000 Y2.0000 Z3.0000": the words of a MoveTo or Probe target (0.1 µm).
std::string xyz_words(const Eigen::Vector3d& p);

class MachineLink {
 public:
  explicit MachineLink(const client::Endpoint& endpoint);  // throws MachineError

  // One command, one reply line: the Ok line is returned, an Err is thrown naming the command.
  std::string request(const std::string& line);
  // The same, the reply returned whichever it is (for commands an older messd may not know).
  std::string try_request(const std::string& line);

  // A queued command ("MoveTo", "X.. F..") under the next id: Ok, then its Done within
  // `timeout`. Returns the id. Throws MoveFailed when it ends Failed.
  std::uint64_t queued(const std::string& verb, const std::string& words,
                       std::chrono::seconds timeout = std::chrono::seconds{120});
  // A Probe toward `words` that must give exactly one Hit; returns it.
  protocol::HitMsg probe(const std::string& words);
  // A scan ("ScanCirc" or "ScanLine" and its words after the id) that must give Scan points;
  // returns them in the order taken.
  std::vector<protocol::HitMsg> scan(const std::string& verb, const std::string& words, std::chrono::seconds timeout);

  // `Get name` as a number; `Status`'s value after `word` (TipRadius, Pos: the first number).
  double get_number(const std::string& name);
  double status_number(const std::string& word);
  Eigen::Vector3d status_position();

  // Every line that is no reply, Done/Failed or Probe Hit (events such as Qualified) is handed
  // to this, if set.
  std::function<void(std::string_view)> on_event;

  void finish();  // ends the link without losing the last line sent

 private:
  void send(const std::string& line);
  template <class Pred>
  void read_until(Pred done, std::chrono::seconds timeout, const std::string& waiting_for);
  void on_line(std::string_view line);
  std::vector<std::string> status_words();

  std::unique_ptr<client::Connection> link_;
  std::uint64_t next_id_ = 1;
  std::optional<std::string> reply_;
  std::map<std::uint64_t, std::string> ended_;
  std::map<std::uint64_t, std::vector<protocol::HitMsg>> hits_;
  std::string fault_;
};

}  // namespace imess::messcap
