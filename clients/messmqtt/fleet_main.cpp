// messfleet: every machine on an MQTT broker, live in the terminal (docs/mqtt.md).
#include <poll.h>

#include <cstdio>
#include <iostream>
#include <string_view>

#include "bridge_config.hpp"
#include "fleet_view.hpp"
#include "imess/client/stop_signal.hpp"
#include "imess/client/usage_error.hpp"
#include "mqtt_link.hpp"

namespace {

struct FleetOptions {
  imess::client::Endpoint broker{"localhost", imess::mqtt::kDefaultBrokerPort};
  std::string user, password_file, tls_ca;
  bool once = false, json = false, help = false;
  int wait_ms = 2000;
};

const char* const kUsage =
    "usage: messfleet [BROKER[:PORT]] [--once] [--json] [--wait MS] [--user USER --password-file FILE]\n"
    "                 [--tls-ca FILE]\n"
    "Shows every machine on the MQTT broker (default localhost:1883) that a messmqtt bridge\n"
    "publishes: online, state, control, position, program, last hit, last inspection result;\n"
    "redrawn as messages arrive, until Ctrl-C.\n"
    "\n"
    "  --once       print the view once the broker's retained messages are in, then exit\n"
    "               (waits until nothing came for 0.3 s, at most --wait MS, default 2000)\n"
    "  --json       the view as one JSON object (with --once: one line; else a line per change)\n"
    "  --user USER, --password-file FILE, --tls-ca FILE   as for messmqtt\n"
    "  -h, --help   this text\n"
    "\n"
    "Exit status: 0; 1 when the broker cannot be reached (--once); 2 on bad arguments.\n";

FleetOptions parse(int argc, char* argv[]) {
  using imess::client::UsageError;
  FleetOptions o;
  bool have_host = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc) throw UsageError(std::string(a) + " needs " + what);
      return argv[++i];
    };
    if (a == "-h" || a == "--help") o.help = true;
    else if (a == "--once") o.once = true;
    else if (a == "--json") o.json = true;
    else if (a == "--user") o.user = value("a user name");
    else if (a == "--password-file") o.password_file = value("a file name");
    else if (a == "--tls-ca") o.tls_ca = value("a file name");
    else if (a == "--wait") {
      const auto v = value("milliseconds");
      char* end = nullptr;
      const long ms = std::strtol(v.c_str(), &end, 10);
      if (!end || *end || ms < 100 || ms > 600000) throw UsageError("--wait takes milliseconds from 100 to 600000, got '" + v + "'");
      o.wait_ms = static_cast<int>(ms);
    } else if (a.size() > 1 && a.front() == '-')
      throw UsageError("unknown option '" + std::string(a) +
                       "'; accepted: --once, --json, --wait, --user, --password-file, --tls-ca, --help");
    else {
      if (have_host) throw UsageError("one broker only, got a second: '" + std::string(a) + "'");
      o.broker = imess::client::parse_endpoint(a, o.broker);
      have_host = true;
    }
  }
  return o;
}

}  // namespace

int main(int argc, char* argv[]) {
  using namespace imess;
  using Clock = std::chrono::steady_clock;
  FleetOptions o;
  std::string password;
  try {
    o = parse(argc, argv);
    if (o.help) {
      std::cout << kUsage;
      return client::kExitOk;
    }
    if (!o.user.empty() && o.password_file.empty()) throw client::UsageError("--user needs --password-file");
    if (!o.password_file.empty()) password = mqtt::read_password(o.password_file);
  } catch (const client::UsageError& e) {
    std::cerr << "messfleet: " << e.what() << "\n(try messfleet --help)\n";
    return client::kExitUsage;
  }
  mqtt::FleetView view;
  bool changed = false, subscribed = false;
  std::string error;
  auto last_message = Clock::now();
  mqtt::MqttLink* self = nullptr;
  mqtt::MqttLink link(
      mqtt::LinkOptions{o.broker.host, o.broker.port, "", o.user, password, o.tls_ca, "", "", 10, std::chrono::milliseconds{1000}},
      mqtt::LinkHandlers{[&] {
                           for (const char* what : {"state", "online", "hit", "event"})
                             self->subscribe(std::string("imess/+/") + what, 0);
                           subscribed = true;
                           last_message = Clock::now();
                         },
                         [&](const std::string& why) {
                           error = why;
                           if (!o.once) std::cerr << "messfleet: broker " << o.broker.to_string() << ": " << why << "\n";
                         },
                         nullptr,
                         [&](std::string_view topic, std::string_view payload, bool) {
                           changed = view.fold(topic, payload) || changed;
                           last_message = Clock::now();
                         }});
  self = &link;
  client::install_stop_signals({SIGINT, SIGTERM});
  const auto start = Clock::now();
  auto last_draw = Clock::time_point{};
  bool drawn = false;
  while (!client::stop_requested()) {
    auto now = Clock::now();
    link.service(false, false, now);
    if (o.once) {
      if (!subscribed && !error.empty() && now - start > std::chrono::milliseconds{o.wait_ms}) {
        std::cerr << "messfleet: broker " << o.broker.to_string() << ": " << error << "\n";
        return client::kExitFailure;
      }
      if (subscribed && (now - last_message > std::chrono::milliseconds{300} || now - start > std::chrono::milliseconds{o.wait_ms}))
        break;
    } else if ((changed || !drawn) && now - last_draw > std::chrono::milliseconds{250}) {
      if (o.json) std::cout << view.to_json().dump() << std::endl;
      else std::cout << "\033[H\033[2J" << "IMESS fleet on " << o.broker.to_string() << "\n\n" << view.table() << std::flush;
      changed = false;
      drawn = true;
      last_draw = now;
    }
    pollfd fd{link.fd(), static_cast<short>(POLLIN | (link.wants_write() ? POLLOUT : 0)), 0};
    const int wait = static_cast<int>(std::min<long>(100, std::max<long>(1, link.until_due(now).count())));
    if (::poll(&fd, 1, wait) < 0) continue;
    if (fd.fd >= 0 && fd.revents) link.service((fd.revents & (POLLIN | POLLHUP | POLLERR)) != 0, (fd.revents & POLLOUT) != 0);
  }
  if (o.once) {
    if (o.json) std::cout << view.to_json().dump() << "\n";
    else std::cout << view.table();
  }
  link.disconnect();
  return client::kExitOk;
}
