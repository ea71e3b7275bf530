// Session output without a daemon: a lost reply slot times out into Err 500 and the replies
// behind it flow; a close while a write is in flight frees nothing the write still reads; a
// burst of requests with big answers is answered in full (reading pauses on bytes waiting).
#include <catch2/catch.hpp>

#include <boost/asio.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "imess/net/session.hpp"

using imess::net::Session;
namespace asio = boost::asio;
using asio::ip::tcp;

namespace {
// A connected pair on loopback: the server end for a Session, the client end read directly.
struct Pair {
  asio::io_context io;
  tcp::socket client{io};
  std::shared_ptr<Session> session;
  int closed = 0;

  explicit Pair(std::size_t max_queue = 1 << 20) {
    tcp::acceptor acceptor(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
    client.connect(acceptor.local_endpoint());
    session = std::make_shared<Session>(
        acceptor.accept(), 1, max_queue, [](Session&, const imess::protocol::FramedLine&) {},
        [this](Session&) { ++closed; });
  }
  // Runs the handlers that are ready (an io_context that ran out of work stays stopped
  // until restarted).
  void pump() {
    io.restart();
    io.poll();
  }
  std::string read(std::size_t n) {
    std::string text(n, '\0');
    asio::read(client, asio::buffer(text));
    return text;
  }
};
}  // namespace

TEST_CASE("a reply slot that is never answered becomes Err 500 after the timeout and later replies flow") {
  Pair p;
  auto& s = *p.session;
  const auto lost = s.reserve_reply();
  const auto b = s.reserve_reply();
  const auto c = s.reserve_reply();
  s.fill_reply(b, "Ok B\n");
  s.fill_reply(c, "Ok C\n");
  p.pump();
  CHECK(p.client.available() == 0);  // held behind the first slot
  CHECK(s.expire_replies(Session::Clock::now(), std::chrono::seconds(2), "Err 500 lost\n") == 0);  // not yet
  CHECK(s.expire_replies(Session::Clock::now() + std::chrono::seconds(3), std::chrono::seconds(2), "Err 500 lost\n") == 1);
  p.pump();
  CHECK(p.read(23) == "Err 500 lost\nOk B\nOk C\n");
  s.fill_reply(lost, "Ok A\n");  // the answer after all: its slot is gone, nothing is sent
  const auto d = s.reserve_reply();
  s.fill_reply(d, "Ok D\n");
  p.pump();
  CHECK(p.read(5) == "Ok D\n");
  CHECK(s.open_replies() == 0);
}

TEST_CASE("one buffer queued for many sessions, and a close during a write frees nothing the write reads") {
  Pair p, q;
  auto line = std::make_shared<const std::string>("Control panel 127.0.0.1\n");
  p.session->send(line);
  q.session->send(line);
  CHECK(line.use_count() == 3);  // the same buffer in both queues, not a copy each
  p.pump();
  q.pump();
  CHECK(p.read(line->size()) == *line);
  CHECK(q.read(line->size()) == *line);

  // 32 MiB to a client that does not read: the kernel takes part, the write stays in flight.
  auto big = std::make_shared<std::string>(32 << 20, 'x');
  big->back() = '\n';
  Pair r(64 << 20);
  r.session->send(std::shared_ptr<const std::string>(big));
  r.pump();
  std::weak_ptr<const std::string> watch = big;
  big.reset();
  CHECK(!watch.expired());  // held by the queue and the write in flight
  r.session->close("test");
  CHECK(r.closed == 1);
  CHECK(!watch.expired());  // the queue is cleared, but the write's handler still holds it
  r.pump();              // the aborted write completes
  CHECK(watch.expired());
  r.session->close("again");
  CHECK(r.closed == 1);
}

TEST_CASE("a burst of pipelined requests with big answers is answered in full, the client is never dropped") {
  asio::io_context io;
  tcp::acceptor acceptor(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  tcp::socket client(io);
  client.connect(acceptor.local_endpoint());
  // About Help's size; 300 of them are 1.5 MiB, more than the 1 MiB output cap.
  const std::string answer = "Help " + std::string(5000, 'h') + "\nOk Help\n";
  const int requests = GENERATE(300, 1000);
  int closed = 0, seen = 0;
  auto session = std::make_shared<Session>(
      acceptor.accept(), 1, 1 << 20,
      [&](Session& s, const imess::protocol::FramedLine&) {
        ++seen;
        s.fill_reply(s.reserve_reply(), answer);
      },
      [&](Session&) { ++closed; });
  session->start();
  std::string burst;
  for (int i = 0; i < requests; ++i) burst += "Help\n";
  asio::write(client, asio::buffer(burst));  // all at once, before reading any answer
  std::thread server([&] { io.run(); });
  const std::size_t expected = answer.size() * static_cast<std::size_t>(requests);
  std::string got(expected, '\0');
  boost::system::error_code ec;
  const std::size_t n = asio::read(client, asio::buffer(got), ec);
  asio::post(io, [&] { session->close("test over"); });
  server.join();
  CHECK(n == expected);
  CHECK(seen == requests);
  CHECK(closed == 1);  // only by the test
  CHECK(session->close_reason() == "test over");
}

TEST_CASE("output beyond the cap to a client that does not read closes it at once, saying why") {
  Pair p(8192);
  p.session->send(std::string(6000, 'x') + "\n");
  CHECK(p.closed == 0);
  p.session->send(std::string(3000, 'y') + "\n");  // 9 KiB would wait: more than the 8 KiB cap
  CHECK(p.closed == 1);
  CHECK(p.session->close_reason() == "dropped: more than 8192 bytes of output waiting (not reading fast enough)");
}

// Issue 26, 1: an exception from a line's handler escaped io_context::run and messd exited 2,
// every client gone. It ends only the session whose line raised it.
TEST_CASE("a line whose handler throws closes only that session, naming the error") {
  asio::io_context io;
  tcp::acceptor acceptor(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  tcp::socket bad_client(io), good_client(io);
  bad_client.connect(acceptor.local_endpoint());
  auto bad_end = acceptor.accept();
  good_client.connect(acceptor.local_endpoint());
  auto good_end = acceptor.accept();
  int lines = 0, closed = 0;
  auto on_line = [&](Session& s, const imess::protocol::FramedLine& l) {
    ++lines;
    if (l.text == "boom") throw std::runtime_error("frame has a non-finite rotation or translation element");
    s.send("Ok " + std::string(l.text) + "\n");
  };
  auto bad = std::make_shared<Session>(std::move(bad_end), 1, 1 << 20, on_line, [&](Session&) { ++closed; });
  auto good = std::make_shared<Session>(std::move(good_end), 2, 1 << 20, on_line, [&](Session&) { ++closed; });
  bad->start();
  good->start();
  asio::write(bad_client, asio::buffer(std::string("boom\nafter\n")));
  asio::write(good_client, asio::buffer(std::string("ping\n")));
  for (int i = 0; i < 200 && (closed == 0 || good_client.available() < 8); ++i) {
    io.restart();
    REQUIRE_NOTHROW(io.poll());
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  CHECK(closed == 1);
  CHECK_FALSE(bad->open());
  CHECK(bad->close_reason().find("non-finite rotation") != std::string::npos);
  CHECK(good->open());
  std::string reply(8, '\0');
  asio::read(good_client, asio::buffer(reply));
  CHECK(reply == "Ok ping\n");
  CHECK(lines == 2);  // "after" was never handled: the session ended at "boom"
}
