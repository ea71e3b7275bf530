// The web panel against a real messd: its files over HTTP, and a WebSocket that is a MESSD
// client in JSON — the same position, replies, hits, control rules, host lists, dead-man and
// closing rules as a client on 1066 (docs/web.md).
#include <catch2/catch.hpp>

#include "net_fixture.hpp"
#include "web_client.hpp"

using namespace imess::test;
using nlohmann::json;
namespace http = boost::beast::http;

namespace {
bool is(const std::optional<json>& e, const std::string& type) { return e && (*e)["type"] == type; }
json cmd(const std::string& verb, json args = json::array()) { return json{{"cmd", verb}, {"args", std::move(args)}}; }
}  // namespace

TEST_CASE("web panel: messd serves the panel's files, nothing outside them, GET and HEAD only") {
  DaemonProcess messd({"--config", fast_cmm()});
  REQUIRE(messd.web_port() > 0);
  auto page = http_request(messd.web_port(), http::verb::get, "/");
  CHECK(page.result() == http::status::ok);
  CHECK(page[http::field::content_type] == "text/html; charset=utf-8");
  CHECK(page.body().find("<title>IMESS") != std::string::npos);
  auto head = http_request(messd.web_port(), http::verb::head, "/index.html");
  CHECK(head.result() == http::status::ok);
  CHECK(head[http::field::content_length] == std::to_string(page.body().size()));
  CHECK(http_request(messd.web_port(), http::verb::get, "/../CMakeLists.txt").result() == http::status::not_found);
  CHECK(http_request(messd.web_port(), http::verb::get, "/%2e%2e/CMakeLists.txt").result() == http::status::not_found);
  CHECK(http_request(messd.web_port(), http::verb::get, "/no-such-file.js").result() == http::status::not_found);
  CHECK(http_request(messd.web_port(), http::verb::post, "/").result() == http::status::method_not_allowed);
  // Debian's libjs-three (scripts/deps.sh installs it) as /three/, by the same rules.
  auto three = http_request(messd.web_port(), http::verb::get, "/three/build/three.module.js");
  CHECK(three.result() == http::status::ok);
  CHECK(three[http::field::content_type] == "text/javascript; charset=utf-8");
  CHECK(three.body().find("WebGLRenderer") != std::string::npos);
  CHECK(http_request(messd.web_port(), http::verb::get, "/three/examples/jsm/controls/OrbitControls.js").result() == http::status::ok);
  CHECK(http_request(messd.web_port(), http::verb::get, "/three/../../../etc/passwd").result() == http::status::not_found);
  CHECK(http_request(messd.web_port(), http::verb::get, "/three/").result() == http::status::not_found);
}

TEST_CASE("web panel: --http-port 0 turns it off") {
  DaemonProcess messd({"--config", fast_cmm(), "--http-port", "0"});
  CHECK(messd.web_port() == 0);
}

TEST_CASE("web panel: the WebSocket is a MESSD client in JSON — position, replies, a jog's hit, as on 1066") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient telnet(messd.port());
  WebClient web(messd.web_port());
  auto pos = web.next();
  REQUIRE(is(pos, "CurrCor"));
  CHECK((*pos)["x"] == 430.0);
  CHECK((*pos)["y"] == 330.0);
  CHECK((*pos)["z"] == 100.0);
  CHECK((*pos)["line"] == "CurrCor 430.000 330.000 100.000");
  auto hello = web.request(cmd("Hello", {"web"}));
  REQUIRE(is(hello, "Ok"));
  CHECK((*hello)["verb"] == "Hello");
  auto jog = web.request(cmd("StartMv", {0, 0, -20}));
  REQUIRE(is(jog, "Ok"));
  CHECK((*jog)["verb"] == "StartMv");
  CHECK(telnet.until_prefix("Control web 127.0.0.1", 3.0));
  auto hit = web.until_type("Hit", 10.0);
  REQUIRE(hit);
  CHECK((*hit)["z"] == 80.0);
  CHECK((*hit)["k"] == -1.0);
  // The same hit as 1066's clients get it, line for line.
  auto line = telnet.until_prefix("Hit ", 3.0);
  REQUIRE(line);
  CHECK(*line == (*hit)["line"].get<std::string>());
  CHECK(is(web.until_type("MeasPt", 3.0), "MeasPt"));
  // The page's points as a file: the web front end answers with messcap's writer, at once.
  json point = {{"seq", (*hit)["seq"]}};
  for (const char* k : {"x", "y", "z", "i", "j", "k", "r"}) point[k] = (*hit)[k];
  web.send_text(json{{"export", "csv"}, {"id", 1}, {"hits", json::array({point})}}.dump());
  auto file = web.until_type("Export", 3.0);
  REQUIRE(file);
  CHECK((*file)["text"] == "hit,x,y,z,scan\n" + std::to_string((*hit)["seq"].get<int>()) + ",430.000,330.000,80.000,\n");
  // The loaded program's path: none loaded yet, then the check's 20 segments of the bore's program.
  web.send_text(R"({"path":"loaded","id":2})");
  auto none = web.until_type("Path", 3.0);
  REQUIRE(none);
  CHECK((*none)["error"].get<std::string>().find("no program loaded") != std::string::npos);
  // Inspection: the programs folder's plans; a name outside it is no plan.
  web.send_text(R"({"inspect":"run","plan":"../cube-1996.plan.json","id":3})");
  auto outside = web.until_type("Inspect", 3.0);
  REQUIRE(outside);
  CHECK((*outside)["error"].get<std::string>().find("no plan '../cube-1996.plan.json' in the programs folder") != std::string::npos);
  web.send_text(R"({"path":"everything"})");
  auto wrong = web.until_type("Path", 3.0);
  REQUIRE(wrong);
  CHECK((*wrong)["error"].get<std::string>().find("accepted: {\"path\":\"loaded\"") != std::string::npos);
  // A message that is no command gets the line protocol's Err, saying what is accepted.
  web.send_text("StartMv 0 0 -20");
  auto refused = web.until_type("Err", 3.0);
  REQUIRE(is(refused, "Err"));
  CHECK((*refused)["code"] == 101);
  CHECK((*refused)["text"].get<std::string>().find("accepted:") != std::string::npos);
  // A typed line goes as it is; Quit ends the session and the WebSocket.
  auto status = web.request(json{{"line", "Status"}});
  REQUIRE(is(status, "Ok"));
  CHECK((*status)["line"].get<std::string>().find("Control web@127.0.0.1") != std::string::npos);
  REQUIRE(is(web.request(cmd("Quit")), "Ok"));
  CHECK_FALSE(web.next(3.0));
  CHECK(telnet.until_prefix("Control none", 3.0));
}

