// The MESSD server's configuration (docs/configuration.md, "server" and "control") and the
// listening socket every front end opens the same way.
#pragma once
#include <boost/asio/ip/tcp.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "imess/net/host_list.hpp"
#include "imess/net/ipp_config.hpp"
#include "imess/net/program_run.hpp"
#include "imess/net/web_config.hpp"

namespace imess::net {

// Who may connect, control and force a take-over; slots kept for controllers; when a
// client counts as gone (docs/configuration.md, "control").
struct ControlConfig {
  HostList hosts = loopback_hosts();          // may take control
  HostList observe_hosts = any_host();        // may connect and observe (control hosts may too)
  HostList force_hosts = loopback_hosts();    // may Take force (must also be in hosts)
  std::size_t reserved_slots = 4;             // of max_clients, only for hosts in `hosts`
  double idle_drop_s = 300;                   // silent this long while controlling or watching: dropped
  double handover_s = 2;                      // an owner without a command this long, the machine at rest
                                              // and nothing queued, hands control to the next who asks (0: never)
  double no_command_drop_s = 300;             // from a control host, no command this long after connecting: dropped (0: never)
  double write_stall_s = 10;                  // one write unfinished this long (not reading): dropped
  std::uint32_t max_in_flight = 32;           // per client, commands waiting in the motion loop's ring
};

struct ServerConfig {
  std::string listen = "0.0.0.0";
  std::uint16_t port = 1066;      // 0: any free port (tests)
  double report_hz = 10;          // CurrCor rate, only when the position changed
  // false: CurrCor only on connect, no rate timer — for the golden transcripts, which run the
  // machine in virtual time and must not depend on a wall-clock timer (tests/golden/README.md).
  bool stream_position = true;
  std::size_t max_clients = 100;
  std::size_t max_queue_bytes = 1 << 20;  // per client; beyond it a non-reading client is dropped
  bool log_traffic = false;       // -dc
  bool log_motion = false;        // -dm
  bool log_status = false;        // -dt
  bool log_timing = false;        // -p
  bool beep = true;               // BEL on the console for every point (when it is a terminal)
  // Events are drained when the motion loop wakes the io thread; this timer only catches a
  // wake-up that never came (and is the only drain when the server has no EventFd).
  double event_backstop_ms = 50;
  double reply_timeout_s = 2;     // a reply slot unanswered this long (answer lost) becomes Err 500
  ControlConfig control;
  std::string version = "0.1.0";
  double period_us = 1000;          // the motion loop's period (Get Period)
  std::string backend = "unknown";  // the backend type (Get Backend): one word
  ProgramConfig programs;           // the programs folder and how program words map to this machine
  IppConfig ippdme;                 // the I++ DME server (TCP 1294) and its tools
  WebConfig web;                    // the web panel (HTTP and WebSocket on 8080)
  std::string frames_file;          // the part frames' store (JSON); empty: kept for this run only
  std::array<double, 3> probe_offset{};  // ProbeOffX/Y/Z: added to every measured point (mm)
};

// Opens, binds and listens on listen:port (0: any free port); returns the port. Throws
// std::runtime_error naming the address (with `busy_hint` when the port is taken); `what`
// names the listener (" for I++ DME").
std::uint16_t open_listener(boost::asio::ip::tcp::acceptor& acceptor, const std::string& listen, std::uint16_t port,
                            std::string_view what, std::string_view busy_hint);

}  // namespace imess::net
