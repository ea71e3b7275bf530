// What the web front end's connections share (web_server.cpp, web_http.cpp, web_bridge.cpp).
#pragma once
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "imess/net/web_server.hpp"

namespace imess::net {

struct WebServer::Shared {
  const ServerConfig& config;
  SessionHub& sessions;
  LogLimiter& log;
  const ProgramRunner* programs;  // the loaded program's path ({"path":…}); null: none
  std::string root;           // the panel's files, an absolute path
  std::string reports;        // messcap inspect's reports, served as /reports/ (web_inspect.cpp)
  bool inspecting = false;    // one inspection at a time
  std::size_t connections = 0;  // HTTP connections open (not the WebSocket sessions)
  bool running = true;
};

// Debian's libjs-three, served as /three/ (the panel's 3-D view; docs/web.md).
inline constexpr std::string_view kThreeRoot = "/usr/share/javascript/three";

// Beast's string_view (Boost's in 1.74) as the standard one.
inline std::string_view std_view(boost::beast::string_view s) { return {s.data(), s.size()}; }

using WebRequest = boost::beast::http::request<boost::beast::http::string_body>;

// One HTTP connection: requests for files until it closes or asks for the WebSocket.
void serve_http(boost::asio::ip::tcp::socket socket, std::shared_ptr<WebServer::Shared> shared);
// The WebSocket upgrade of `request` on `stream`: checked (Origin, token), accepted, bridged.
void start_web_session(boost::beast::tcp_stream stream, WebRequest request, std::shared_ptr<WebServer::Shared> shared);
// The answer to the page's {"path":"loaded"} (web_path.cpp); nothing for any other message.
std::optional<std::string> answer_path_message(std::string_view message, const ProgramRunner* programs);
// The response for a file request (GET/HEAD): the panel's, three.js's (/three/), a report (/reports/).
boost::beast::http::response<boost::beast::http::string_body> file_response(const WebRequest& request, const WebServer::Shared& shared);
// The page's {"inspect":…} (web_inspect.cpp): answered (now, or when messcap ends) through
// `answer`; false for any other message. `refusal`: why this page may not move the machine ("": it may).
bool answer_inspect_message(std::string_view message, const std::shared_ptr<WebServer::Shared>& shared,
                            boost::asio::any_io_executor ex, const std::string& refusal, std::function<void(std::string)> answer);

}  // namespace imess::net
