// One WebSocket of the web panel, bridged to a MESSD session: browser messages -> lines into
// one end of a socket pair, whose other end SessionHub serves as a client of its own; that
// session's lines -> JSON events back to the browser. Back-pressure passes through: a browser
// that does not read stops this bridge reading the pair, so the session's output waits as a
// TCP client's would (and write_stall_s drops it); a session that does not read (backlogged)
// stops the bridge reading the browser.
#include <sys/socket.h>

#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>
#include <deque>

#include "imess/protocol/messages.hpp"
#include "imess/webjson/web_json.hpp"
#include "imess/webpoints/points_request.hpp"
#include "web_shared.hpp"

namespace imess::net {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using asio::ip::tcp;

namespace {

constexpr std::size_t kMaxPending = 1 << 20;  // bytes waiting either way before reading that side pauses

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The token a target "/ws?token=..." carries ("" without one).
std::string token_of(std::string_view target) {
  const auto q = target.find('?');
  if (q == std::string_view::npos) return {};
  std::string_view query = target.substr(q + 1);
  while (!query.empty()) {
    const auto amp = query.find('&');
    const auto pair = query.substr(0, amp);
    if (pair.starts_with("token=")) return std::string(pair.substr(6));
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return {};
}

// A refusal of the bridge itself, as the Err event the line protocol would send.
std::string err_event(int code, const std::string& text) {
  std::string line = protocol::format_err(static_cast<protocol::ErrorCode>(code), text);
  line.pop_back();  // its "\n"
  return webjson::event_text(line);
}

bool same_secret(std::string_view a, std::string_view b) {  // no early exit on the first difference
  unsigned diff = a.size() == b.size() ? 0u : 1u;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

class WebBridge : public std::enable_shared_from_this<WebBridge> {
 public:
  WebBridge(beast::tcp_stream stream, std::shared_ptr<WebServer::Shared> shared)
      : ws_(std::move(stream)), line_(ws_.get_executor()), shared_(std::move(shared)) {}

  void start(WebRequest request) {
    boost::system::error_code ec;
    peer_ = beast::get_lowest_layer(ws_).socket().remote_endpoint(ec);
    if (ec) return;
    // Commands only from the page messd serves: a browser names the page's origin, and it
    // must be this server's (Host is the address the browser connected to).
    const auto origin = request.find(http::field::origin);
    if (origin != request.end()) {
      const std::string host(std_view(request[http::field::host]));
      if (lower(std_view(origin->value())) != "http://" + lower(host)) {
        log_limited(shared_->log, spdlog::level::warn, "web-origin",
                    "web panel: refused a WebSocket from a page of " + std::string(std_view(origin->value())) + " (not http://" + host + ")");
        return reject(request, http::status::forbidden,
                      "origin " + std::string(std_view(origin->value())) + " is not this panel's (http://" + host +
                          "): messd takes commands only from the page it serves");
      }
    }
    const auto& token = shared_->config.web.token;
    if (!token.empty() && !same_secret(token_of(std_view(request.target())), token))
      observe_reason_ = "this page gave no or a wrong web panel token (server.http_token): it may observe but not control";
    ws_.set_option(websocket::stream_base::timeout{std::chrono::seconds(30), std::chrono::seconds(300), true});
    ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& r) { r.set(http::field::server, "messd"); }));
    ws_.read_message_max(webjson::kMaxMessageBytes);
    request_ = std::move(request);
    ws_.async_accept(request_, [self = shared_from_this()](beast::error_code aec) {
      if (!aec) self->connect();
    });
  }

 private:
  void reject(const WebRequest& request, http::status status, std::string text) {
    auto r = std::make_shared<http::response<http::string_body>>(status, request.version());
    r->set(http::field::server, "messd");
    r->set(http::field::content_type, "text/plain; charset=utf-8");
    r->body() = std::move(text) + "\n";
    r->keep_alive(false);
    r->prepare_payload();
    auto& stream = beast::get_lowest_layer(ws_);
    http::async_write(stream, *r, [self = shared_from_this(), r](beast::error_code, std::size_t) {
      beast::get_lowest_layer(self->ws_).close();
    });
  }

  // The MESSD session: one end of a socket pair for it, the other for us.
  void connect() {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      log_limited(shared_->log, spdlog::level::err, "web-pair", "web panel: no socket pair for a session: " + std::string(std::strerror(errno)));
      return finish();
    }
    boost::system::error_code ec;
    line_.assign(asio::local::stream_protocol(), fds[0], ec);
    tcp::socket session_end(ws_.get_executor());
    session_end.assign(tcp::v4(), fds[1], ec);
    shared_->sessions.adopt(std::move(session_end), peer_, "over the web panel", observe_reason_);
    read_browser();
    read_session();
  }

