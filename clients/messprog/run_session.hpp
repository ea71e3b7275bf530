// The conversation of `messprog run` with messd, as pure logic (no sockets, no terminal):
// Hello messprog (its Caps must name `programs`), Take, Upload <name>, after its `Ok Upload`
// the program's lines + ".", then Run [detached] once messd answered `Ok Load`; then the Block, ProgPause
// and ProgEnd events, and what Ctrl-C and the operator's answers send. Every step returns
// what to send, what to print and, at the end, the exit status.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prog_events.hpp"
#include "upload.hpp"

namespace imess::messprog {

struct RunOutput {
  std::vector<std::string> send;     // lines for messd, in order
  std::vector<std::string> notes;    // for stdout
  std::vector<std::string> errors;   // for stderr
  std::optional<BlockEvent> block;   // the block now executing (for the progress line)
  bool ask = false;                  // ask the operator "abort or resume? [a/r]"
  std::optional<ProgEndEvent> end;   // the program ended
  std::optional<int> exit;           // messprog is done: exit with this status
};

class RunSession {
 public:
  // Announcing: "Upload <name>" sent, its Ok awaited; Uploading: the lines and "." sent.
  enum class Phase { Greeting, Taking, Announcing, Uploading, Starting, Running, Ended };

  struct Settings {
    std::string file;       // as named on the command line, for messages
    std::string where;      // "localhost:1066"
    bool detached = false;  // Run detached
    bool interactive = false;  // stdin is a terminal: Ctrl-C pauses and asks
  };

  RunSession(Upload upload, Settings settings);

  RunOutput start();                          // after connecting: Hello
  RunOutput on_line(std::string_view line);   // a line from messd
  RunOutput interrupt();                      // Ctrl-C (SIGINT)
  RunOutput terminate();                      // SIGTERM: abort, never ask
  RunOutput answer(std::string_view text);    // the operator's answer to the question
  RunOutput lost(std::string_view reason);    // the connection ended

  Phase phase() const { return phase_; }
  bool asking() const { return asking_; }
  // For the keep-alive blank line: never while messd awaits the program's lines (Announcing),
  // where a blank line would be one of them.
  bool holds_control() const {
    return phase_ != Phase::Greeting && phase_ != Phase::Taking && phase_ != Phase::Announcing && phase_ != Phase::Ended;
  }

 private:
  RunOutput on_reply(std::string_view line);
  RunOutput on_event(std::string_view line);
  RunOutput finish(RunOutput out, int status);
  RunOutput abort(RunOutput out);
  std::string source_line(int line) const;

  Upload upload_;  // its lines are also the source shown with a failure
  Settings settings_;
  Phase phase_ = Phase::Greeting;
  bool asking_ = false;
  bool abort_sent_ = false;
};

}  // namespace imess::messprog
