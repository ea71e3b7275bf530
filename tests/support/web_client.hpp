// WebClient: the web panel's WebSocket as a test drives it (Boost.Beast, its own io_context):
// connect from a chosen source address with a chosen Origin and target, send JSON commands,
// wait for JSON events with timeouts. http_get: one plain HTTP request.
#pragma once
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace imess::test {

namespace web_asio = boost::asio;
namespace web_beast = boost::beast;

class WebClient {
 public:
  // Throws boost::system::system_error when the upgrade is declined; `status` then holds
  // the HTTP status of the answer (see try_connect).
  explicit WebClient(int port, const std::string& source = "", const std::string& target = "/ws",
                     const std::string& origin = "")
      : ws_(io_) {
    auto& socket = web_beast::get_lowest_layer(ws_).socket();
    socket.open(web_asio::ip::tcp::v4());
    if (!source.empty()) socket.bind({web_asio::ip::make_address(source), 0});
    socket.connect({web_asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)});
    ws_.set_option(web_beast::websocket::stream_base::decorator([origin](web_beast::websocket::request_type& r) {
      if (!origin.empty()) r.set(web_beast::http::field::origin, origin);
    }));
    web_beast::websocket::response_type response;
    web_beast::error_code ec;
    ws_.handshake(response, "127.0.0.1:" + std::to_string(port), target, ec);
    status_ = static_cast<int>(response.result_int());
    if (ec) throw boost::system::system_error(ec);
  }
  int status() const { return status_; }

  void send(const nlohmann::json& message) { send_text(message.dump()); }
  void send_text(const std::string& text) {
    ws_.text(true);
    ws_.write(web_asio::buffer(text));
  }

  // The next event, or nothing within timeout_s (or when the server closed).
  std::optional<nlohmann::json> next(double timeout_s = 5.0) {
    if (closed_) return std::nullopt;
    bool done = false;
    web_beast::error_code result;
    ws_.async_read(buffer_, [&](web_beast::error_code ec, std::size_t) {
      done = true;
      result = ec;
    });
    io_.restart();
    io_.run_for(std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::duration<double>(timeout_s)));
    if (!done) {  // give up this read: cancel it and let its handler run
      web_beast::get_lowest_layer(ws_).socket().cancel();
      io_.restart();
      io_.run();
      closed_ = true;  // a cancelled WebSocket read leaves the stream unusable
      return std::nullopt;
    }
    if (result) {
      closed_ = true;
      return std::nullopt;
    }
    auto text = web_beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    return nlohmann::json::parse(text);
  }
  // The first event `pred` accepts, skipping others.
  std::optional<nlohmann::json> until(const std::function<bool(const nlohmann::json&)>& pred, double timeout_s = 10.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      if (left <= 0) return std::nullopt;
      auto e = next(left);
      if (!e) return std::nullopt;
      if (pred(*e)) return e;
    }
  }
  std::optional<nlohmann::json> until_type(const std::string& type, double timeout_s = 10.0) {
    return until([&](const nlohmann::json& e) { return e.value("type", "") == type; }, timeout_s);
  }
  // Sends a command and returns its reply (the first Ok or Err).
  std::optional<nlohmann::json> request(const nlohmann::json& command, double timeout_s = 5.0) {
    send(command);
    return until([](const nlohmann::json& e) { return e["type"] == "Ok" || e["type"] == "Err"; }, timeout_s);
  }
  bool closed() const { return closed_; }
  void close() {
    web_beast::error_code ec;
    web_beast::get_lowest_layer(ws_).socket().close(ec);
    closed_ = true;
  }

 private:
  web_asio::io_context io_;
  web_beast::websocket::stream<web_beast::tcp_stream> ws_;
  web_beast::flat_buffer buffer_;
  int status_ = 0;
  bool closed_ = false;
};

// The HTTP status a WebSocket upgrade request gets (101: accepted), asked by hand.
inline int upgrade_status(int port, const std::string& source, const std::string& target, const std::string& origin) {
  web_asio::io_context io;
  web_beast::tcp_stream stream(io);
  auto& socket = stream.socket();
  socket.open(web_asio::ip::tcp::v4());
  if (!source.empty()) socket.bind({web_asio::ip::make_address(source), 0});
  socket.connect({web_asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)});
  namespace http = web_beast::http;
  http::request<http::empty_body> request{http::verb::get, target, 11};
  request.set(http::field::host, "127.0.0.1:" + std::to_string(port));
  request.set(http::field::connection, "Upgrade");
  request.set(http::field::upgrade, "websocket");
  request.set(http::field::sec_websocket_version, "13");
  request.set(http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
  if (!origin.empty()) request.set(http::field::origin, origin);
  http::write(stream, request);
  web_beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.skip(false);
  web_beast::error_code ec;
  http::read_header(stream, buffer, parser, ec);
  return ec ? -1 : static_cast<int>(parser.get().result_int());
}

// One HTTP/1.1 request to 127.0.0.1:port; the response.
inline web_beast::http::response<web_beast::http::string_body> http_request(int port, web_beast::http::verb method,
                                                                            const std::string& target) {
  web_asio::io_context io;
  web_beast::tcp_stream stream(io);
  stream.connect(web_asio::ip::tcp::endpoint(web_asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
  web_beast::http::request<web_beast::http::string_body> request{method, target, 11};
  request.set(web_beast::http::field::host, "127.0.0.1:" + std::to_string(port));
  web_beast::http::write(stream, request);
  web_beast::flat_buffer buffer;
  web_beast::http::response_parser<web_beast::http::string_body> parser;
  parser.skip(method == web_beast::http::verb::head);
  web_beast::http::read(stream, buffer, parser);
  return parser.release();
}

}  // namespace imess::test
