// Session: one TCP client. Reads into a capped LineFramer, writes through a bounded queue;
// a client that stops reading is dropped rather than slowing anyone else.
#pragma once
#include <boost/asio.hpp>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>

#include "imess/protocol/line_framer.hpp"

namespace imess::net {

class Session : public std::enable_shared_from_this<Session> {
 public:
  using LineHandler = std::function<void(Session&, const protocol::FramedLine&)>;
  using CloseHandler = std::function<void(Session&)>;

  Session(boost::asio::ip::tcp::socket socket, std::uint32_t id, std::size_t max_queue_bytes, LineHandler on_line,
          CloseHandler on_close);

  void start();
  void send(std::string line);  // one complete line with its "\n" (events: sent at once)

  // Replies leave in the order of the requests, even when the motion loop answers later
  // than the io thread: reserve a slot per request, fill it when the answer is known.
  std::uint32_t reserve_reply();
  void fill_reply(std::uint32_t slot, std::string lines);
  void close_after_flush();     // Quit: finish writing, then close
  void close();

  std::uint32_t id() const { return id_; }
  const std::string& peer() const { return peer_; }
  bool open() const { return open_; }

 private:
  void read();
  void write();

  boost::asio::ip::tcp::socket socket_;
  std::uint32_t id_;
  std::size_t max_queue_bytes_;
  LineHandler on_line_;
  CloseHandler on_close_;
  protocol::LineFramer framer_;
  std::array<char, 4096> buffer_{};
  std::deque<std::string> queue_;
  std::deque<std::pair<std::uint32_t, std::string>> replies_;  // empty text: not answered yet
  std::uint32_t next_slot_ = 1;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false, open_ = true, close_when_flushed_ = false;
  std::string peer_;
};

}  // namespace imess::net
