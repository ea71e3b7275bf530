// One HTTP connection of the web panel: read a request, answer it with a file, again, until
// the browser closes, goes silent for 30 s, or upgrades to the WebSocket on /ws.
#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

#include "web_shared.hpp"

namespace imess::net {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using asio::ip::tcp;

namespace {

constexpr auto kIdle = std::chrono::seconds(30);

class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
 public:
  // refusal: not empty, every request gets 403 with it (a host in neither list).
  HttpConnection(tcp::socket socket, std::shared_ptr<WebServer::Shared> shared, std::string refusal)
      : stream_(std::move(socket)), shared_(std::move(shared)), refusal_(std::move(refusal)) {
    ++shared_->connections;
  }
  ~HttpConnection() { --shared_->connections; }

  void read() {
    parser_.emplace();
    parser_->header_limit(16 * 1024);
    parser_->body_limit(16 * 1024);  // the panel sends no bodies; a form would be small
    stream_.expires_after(kIdle);
    http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_request(ec);
    });
  }

 private:
  void on_request(beast::error_code ec) {
    if (ec || !shared_->running) return close();
    WebRequest request = parser_->release();
    if (!refusal_.empty()) {
      auto response = std::make_shared<http::response<http::string_body>>(http::status::forbidden, request.version());
      response->set(http::field::server, "messd");
      response->set(http::field::content_type, "text/plain; charset=utf-8");
      response->body() = refusal_ + "\n";
      response->keep_alive(false);
      response->prepare_payload();
      http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code, std::size_t) { self->close(); });
      return;
    }
    if (boost::beast::websocket::is_upgrade(request)) {
      const std::string_view target = std_view(request.target());
      if (target == "/ws" || target.starts_with("/ws?")) {
        stream_.expires_never();
        start_web_session(std::move(stream_), std::move(request), shared_);
        return;
      }
    }
    auto response = std::make_shared<http::response<http::string_body>>(file_response(request, *shared_));
    response->keep_alive(request.keep_alive());
    response->prepare_payload();
    if (request.method() == http::verb::head) {  // the length of what GET would send, no body
      const auto length = response->body().size();
      response->body().clear();
      response->content_length(length);
    }
    http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code wec, std::size_t) {
      if (wec || !response->keep_alive()) return self->close();
      self->read();
    });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.close();
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<WebServer::Shared> shared_;
  std::string refusal_;
};

}  // namespace

void serve_http(tcp::socket socket, std::shared_ptr<WebServer::Shared> shared) {
  // A host in neither list may not even load the page: 403 saying why, as 1066 says Err 210.
  boost::system::error_code ec;
  auto remote = socket.remote_endpoint(ec);
  if (ec) return;
  auto address = remote.address();
  if (address.is_v6() && address.to_v6().is_v4_mapped()) address = asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6());
  const auto& rules = shared->config.control;
  std::string refusal;
  if (!rules.hosts.contains(address) && !rules.observe_hosts.contains(address)) {
    log_limited(shared->log, spdlog::level::warn, "web-refused-host",
                "web panel: refused " + address.to_string() + ": not in control.hosts or control.observe_hosts");
    refusal = "host " + address.to_string() +
              " may not connect: it is in neither control.hosts nor control.observe_hosts of the daemon's configuration";
  }
  std::make_shared<HttpConnection>(std::move(socket), std::move(shared), std::move(refusal))->read();
}

}  // namespace imess::net