TEST_CASE("web panel: a closed tab mid-jog stops the machine and frees control, as a closed connection does") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient telnet(messd.port());
  {
    WebClient web(messd.web_port());
    REQUIRE(is(web.request(cmd("StartMv", {20, 0, 0})), "Ok"));
    REQUIRE(telnet.until_prefix("State jog", 3.0));
    web.close();
  }
  CHECK(telnet.until_prefix("Control none", 2.0));  // control lost: the machine stops
  CHECK(telnet.until_prefix("State stopping", 2.0));
}

TEST_CASE("web panel: the dead-man (Watch) stops a jog when the page falls silent") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient telnet(messd.port());
  WebClient web(messd.web_port());
  REQUIRE(is(web.request(cmd("Watch", {300})), "Ok"));
  REQUIRE(is(web.request(cmd("StartMv", {20, 0, 0})), "Ok"));
  // Keep-alives hold it...
  for (int i = 0; i < 5; ++i) {
    web.send(json{{"cmd", ""}});
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  auto status = telnet.request("Status");
  REQUIRE(status);
  CHECK(status_field(*status, "State") == "jog");
  // ... silence stops it.
  auto warn = web.until([](const json& e) { return e["type"] == "Warn" && e["name"] == "WatchExpired"; }, 3.0);
  CHECK(warn);
  CHECK(telnet.until_prefix("State stopping", 2.0));
}

TEST_CASE("web panel: the host lists hold for the page: an observer host may watch and stop, not move") {
  TempConfig config(R"({ "motion": { "max_speed": 100, "max_accel": 4000, "max_velocity": 400 }, "sim": { "time": "loop" },
                         "control": { "hosts": ["127.0.0.1/32"], "observe_hosts": ["127.0.0.2/32"] } })");
  DaemonProcess messd({"--config", config.path()});
  WebClient far(messd.web_port(), "127.0.0.2");
  REQUIRE(is(far.next(), "CurrCor"));
  auto refused = far.request(cmd("StartMv", {0, 0, -20}));
  REQUIRE(is(refused, "Err"));
  CHECK((*refused)["code"] == 210);
  CHECK((*refused)["text"].get<std::string>().find("127.0.0.2") != std::string::npos);
  CHECK(is(far.request(cmd("StopMv")), "Ok"));
  // An inspection moves the machine: an observer's is refused before messcap starts.
  far.send_text(R"({"inspect":"run","plan":"cube-top.plan.json","id":9})");
  auto inspect = far.until_type("Inspect", 3.0);
  REQUIRE(inspect);
  CHECK((*inspect)["id"] == 9);
  CHECK((*inspect)["error"].get<std::string>().find("may observe but not control") != std::string::npos);
  // A host in neither list is refused the page and the WebSocket.
  CHECK(upgrade_status(messd.web_port(), "127.0.0.3", "/ws", "") == 403);
}

TEST_CASE("web panel: a page served elsewhere is refused (Origin), the token is needed for control") {
  TempConfig config(R"({ "motion": { "max_speed": 100, "max_accel": 4000, "max_velocity": 400 }, "sim": { "time": "loop" },
                         "server": { "http_token": "s3cret" } })");
  DaemonProcess messd({"--config", config.path()});
  const std::string own = "http://127.0.0.1:" + std::to_string(messd.web_port());
  CHECK(upgrade_status(messd.web_port(), "", "/ws?token=s3cret", "http://evil.example") == 403);
  CHECK(upgrade_status(messd.web_port(), "", "/ws?token=s3cret", own) == 101);
  WebClient without(messd.web_port(), "", "/ws", own);
  auto refused = without.request(cmd("StartMv", {0, 0, -20}));
  REQUIRE(is(refused, "Err"));
  CHECK((*refused)["code"] == 210);
  CHECK((*refused)["text"].get<std::string>().find("server.http_token") != std::string::npos);
  CHECK(is(without.request(cmd("StopMv")), "Ok"));
  WebClient wrong(messd.web_port(), "", "/ws?token=guess", own);
  CHECK(is(wrong.request(cmd("StartMv", {0, 0, -20})), "Err"));
  WebClient with(messd.web_port(), "", "/ws?token=s3cret", own);
  CHECK(is(with.request(cmd("StartMv", {0, 0, -20})), "Ok"));
}
