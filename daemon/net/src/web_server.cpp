// The web panel's listener: accepting, the connection count, where the files are.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "web_shared.hpp"

namespace imess::net {

namespace asio = boost::asio;
using asio::ip::tcp;

std::string default_web_root() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "imess" / "web";
    if (std::filesystem::is_regular_file(installed / "index.html", ec)) return installed.string();
  }
  return IMESS_WEB_SOURCE_DIR;
}

WebServer::WebServer(asio::io_context& io, const ServerConfig& config, SessionHub& sessions, LogLimiter& log,
                     const ProgramRunner* programs)
    : acceptor_(io) {
  std::string root = config.web.root.empty() ? default_web_root() : config.web.root;
  std::error_code ec;
  const auto absolute = std::filesystem::weakly_canonical(root, ec);
  root_ = ec ? root : absolute.string();
  shared_ = std::make_shared<Shared>(Shared{config, sessions, log, programs, root_});
  // messcap inspect's reports for the page: a folder of this process, gone when it stops.
  shared_->reports = (std::filesystem::temp_directory_path(ec) / ("messd-reports-" + std::to_string(::getpid()))).string();
}

WebServer::~WebServer() {
  stop();
  std::error_code ec;
  std::filesystem::remove_all(shared_->reports, ec);
}

void WebServer::start() {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(std::filesystem::path(root_) / "index.html", ec))
    throw std::runtime_error("the web panel's files are not in " + root_ + " (no index.html): server.http_root names "
                             "the folder, server.http_port 0 or --http-port 0 turns the panel off");
  const auto& config = shared_->config;
  std::filesystem::create_directories(shared_->reports, ec);
  if (ec) {
    spdlog::warn("web panel: no folder for inspection reports ({}): {}", shared_->reports, ec.message());
    shared_->reports.clear();
  }
  port_ = open_listener(acceptor_, config.listen, config.web.port, " for the web panel",
                        " - is another messd or web server running? (--http-port chooses another, 0 turns it off)");
  running_ = true;
  accept();
}

void WebServer::stop() {
  if (!running_) return;
  running_ = false;
  shared_->running = false;
  boost::system::error_code ec;
  acceptor_.close(ec);
}

void WebServer::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (!running_) return;
    if (ec) {
      log_limited(shared_->log, spdlog::level::warn, "web-accept", "web panel: accept failed: " + ec.message());
      // Out of descriptors: try again a little later rather than spin.
      auto timer = std::make_shared<asio::steady_timer>(acceptor_.get_executor(), std::chrono::milliseconds(100));
      timer->async_wait([this, timer](boost::system::error_code) {
        if (running_) accept();
      });
      return;
    }
    if (shared_->connections >= shared_->config.web.max_connections) {
      log_limited(shared_->log, spdlog::level::warn, "web-full",
                  "web panel: refused a connection, " + std::to_string(shared_->connections) + " HTTP connections open");
      boost::system::error_code ignored;
      socket.close(ignored);
    } else {
      serve_http(std::move(socket), shared_);
    }
    accept();
  });
}

}  // namespace imess::net
