// The panel's files: GET and HEAD of a path below the web root, nothing else; /three/… comes
// from Debian's libjs-three (kThreeRoot) by the same rules. A path that leaves its root (.., a
// link pointing out), names no regular file or holds odd bytes is 404.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "web_shared.hpp"

namespace imess::net {

namespace http = boost::beast::http;

namespace {

std::string_view content_type(std::string_view path) {
  const auto dot = path.rfind('.');
  const std::string_view ext = dot == std::string_view::npos ? "" : path.substr(dot + 1);
  if (ext == "html") return "text/html; charset=utf-8";
  if (ext == "js") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "json") return "application/json";
  if (ext == "png") return "image/png";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "ico") return "image/x-icon";
  return "text/plain; charset=utf-8";
}

http::response<http::string_body> plain(const WebRequest& request, http::status status, std::string text) {
  http::response<http::string_body> r{status, request.version()};
  r.set(http::field::server, "messd");
  r.set(http::field::content_type, "text/plain; charset=utf-8");
  r.body() = std::move(text) + "\n";
  return r;
}

// The file a request target names below root, or empty.
std::string file_of(std::string_view target, const std::string& root) {
  const auto query = target.find('?');
  std::string_view path = target.substr(0, query);
  if (path.empty() || path[0] != '/') return {};
  for (unsigned char c : path)
    if (c < 33 || c > 126 || c == '\\' || c == '%') return {};  // the panel's names need no escapes
  std::string relative(path.substr(1));
  if (relative.empty() || relative.back() == '/') relative += "index.html";
  std::error_code ec;
  const auto base = std::filesystem::weakly_canonical(root, ec);
  if (ec) return {};
  const auto file = std::filesystem::weakly_canonical(base / relative, ec);
  if (ec) return {};
  const auto inside = std::filesystem::relative(file, base, ec);
  if (ec || inside.empty() || *inside.begin() == "..") return {};
  if (!std::filesystem::is_regular_file(file, ec)) return {};
  return file.string();
}

// The folder a target's path is in and the target below it: /three/… is three.js, /reports/…
// messcap inspect's reports.
std::pair<std::string, std::string_view> mapped(std::string_view target, const WebServer::Shared& shared) {
  constexpr std::string_view three = "/three/";
  constexpr std::string_view reports = "/reports/";
  if (target.starts_with(three)) return {std::string(kThreeRoot), target.substr(three.size() - 1)};
  if (target.starts_with(reports) && !shared.reports.empty()) return {shared.reports, target.substr(reports.size() - 1)};
  return {shared.root, target};
}

}  // namespace

http::response<http::string_body> file_response(const WebRequest& request, const WebServer::Shared& shared) {
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    auto r = plain(request, http::status::method_not_allowed, "messd's web panel answers GET and HEAD only");
    r.set(http::field::allow, "GET, HEAD");
    return r;
  }
  const auto [folder, target] = mapped(std_view(request.target()), shared);
  const std::string file = file_of(target, folder);
  if (file.empty()) return plain(request, http::status::not_found, "no such file in messd's web panel");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream body;
  body << in.rdbuf();
  if (!in) return plain(request, http::status::internal_server_error, "cannot read " + file);
  http::response<http::string_body> r{http::status::ok, request.version()};
  r.set(http::field::server, "messd");
  r.set(http::field::content_type, std::string(content_type(file)));
  r.set(http::field::cache_control, "no-cache");
  r.set("X-Content-Type-Options", "nosniff");
  // A report is messcap's one self-contained page (its style inline, its pictures inline SVG).
  if (folder == shared.reports)
    r.set("Content-Security-Policy", "default-src 'none'; style-src 'unsafe-inline'; img-src data:");
  else
    r.set("Content-Security-Policy", "default-src 'self'; connect-src 'self'; img-src 'self' data: blob:");
  r.body() = body.str();
  return r;
}

}  // namespace imess::net
