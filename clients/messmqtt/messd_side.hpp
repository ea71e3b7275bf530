// MessdSide: the bridge's link to messd, as an observer. It sends only `Hello messmqtt`,
// `Status`, `Program`, `Replay <from>` (read-only) and `StopMv` (open to every client, takes no
// control): never a command that moves the machine. messd answers every command line with one
// `Ok`/`Err` reply in order, so the commands in flight are a FIFO and each reply is matched to
// its command — which is how a `Replay`'s `Ok Replay count newest` finds the request it ends.
#pragma once
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>

#include "imess/client/reconnector.hpp"

namespace imess::mqtt {

struct Command {
  enum class Kind { Hello, Status, Program, CatchUp, Request, Stop } kind;
  std::uint64_t from = 0;   // Replay's
  std::string reply_to;     // a broker request's answer topic level
};

class MessdSide {
 public:
  struct Handlers {
    std::function<void()> connected;  // send Hello, Status ... now
    std::function<void(const std::string& why)> lost;
    std::function<void(std::string_view line)> event;             // any line that is not a reply
    std::function<void(const Command&, std::string_view reply)> replied;  // "Ok ..."/"Err ..." of a command
    std::function<void(std::string_view line)> replay_data;       // "Replay Lost ..." lines
  };

  MessdSide(client::Endpoint where, Handlers handlers);

  void service(bool readable, std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  int fd() const { return link_.fd(); }
  bool connected() const { return link_.connected(); }
  std::chrono::milliseconds until_due() const { return link_.until_next_attempt(); }
  bool send(Command command);
  const std::deque<Command>& in_flight() const { return in_flight_; }
  const client::Endpoint& endpoint() const { return link_.endpoint(); }
  void finish();

 private:
  void line(std::string_view l);
  void lost(const std::string& why);

  client::Reconnector link_;
  Handlers handlers_;
  std::deque<Command> in_flight_;
  bool announced_down_ = false;
};

}  // namespace imess::mqtt
