// Transactions: what messipp still waits for from the server. Every line sent opens one; it is
// answered by its Ack `&`, and ends with its `%` — or with an error on E0000 when the server
// cannot use the tag (a malformed tag, a tag still open, the wrong queue), which no `%`
// follows. A line refused at once gets `!` and `%` on its tag without an Ack. A daemon such as
// OnMoveReportE ends here at its `%`; the lines it goes on sending after that carry a tag no
// longer tracked. Pure.
#pragma once
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace imess::messipp {

class Transactions {
 public:
  // A line went out with the five characters `tag` ("00001", "E0003", even "00000" sent raw).
  void sent(std::string_view tag);

  // A line from the server. True when it answered an open transaction (progress, for the
  // timeout); false for anything else (E0000 events, a daemon's reports, lines of no tag).
  bool received(std::string_view line);

  // The last line sent has its Ack, or has ended: the spec lets a client send the next command
  // only after the previous one's Ack (IPPDME.md §3).
  bool last_answered() const;
  // Every line sent has its `%`.
  bool all_complete() const { return open_.empty(); }
  // An open transaction carries `tag` (a second line with it would be refused: tag reuse).
  bool is_open(std::string_view tag) const;
  // The tags of the open transactions, in the order sent.
  std::vector<std::string> open_tags() const;

 private:
  struct Open {
    std::string tag;
    bool answered = false;
  };
  std::deque<Open> open_;  // in the order sent
};

}  // namespace imess::messipp
