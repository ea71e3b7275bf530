// Connection and Reconnector against a fake daemon on loopback: the refusal message, lines
// both ways (also split across reads), loss detection, and reconnecting after a restart.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <thread>

#include "fake_daemon.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/client/reconnector.hpp"

using namespace imess::client;
using imess::test::FakeDaemon;
using namespace std::chrono_literals;

namespace {

// Polls until `want` lines arrived, the link closed, or 3 s passed.
ReadStatus collect(Connection& c, std::vector<std::string>& lines, std::size_t want) {
  auto deadline = std::chrono::steady_clock::now() + 3s;
  ReadStatus s = ReadStatus::Idle;
  while (lines.size() < want && std::chrono::steady_clock::now() < deadline) {
    s = c.poll_lines(50ms, [&](std::string_view l) { lines.emplace_back(l); });
    if (s == ReadStatus::Closed) break;
  }
  return s;
}

}  // namespace

TEST_CASE("Connection::open: refused names host, port and reason") {
  auto port = imess::test::unused_port();
  Endpoint where{"127.0.0.1", port};
  try {
    Connection::open(where, 1000ms);
    FAIL("connected to a port nobody listens on");
  } catch (const ConnectError& e) {
    CHECK(e.kind() == ConnectError::Kind::Unreachable);
    CHECK(e.reason() == "connection refused");
    CHECK(std::string(e.what()) ==
          "no partner on 127.0.0.1:" + std::to_string(port) + " (connection refused) — is messd running?");
  }
}

TEST_CASE("Connection::open: an unresolvable host is reported as such") {
  try {
    Connection::open(Endpoint{"no-such-host.invalid", 1066}, 1000ms);
    FAIL("resolved an .invalid name");
  } catch (const ConnectError& e) {
    CHECK(e.kind() == ConnectError::Kind::NotResolved);
    CHECK_THAT(e.what(), Catch::StartsWith("cannot resolve host 'no-such-host.invalid'"));
  }
}

TEST_CASE("Connection: lines in both directions, split lines joined, close detected") {
  FakeDaemon daemon({0, {"CurrCor 1.000 2.000 3.000", "State idle"}, {}});
  auto c = Connection::open(Endpoint{"127.0.0.1", daemon.port()});
  REQUIRE(c.is_open());

  std::vector<std::string> lines;
  collect(c, lines, 2);
  CHECK(lines == std::vector<std::string>{"CurrCor 1.000 2.000 3.000", "State idle"});

  REQUIRE(c.send_line("StartMv 2 0 0"));
  REQUIRE(c.send_line("StopMv\n"));  // a terminator already there is not doubled
  CHECK(daemon.wait_for_line("StartMv 2 0 0"));
  CHECK(daemon.wait_for_line("StopMv"));
  CHECK(daemon.received() == std::vector<std::string>{"StartMv 2 0 0", "StopMv"});

  daemon.send_raw("MeasPt 1.0");
  std::this_thread::sleep_for(30ms);
  daemon.send_raw("00 2.000 3.000\r\nHom");
  daemon.send_raw("ed\n");
  collect(c, lines, 4);
  REQUIRE(lines.size() == 4);
  CHECK(lines[2] == "MeasPt 1.000 2.000 3.000");
  CHECK(lines[3] == "Homed");

  CHECK(c.poll_lines(0ms, [](std::string_view) {}) == ReadStatus::Idle);
  daemon.drop_clients();
  CHECK(collect(c, lines, 99) == ReadStatus::Closed);
  CHECK_FALSE(c.is_open());
  CHECK(c.close_reason() == "closed by messd");
  CHECK_FALSE(c.send_line("StopMv"));
}

TEST_CASE("Connection: lines are cut at 200 characters unless a longer limit is asked for (I++ DME answers)") {
  const std::string long_line = "00002 # " + std::string(300, 'x');
  FakeDaemon daemon({0, {long_line}, {}});
  std::vector<std::string> lines;
  auto plain = Connection::open(Endpoint{"127.0.0.1", daemon.port()});
  collect(plain, lines, 1);
  auto ipp = Connection::open(Endpoint{"127.0.0.1", daemon.port()}, 1000ms, 65536);
  collect(ipp, lines, 2);
  REQUIRE(lines.size() == 2);
  CHECK(lines[0] == long_line.substr(0, 200));
  CHECK(lines[1] == long_line);
}

