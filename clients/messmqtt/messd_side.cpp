// The bridge's observer link to messd (messd_side.hpp).
#include "messd_side.hpp"

namespace imess::mqtt {

namespace {
std::string line_of(const Command& c) {
  switch (c.kind) {
    case Command::Kind::Hello: return "Hello messmqtt";
    case Command::Kind::Status: return "Status";
    case Command::Kind::Program: return "Program";
    case Command::Kind::CatchUp:
    case Command::Kind::Request: return "Replay " + std::to_string(c.from);
    case Command::Kind::Stop: return "StopMv";
  }
  return "Status";
}
}  // namespace

MessdSide::MessdSide(client::Endpoint where, Handlers handlers)
    : link_(std::move(where), client::Reconnector::Options{std::chrono::milliseconds{500}, std::chrono::milliseconds{500}}),
      handlers_(std::move(handlers)) {}

bool MessdSide::send(Command command) {
  if (!link_.connected()) return false;
  if (!link_.send_line(line_of(command))) {
    lost("the link to messd broke while sending");
    return false;
  }
  in_flight_.push_back(std::move(command));
  return true;
}

void MessdSide::lost(const std::string& why) {
  link_.lost();
  in_flight_.clear();
  if (handlers_.lost) handlers_.lost(why);
}

void MessdSide::line(std::string_view l) {
  const bool reply = l.substr(0, 3) == "Ok " || l == "Ok" || l.substr(0, 4) == "Err ";
  if (reply && !in_flight_.empty()) {
    const Command c = in_flight_.front();
    in_flight_.pop_front();
    if (handlers_.replied) handlers_.replied(c, l);
    return;
  }
  if (l.substr(0, 7) == "Replay " && handlers_.replay_data) {
    handlers_.replay_data(l);
    return;
  }
  if (handlers_.event) handlers_.event(l);
}

void MessdSide::service(bool readable, std::chrono::steady_clock::time_point now) {
  if (auto* c = link_.connection()) {
    if (!readable) return;
    const auto status = c->receive([this](std::string_view l) { line(l); });
    if (status == client::ReadStatus::Closed) lost(c->close_reason());
    return;
  }
  if (link_.maintain(now)) {
    announced_down_ = false;
    if (handlers_.connected) handlers_.connected();
  } else if (!announced_down_ && handlers_.lost && link_.attempts() > 0) {
    announced_down_ = true;
    handlers_.lost(link_.last_error());
  }
}

void MessdSide::finish() {
  if (auto* c = link_.connection()) c->finish();
}

}  // namespace imess::mqtt