  void read_browser() {
    if (to_session_.size() >= kMaxPending) {  // the session is behind: let the browser wait
      browser_paused_ = true;
      return;
    }
    ws_.async_read(in_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->finish();
      self->on_message();
    });
  }

  void on_message() {
    const std::string message = beast::buffers_to_string(in_.data());
    in_.consume(in_.size());
    if (!ws_.got_text()) {
      to_browser(err_event(101, "a binary message; the panel speaks JSON text messages (docs/web.md)"));
    } else if (answer_inspect_message(message, shared_, ws_.get_executor(), move_refusal(),
                                      [self = shared_from_this()](std::string r) { self->to_browser(std::move(r)); })) {
      // an inspection's list, its refusal, or messcap started: the answer comes when it ends
    } else if (auto path = answer_path_message(message, shared_->programs)) {
      to_browser(std::move(*path));  // the loaded program's path: answered here, at once
    } else if (auto points = webpoints::answer_points_message(message)) {
      to_browser(std::move(*points));  // a file or a fit of the page's points: answered here, at once
    } else {
      auto result = webjson::command_lines(message);
      if (auto* refusal = std::get_if<webjson::Refusal>(&result)) {
        to_browser(err_event(refusal->code, refusal->text));
      } else {
        for (const auto& l : std::get<std::vector<std::string>>(result)) to_session_ += l + '\n';
        write_session();
      }
    }
    read_browser();
  }

  // Why this page may not move the machine ("": it may): its token, or its host.
  std::string move_refusal() const {
    if (!observe_reason_.empty()) return observe_reason_;
    auto address = peer_.address();
    if (address.is_v6() && address.to_v6().is_v4_mapped()) address = asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6());
    if (!shared_->config.control.hosts.contains(address))
      return "host " + address.to_string() + " may observe but not control the machine (control.hosts)";
    return {};
  }

  void write_session() {
    if (writing_session_ || to_session_.empty() || !line_.is_open()) return;
    writing_session_ = true;
    auto bytes = std::make_shared<std::string>(std::move(to_session_));
    to_session_.clear();
    asio::async_write(line_, asio::buffer(*bytes), [self = shared_from_this(), bytes](boost::system::error_code ec, std::size_t) {
      self->writing_session_ = false;
      if (ec) return self->finish();
      self->write_session();
      if (self->browser_paused_ && self->to_session_.size() < kMaxPending) {
        self->browser_paused_ = false;
        self->read_browser();
      }
    });
  }

  void read_session() {
    if (browser_bytes_ >= kMaxPending) {  // the browser is behind: the session's output waits in the pair
      session_paused_ = true;
      return;
    }
    line_.async_read_some(asio::buffer(chunk_), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
      if (ec) {  // the session closed (Quit, dropped, refused): what it said goes out, then the WebSocket closes
        self->session_gone_ = true;
        self->write_browser();
        return;
      }
      self->partial_.append(self->chunk_.data(), n);
      std::size_t at = 0;
      for (std::size_t nl; (nl = self->partial_.find('\n', at)) != std::string::npos; at = nl + 1)
        self->to_browser(webjson::event_text(std::string_view(self->partial_).substr(at, nl - at)));
      self->partial_.erase(0, at);
      self->read_session();
    });
  }

  void to_browser(std::string message) {
    browser_bytes_ += message.size();
    out_.push_back(std::move(message));
    write_browser();
  }

  void write_browser() {
    if (writing_browser_ || closed_) return;
    if (out_.empty()) {
      if (session_gone_) {
        closed_ = true;
        ws_.async_close(websocket::close_code::normal, [self = shared_from_this()](beast::error_code) { self->finish(); });
      }
      return;
    }
    writing_browser_ = true;
    ws_.text(true);
    ws_.async_write(asio::buffer(out_.front()), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->writing_browser_ = false;
      if (ec) return self->finish();
      self->browser_bytes_ -= self->out_.front().size();
      self->out_.pop_front();
      if (self->session_paused_ && self->browser_bytes_ < kMaxPending) {
        self->session_paused_ = false;
        self->read_session();
      }
      self->write_browser();
    });
  }

  // Either side gone: both closed. The session sees its socket end (a closed connection:
  // control is lost and the machine stops, as for any client).
  void finish() {
    boost::system::error_code ec;
    line_.close(ec);
    beast::get_lowest_layer(ws_).close();
  }

  websocket::stream<beast::tcp_stream> ws_;
  asio::local::stream_protocol::socket line_;
  std::shared_ptr<WebServer::Shared> shared_;
  WebRequest request_;
  tcp::endpoint peer_;
  std::string observe_reason_;
  beast::flat_buffer in_;
  std::array<char, 8192> chunk_{};
  std::string partial_;     // the session's bytes after its last line end
  std::string to_session_;  // lines waiting to go into the pair
  std::deque<std::string> out_;  // JSON messages waiting for the browser
  std::size_t browser_bytes_ = 0;
  bool writing_session_ = false, writing_browser_ = false, browser_paused_ = false, session_paused_ = false;
  bool session_gone_ = false, closed_ = false;
};

}  // namespace

void start_web_session(beast::tcp_stream stream, WebRequest request, std::shared_ptr<WebServer::Shared> shared) {
  std::make_shared<WebBridge>(std::move(stream), std::move(shared))->start(std::move(request));
}

}  // namespace imess::net