TEST_CASE("Reconnector: notices the loss, retries while messd is down, reconnects after a restart") {
  auto daemon = std::make_unique<FakeDaemon>();
  auto port = daemon->port();
  Reconnector link(Endpoint{"127.0.0.1", port}, Reconnector::Options{50ms, 500ms});
  REQUIRE(link.maintain());  // first attempt is due at once
  CHECK(link.connected());
  CHECK_FALSE(link.maintain());  // already connected: nothing new
  REQUIRE(daemon->wait_for_accepted(1));

  daemon.reset();  // messd stops
  auto* c = link.connection();
  REQUIRE(c != nullptr);
  ReadStatus s = ReadStatus::Idle;
  for (int i = 0; i < 60 && s != ReadStatus::Closed; ++i) s = c->poll_lines(50ms, [](std::string_view) {});
  REQUIRE(s == ReadStatus::Closed);
  link.lost();
  CHECK_FALSE(link.connected());
  CHECK(link.fd() == -1);
  CHECK_FALSE(link.send_line("StopMv"));
  CHECK(link.until_next_attempt() > 0ms);

  auto deadline = std::chrono::steady_clock::now() + 2s;
  while (link.attempts() < 2 && std::chrono::steady_clock::now() < deadline) {
    link.maintain();
    std::this_thread::sleep_for(10ms);
  }
  CHECK(link.attempts() >= 2);  // retried, at the interval, while nobody listened
  CHECK(link.last_error() == "connection refused");

  FakeDaemon restarted({port, {"CurrCor 0.000 0.000 0.000"}, {}});  // messd is back, same port
  bool reconnected = false;
  deadline = std::chrono::steady_clock::now() + 2s;
  while (!reconnected && std::chrono::steady_clock::now() < deadline) {
    reconnected = link.maintain();
    std::this_thread::sleep_for(10ms);
  }
  REQUIRE(reconnected);
  CHECK(link.attempts() == 0);
  REQUIRE(link.send_line("Hello again"));
  CHECK(restarted.wait_for_line("Hello again"));
}

TEST_CASE("Connection::finish: the last line arrives and the link ends without a reset") {
  // The daemon's greeting stays unread in the client, as when a jog panel quits mid-stream.
  FakeDaemon daemon({0, {"CurrCor 1.000 2.000 3.000", "State jog", "CurrCor 1.100 2.000 3.000"}, {}});
  Endpoint where{"127.0.0.1", daemon.port()};

  SECTION("finish(): orderly") {
    auto c = Connection::open(where);
    REQUIRE(daemon.wait_for_accepted(1));
    std::this_thread::sleep_for(50ms);  // the greeting is in our receive buffer, unread
    REQUIRE(c.send_line("StopMv"));
    auto t0 = std::chrono::steady_clock::now();
    c.finish();
    CHECK(std::chrono::steady_clock::now() - t0 < 400ms);  // messd closed at once: no full wait
    CHECK_FALSE(c.is_open());
    REQUIRE(daemon.wait_for_gone(1));
    CHECK(daemon.wait_for_line("StopMv"));
    CHECK(daemon.resets() == 0);
  }
  SECTION("close() with unread input resets - what finish() avoids") {
    auto c = Connection::open(where);
    REQUIRE(daemon.wait_for_accepted(1));
    std::this_thread::sleep_for(50ms);
    REQUIRE(c.send_line("StopMv"));
    c.close();
    REQUIRE(daemon.wait_for_gone(1));
    CHECK(daemon.resets() == 1);
  }
}

TEST_CASE("Connection: a daemon closing with our line unread (a reset) reads as closed by messd") {
  // A bare listener that accepts, lets the client's line arrive unread and closes: the
  // kernel answers with a reset instead of an orderly end.
  int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  REQUIRE(listener >= 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  REQUIRE(::bind(listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  REQUIRE(::listen(listener, 1) == 0);
  REQUIRE(::getsockname(listener, reinterpret_cast<sockaddr*>(&addr), &len) == 0);

  auto c = Connection::open(Endpoint{"127.0.0.1", ntohs(addr.sin_port)});
  int peer = ::accept(listener, nullptr, nullptr);
  REQUIRE(peer >= 0);
  REQUIRE(c.send_line("Hello unread"));
  pollfd p{peer, POLLIN, 0};
  REQUIRE(::poll(&p, 1, 3000) == 1);  // the line sits in the daemon's socket, unread
  ::close(peer);
  ::close(listener);

  std::vector<std::string> lines;
  CHECK(collect(c, lines, 1) == ReadStatus::Closed);
  CHECK(c.close_reason() == "closed by messd (connection reset)");
}
