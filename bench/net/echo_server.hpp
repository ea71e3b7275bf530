// EchoServer: the loopback floor the network figures compare messd with. One Boost.Asio
// io_context on one thread, TCP_NODELAY, lines out through one shared buffer per broadcast
// (as messd's Server::broadcast); a greeting line on connect as messd's CurrCor.
//   echo       each line goes back to its sender
//   broadcast  each line received from any client goes to every connected client
//   timer      every 1/hz s a CurrCor-sized line "CurrCor <t> 0.000 0.000" goes to every client,
//              t the CLOCK_MONOTONIC seconds (6 decimals) read right before the broadcast
#pragma once
#include <array>
#include <utility>  // before Asio: its awaitable.hpp uses std::exchange without it
#include <boost/asio.hpp>
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace imess::bench {

enum class EchoMode { Echo, Broadcast, Timer };

class EchoServer {
 public:
  EchoServer(boost::asio::io_context& io, EchoMode mode, double hz, std::uint16_t port);
  std::uint16_t port() const;

 private:
  class Peer;
  void accept();
  void on_line(Peer& from, std::string line);
  void broadcast(const std::shared_ptr<const std::string>& line);
  void tick();

  boost::asio::io_context& io_;
  EchoMode mode_;
  std::chrono::nanoseconds period_{0};
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer timer_;
  std::map<std::uint32_t, std::shared_ptr<Peer>> peers_;
  std::uint32_t next_id_ = 1;
};

}  // namespace imess::bench
