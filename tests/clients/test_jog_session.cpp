// messjog end to end without a terminal: JogSession against a fake daemon — the exact lines
// messd receives for keys, and reconnecting (mark kept, Hello again) after messd restarts.
#include <catch2/catch.hpp>

#include <thread>

#include "fake_daemon.hpp"
#include "imess/client/connection.hpp"
#include "jog_session.hpp"

using namespace imess::messjog;
using imess::client::Connection;
using imess::client::Endpoint;
using imess::client::Reconnector;
using imess::test::FakeDaemon;
using imess::test::FakeDaemonScript;
using namespace std::chrono_literals;

namespace {

FakeDaemonScript messd_like(std::uint16_t port, std::string position) {
  return {port, {"CurrCor " + position},
          [](const std::string& line) -> std::vector<std::string> {
            auto verb = line.substr(0, line.find(' '));
            if (verb.empty()) return {};  // a keep-alive: messd does not answer blank lines
            if (verb == "Hello") return {"Ok Hello IMESS 1 fake"};
            if (verb == "Status") return {"Ok Status State idle Pos 0.000 0.000 0.000"};
            return {"Ok " + verb};
          }};
}

std::vector<std::string> commands(const FakeDaemon& d) {  // without the blank keep-alives
  std::vector<std::string> out;
  for (const auto& l : d.received())
    if (!l.empty()) out.push_back(l);
  return out;
}

std::size_t keepalives(const FakeDaemon& d) {
  std::size_t n = 0;
  for (const auto& l : d.received()) n += l.empty();
  return n;
}

template <class Pred>
bool pump_until(JogSession& s, Pred done, std::chrono::milliseconds timeout = 3s) {
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    s.pump(20ms);
  }
  return true;
}

}  // namespace

TEST_CASE("JogSession: keys reach messd as exact command lines") {
  FakeDaemon daemon(messd_like(0, "0.000 0.000 0.000"));
  JogSession session(Endpoint{"127.0.0.1", daemon.port()}, Reconnector::Options{50ms, 500ms});
  session.adopt(Connection::open(Endpoint{"127.0.0.1", daemon.port()}));
  REQUIRE(daemon.wait_for_line("Hello messjog"));
  REQUIRE(pump_until(session, [&] { return session.panel().current().has_value(); }));

  session.act(JogAction::Mark);
  session.act(JogAction::XPlus);
  session.act(JogAction::Speed3);
  session.act(JogAction::Stop);
  session.act(JogAction::Measure);
  daemon.send("CurrCor 3.000 4.000 0.000");
  REQUIRE(pump_until(session, [&] { return session.panel().current() == Xyz{3, 4, 0}; }));
  session.act(JogAction::Speed2);
  session.act(JogAction::TowardMark);
  REQUIRE(daemon.wait_for_line("StartMv -12.000 -16.000 0.000"));
  CHECK(commands(daemon) == std::vector<std::string>{"Hello messjog", "Watch 500", "Status", "StartMv 20.000 0.000 0.000",
                                                      "StartMv 100.000 0.000 0.000", "StopMv", "ForcePt",
                                                      "StartMv -12.000 -16.000 0.000"});
}

TEST_CASE("JogSession: reconnects by itself after messd restarts and keeps the mark") {
  auto daemon = std::make_unique<FakeDaemon>(messd_like(0, "0.000 0.000 0.000"));
  auto port = daemon->port();
  JogSession session(Endpoint{"127.0.0.1", port}, Reconnector::Options{50ms, 500ms});
  session.adopt(Connection::open(Endpoint{"127.0.0.1", port}));
  REQUIRE(pump_until(session, [&] { return session.panel().current().has_value(); }));
  session.act(JogAction::Mark);
  session.act(JogAction::YPlus);

  daemon.reset();  // messd goes away
  REQUIRE(pump_until(session, [&] { return !session.panel().connected(); }));
  CHECK_FALSE(session.panel().moving());
  CHECK(session.fd() == -1);
  session.pump(120ms);  // a couple of refused attempts
  CHECK(session.link().attempts() >= 1);

  daemon = std::make_unique<FakeDaemon>(messd_like(port, "3.000 4.000 0.000"));  // back, same port
  REQUIRE(pump_until(session, [&] { return session.panel().connected(); }));
  REQUIRE(daemon->wait_for_line("Hello messjog"));
  REQUIRE(pump_until(session, [&] { return session.panel().current() == Xyz{3, 4, 0}; }));
  REQUIRE(pump_until(session, [&] { return session.panel().machine_state() == "idle"; }));
  CHECK(session.panel().mark() == Xyz{0, 0, 0});
  session.act(JogAction::AwayFromMark);
  CHECK(daemon->wait_for_line("StartMv 12.000 16.000 0.000"));
}

TEST_CASE("JogSession: q while jogging sends StopMv, and finish() delivers it without a reset") {
  FakeDaemon daemon(messd_like(0, "0.000 0.000 0.000"));
  JogSession session(Endpoint{"127.0.0.1", daemon.port()}, Reconnector::Options{50ms, 500ms});
  session.adopt(Connection::open(Endpoint{"127.0.0.1", daemon.port()}));
  session.act(JogAction::ZMinus);
  REQUIRE(daemon.wait_for_line("StartMv 0.000 0.000 -20.000"));
  daemon.send("CurrCor 0.000 0.000 -0.100");  // left unread: the panel quits first
  std::this_thread::sleep_for(30ms);
  session.act(JogAction::Quit);
  CHECK(session.panel().quit_requested());
  session.finish();
  REQUIRE(daemon.wait_for_gone(1));
  CHECK(daemon.received().back() == "StopMv");
  CHECK(daemon.resets() == 0);
}

TEST_CASE("JogSession: blank keep-alives go out while a jog runs, not while the panel is idle") {
  FakeDaemon daemon(messd_like(0, "0.000 0.000 0.000"));
  JogSession session(Endpoint{"127.0.0.1", daemon.port()}, Reconnector::Options{50ms, 500ms});
  session.adopt(Connection::open(Endpoint{"127.0.0.1", daemon.port()}));
  REQUIRE(daemon.wait_for_line("Watch 500"));
  REQUIRE(pump_until(session, [&] { return session.panel().machine_state() == "idle"; }));
  auto idle_start = keepalives(daemon);
  auto until = std::chrono::steady_clock::now() + 600ms;
  while (std::chrono::steady_clock::now() < until) session.pump(20ms);
  CHECK(keepalives(daemon) == idle_start);  // idle: one every 30 s at most
  session.act(JogAction::XPlus);
  // Every 100 ms, well inside Watch 500: 4 within 600 ms on a quiet host; a busy one (the
  // suite beside it) may delay the pump, so the deadline is generous and the rate is judged
  // by the time they took.
  const auto jog_start = std::chrono::steady_clock::now();
  until = jog_start + 3s;
  while (keepalives(daemon) - idle_start < 4 && std::chrono::steady_clock::now() < until) session.pump(20ms);
  CHECK(keepalives(daemon) - idle_start >= 4);
  CHECK(std::chrono::steady_clock::now() - jog_start < 2s);  // not one per Watch period or slower
}
