// messmqtt end to end: a real mosquitto, three real messd instances (simulated machines), three
// bridges, one subscriber. Every hit of all three machines arrives exactly once after dedup by
// seq, in seq order per machine, also across a broker killed and restarted mid-measurement
// and a bridge killed and restarted; the retained state shows the control holder and the
// position; a stop on the broker stops the machine whose bridge allows it and is ignored (and
// logged) by the one that does not. messfleet --once --json reads the fleet.
#include <mosquitto.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "daemon_process.hpp"

using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {

int free_loopback_port() {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  ::close(fd);
  return ntohs(a.sin_port);
}

bool port_accepts(int port) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(fd);
  return ok;
}

template <class Pred>
bool wait_until(Pred pred, std::chrono::milliseconds timeout) {
  const auto end = Clock::now() + timeout;
  while (Clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds{10});
  }
  return pred();
}

// Debian's mosquitto on a free loopback port, no persistence, anonymous: a broker that
// forgets everything when killed, the hard case for "nothing lost".
class Broker {
 public:
  explicit Broker(const TempDir& dir) : conf_(dir.file("mosquitto.conf")), port_(free_loopback_port()) {
    std::ofstream(conf_) << "listener " << port_ << " 127.0.0.1\nallow_anonymous true\npersistence false\n";
    start();
  }
  ~Broker() { kill_now(SIGTERM); }
  void start() {
    pid_ = ::fork();
    if (pid_ == 0) {
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
      ::execl("/usr/sbin/mosquitto", "mosquitto", "-c", conf_.c_str(), nullptr);
      ::_exit(127);
    }
    if (!wait_until([&] { return port_accepts(port_); }, std::chrono::seconds{5}))
      throw std::runtime_error("mosquitto did not start on port " + std::to_string(port_) + " (is the mosquitto package installed?)");
  }
  void kill_now(int sig) {
    if (pid_ <= 0) return;
    ::kill(pid_, sig);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  int port() const { return port_; }

 private:
  std::string conf_;
  int port_;
  pid_t pid_ = -1;
};

// One subscriber with libmosquitto's own thread: what a dashboard or a quality database does.
class Subscriber {
 public:
  explicit Subscriber(int port) {
    mosquitto_lib_init();
    m_ = mosquitto_new("test-subscriber", true, this);
    mosquitto_connect_callback_set(m_, [](mosquitto* m, void* self, int rc) {
      if (rc != 0) return;
      for (const char* t : {"imess/+/hit", "imess/+/event", "imess/+/state", "imess/+/online", "imess/+/replay/sub1"})
        mosquitto_subscribe(m, nullptr, t, 1);
      ++static_cast<Subscriber*>(self)->connects_;
    });
    mosquitto_message_callback_set(m_, [](mosquitto*, void* self, const mosquitto_message* msg) {
      static_cast<Subscriber*>(self)->message(msg->topic, std::string(static_cast<const char*>(msg->payload), msg->payloadlen));
    });
    mosquitto_threaded_set(m_, true);  // publish() comes from the test's thread, the loop runs in thread_
    if (mosquitto_connect(m_, "127.0.0.1", port, 5) != MOSQ_ERR_SUCCESS) throw std::runtime_error("subscriber: no broker");
    // Its own loop, which reconnects within 20 ms of the broker's return (libmosquitto's
    // thread waits at least a second): subscribed again before the bridges publish again.
    thread_ = std::thread([this] {
      while (!quit_) {
        if (mosquitto_loop(m_, 20, 1) != MOSQ_ERR_SUCCESS && !quit_) {
          std::this_thread::sleep_for(std::chrono::milliseconds{20});
          mosquitto_reconnect(m_);
        }
      }
    });
  }
  ~Subscriber() {
    quit_ = true;
    thread_.join();
    mosquitto_disconnect(m_);
    mosquitto_destroy(m_);
  }
  int connects() const { return connects_; }
  void publish(const std::string& topic, const std::string& payload, bool retain = false) {
    mosquitto_publish(m_, nullptr, topic.c_str(), static_cast<int>(payload.size()), payload.data(), 1, retain);
  }
  struct Machine {
    std::vector<std::uint64_t> live;  // seqs on imess/<m>/hit in arrival order
    std::set<std::uint64_t> have;
    int duplicates = 0, by_replay = 0;
    std::vector<nlohmann::json> events, replay_answers;
    nlohmann::json state, online;
    std::vector<Clock::time_point> state_times;  // when each state message arrived
  };
  template <class F>
  auto with(F f) {
    std::lock_guard lock(mu_);
    return f(machines_);
  }

 private:
  void message(const std::string& topic, const std::string& payload) {
    const auto parts = split(topic);
    if (parts.size() < 3) return;
    const auto j = nlohmann::json::parse(payload);
    std::lock_guard lock(mu_);
    auto& m = machines_[parts[1]];
    if (parts[2] == "hit") {
      const auto seq = j.at("seq").get<std::uint64_t>();
      m.live.push_back(seq);
      if (!m.have.insert(seq).second) ++m.duplicates;
    } else if (parts[2] == "replay") {
      if (j.contains("seq")) {
        if (m.have.insert(j.at("seq").get<std::uint64_t>()).second) ++m.by_replay;
      } else {
        m.replay_answers.push_back(j);
      }
    } else if (parts[2] == "event") {
      m.events.push_back(j);
    } else if (parts[2] == "state") {
      m.state = j;
      m.state_times.push_back(Clock::now());
    } else if (parts[2] == "online") {
      m.online = j;
    }
  }
  static std::vector<std::string> split(const std::string& t) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
      const auto slash = t.find('/', start);
      out.push_back(t.substr(start, slash - start));
      if (slash == std::string::npos) return out;
      start = slash + 1;
    }
  }
  mosquitto* m_;
  std::thread thread_;
  std::atomic<bool> quit_{false};
  std::atomic<int> connects_{0};
  std::mutex mu_;
  std::map<std::string, Machine> machines_;
};

struct Cell {  // one machine: messd, its bridge, a client that takes its hits
  std::string name, config, state_file;
  std::unique_ptr<DaemonProcess> messd;
  std::unique_ptr<ChildProcess> bridge;
  std::unique_ptr<LineClient> client;
  std::string bridge_log;  // stderr of bridges ended before
  void start_bridge() {
    bridge = std::make_unique<ChildProcess>(std::vector<std::string>{
        client_binary("messmqtt"), "--config", config, "127.0.0.1:" + std::to_string(messd->port())});
  }
  void kill_bridge(int sig) {
    bridge->signal(sig);
    bridge->wait(std::chrono::seconds{5});
    bridge_log += bridge->err();
  }
  std::uint64_t acked() const {
    std::ifstream in(state_file);
    nlohmann::json j;
    try {
      in >> j;
      return j.at("acked").get<std::uint64_t>();
    } catch (...) {
      return 0;  // being renamed this very moment
    }
  }
};

}  // namespace

TEST_CASE("messmqtt: three machines on a real mosquitto, every hit exactly once in seq order across a broker and a bridge restart, retained state, stop only where allowed") {
  TempDir dir;
  Broker broker(dir);
  std::vector<Cell> cells(3);
  for (int i = 0; i < 3; ++i) {
    auto& c = cells[static_cast<std::size_t>(i)];
    c.name = "m" + std::to_string(i + 1);
    c.config = dir.file(c.name + ".json");
    c.state_file = dir.file(c.name + "-acked.json");
    // messd reads the same file as its bridge: it accepts the "mqtt" section messmqtt checks.
    std::ofstream(c.config) << nlohmann::json{
        {"motion", {{"max_speed", 100}, {"max_accel", 4000}, {"max_velocity", 400}, {"goto_speed", 300}, {"idle_open_s", 60}}},
        {"sim", {{"time", "loop"}}},
        {"mqtt", {{"broker", "127.0.0.1:" + std::to_string(broker.port())},
                  {"machine", c.name},
                  {"allow_stop", c.name != "m2"},
                  {"state_file", c.state_file}}}}.dump(2);
    c.messd = std::make_unique<DaemonProcess>(std::vector<std::string>{"--config", c.config});
    c.start_bridge();
  }
  Subscriber sub(broker.port());
  REQUIRE(wait_until([&] {
    return sub.with([](auto& ms) {
      int up = 0;
      for (auto& [n, m] : ms) up += m.online.is_object() && m.online.value("online", false) && m.online.value("messd", false);
      return up == 3;
    });
  }, std::chrono::seconds{5}));
  for (auto& c : cells) {
    c.client = std::make_unique<LineClient>(c.messd->port());
    REQUIRE(c.client->request("Hello mqtttest")->rfind("Ok Hello", 0) == 0);
  }

  // Hits, taken on all three machines in turn (ForcePt: a journaled hit at once).
  std::uint64_t sent = 0;
  auto take_hits = [&](int n) {
    for (int k = 0; k < n; ++k)
      for (auto& c : cells) {
        REQUIRE(c.client->request("ForcePt") == std::optional<std::string>("Ok ForcePt"));
        ++sent;
      }
  };
  take_hits(30);
  cells[2].kill_bridge(SIGKILL);  // m3's bridge dies: its state file says how far the broker got
  take_hits(10);
  broker.kill_now(SIGKILL);       // the broker dies mid-measurement, with what it had not delivered
  take_hits(30);
  broker.start();
  // m3's new bridge once the subscriber is back (the others retry every 0.5 s, it every 20 ms):
  // what the bridges publish again from the journal then reaches it live.
  REQUIRE(wait_until([&] { return sub.connects() >= 2; }, std::chrono::seconds{3}));
  cells[2].start_bridge();
  take_hits(30);
  constexpr std::uint64_t kPerMachine = 100;
  REQUIRE(sent == 3 * kPerMachine);

  // Each bridge has the broker's PUBACK for every hit (its state file says so) ...
  for (auto& c : cells) {
    INFO(c.name << " acknowledged up to " << c.acked() << "; bridge log:\n" << c.bridge_log << c.bridge->err());
    REQUIRE(wait_until([&] { return c.acked() == kPerMachine; }, std::chrono::seconds{10}));
  }
  // ... and the subscriber, once the broker's queue has drained, asks for what a broker killed
  // between its PUBACK and the delivery could not send it: replay requests, read-only.
  wait_until([&] { return sub.with([&](auto& ms) {
    std::size_t n = 0;
    for (auto& [name, m] : ms) n += m.have.size();
    return n == 3 * kPerMachine;
  }); }, std::chrono::seconds{2});
  for (auto& c : cells) {
    for (int round = 0; round < 5; ++round) {
      const auto missing = sub.with([&](auto& ms) {
        auto& m = ms[c.name];
        for (std::uint64_t s = 1; s <= kPerMachine; ++s)
          if (!m.have.count(s)) return s;
        return std::uint64_t{0};
      });
      if (missing == 0) break;
      const auto answers = sub.with([&](auto& ms) { return ms[c.name].replay_answers.size(); });
      sub.publish("imess/" + c.name + "/replay", nlohmann::json{{"from", missing}, {"reply_to", "sub1"}}.dump());
      REQUIRE(wait_until([&] { return sub.with([&](auto& ms) { return ms[c.name].replay_answers.size() > answers; }); },
                         std::chrono::seconds{5}));
    }
  }

  std::uint64_t received = 0, duplicates = 0, replayed = 0;
  for (auto& c : cells) {
    sub.with([&](auto& ms) {
      auto& m = ms[c.name];
      INFO(c.name);
      // exactly once after dedup: every seq 1 … 100, nothing else
      CHECK(m.have.size() == kPerMachine);
      CHECK(*m.have.begin() == 1);
      CHECK(*m.have.rbegin() == kPerMachine);
      // in seq order: dropping the repeats of a republication, the live stream only rises
      std::uint64_t highest = 0;
      for (auto seq : m.live) {
        if (seq <= highest) continue;  // a duplicate after a break (recognised by seq)
        CHECK(seq > highest);
        highest = seq;
      }
      std::uint64_t last = 0;
      bool rising = true;
      std::set<std::uint64_t> seen;
      for (auto seq : m.live) {
        if (seen.count(seq)) continue;
        rising = rising && seq > last;
        last = seq;
        seen.insert(seq);
      }
      CHECK(rising);
      for (const auto& a : m.replay_answers) CHECK(a.value("done", false));
      received += m.have.size();
      duplicates += static_cast<std::uint64_t>(m.duplicates);
      replayed += static_cast<std::uint64_t>(m.by_replay);
      std::printf("mqtt: %s: %llu hits sent, %zu distinct received (%zu live messages, %d duplicates, %d by a replay request)\n",
                  c.name.c_str(), static_cast<unsigned long long>(kPerMachine), m.have.size(), m.live.size(),
                  m.duplicates, m.by_replay);
      return 0;
    });
  }
  std::printf("mqtt: all: %llu hits sent, %llu received exactly once after dedup, %llu duplicates recognised by seq, %llu "
              "fetched by replay requests; the broker was killed (SIGKILL) and restarted, m3's bridge killed and restarted\n",
              static_cast<unsigned long long>(sent), static_cast<unsigned long long>(received),
              static_cast<unsigned long long>(duplicates), static_cast<unsigned long long>(replayed));
  CHECK(received == sent);

  // A late subscriber reads what it missed: a read-only replay request, answered on its own topic.
  const auto answers_before = sub.with([](auto& ms) { return ms["m1"].replay_answers.size(); });
  sub.publish("imess/m1/replay", R"({"from": 95, "reply_to": "sub1"})");
  REQUIRE(wait_until([&] { return sub.with([&](auto& ms) { return ms["m1"].replay_answers.size() > answers_before; }); },
                     std::chrono::seconds{5}));
  sub.with([&](auto& ms) {
    const auto& done = ms["m1"].replay_answers.back();
    INFO(done.dump());
    CHECK(done["done"] == true);
    CHECK(done["from"] == 95);
    CHECK(done["count"] == 6);  // 95 … 100
    CHECK(done["hits"] == 6);
    CHECK(done["newest"] == kPerMachine);
    CHECK_FALSE(done.contains("next"));
    return 0;
  });
  sub.publish("imess/m1/replay", R"({"from": 1, "reply_to": "sub1", "goto": [0, 0, 0]})");
  REQUIRE(wait_until([&] { return sub.with([](auto& ms) {
    for (const auto& e : ms["m1"].events)
      if (e.value("type", "") == "request_refused") return e.value("text", "").find("unknown key 'goto'") != std::string::npos;
    return false;
  }); }, std::chrono::seconds{3}));

  // An inspection's result announced on m3 (as messcap inspect does after a run) is its event.
  REQUIRE(cells[2].client->request("Verdict cube-1996 12 1 fail") == std::optional<std::string>("Ok Verdict"));
  const bool inspection_published = wait_until([&] { return sub.with([](auto& ms) {
    for (const auto& e : ms["m3"].events)
      if (e.value("type", "") == "inspection")
        return e.value("plan", "") == "cube-1996" && e.value("in", -1) == 12 && e.value("out", -1) == 1 &&
               e.value("result", "") == "fail" && e.value("machine", "") == "m3";
    return false;
  }); }, std::chrono::seconds{3});
  INFO("m3's events: " << sub.with([](auto& ms) { return nlohmann::json(ms["m3"].events).dump(); }) << "\nm3's bridge: "
                       << cells[2].bridge->err());
  REQUIRE(inspection_published);

  // Retained state: m3 moved by the client "mqtttest", which holds control.
  REQUIRE(cells[2].client->request("GoTo 440 340 90") == std::optional<std::string>("Ok GoTo"));
  REQUIRE(cells[2].client->until([](const std::string& l) { return l == "State idle"; }, 10));
  REQUIRE(wait_until([&] { return sub.with([](auto& ms) {
    const auto& s = ms["m3"].state;
    return s.is_object() && s["position"] == nlohmann::json{440.0, 340.0, 90.0} && s["state"] == "idle";
  }); }, std::chrono::seconds{3}));
  auto fleet = run_program({client_binary("messfleet"), "127.0.0.1:" + std::to_string(broker.port()), "--once", "--json"},
                           std::chrono::seconds{5});
  REQUIRE(fleet.status == 0);
  const auto view = nlohmann::json::parse(fleet.out);
  REQUIRE(view["machines"].size() == 3);
  for (const auto& m : view["machines"]) {
    INFO(m.dump());
    CHECK(m["online"] == true);
    CHECK(m["messd"] == true);
    CHECK(m["state"]["control"] == "mqtttest@127.0.0.1");
    CHECK(m["last_hit"]["seq"] == kPerMachine);
    if (m["machine"] == "m3") {
      CHECK(m["state"]["position"] == nlohmann::json{440.0, 340.0, 90.0});
      CHECK(m["state"]["state"] == "idle");
    } else {
      CHECK(m["state"]["position"] == nlohmann::json{430.0, 330.0, 100.0});
    }
  }

  // A stop on the broker: m1's bridge allows it, m2's does not.
  for (int i : {0, 1}) {
    REQUIRE(cells[static_cast<std::size_t>(i)].client->request("StartMv 0 0 5") == std::optional<std::string>("Ok StartMv"));
  }
  sub.publish("imess/m1/cmd/stop", R"({"reason": "door open", "by": "line PLC"})");
  sub.publish("imess/m2/cmd/stop", R"({"reason": "door open", "by": "line PLC"})");
  CHECK(cells[0].client->until([](const std::string& l) { return l == "State stopping"; }, 3));
  REQUIRE(wait_until([&] { return sub.with([](auto& ms) {
    for (const auto& e : ms["m2"].events)
      if (e.value("type", "") == "stop_ignored") return true;
    return false;
  }); }, std::chrono::seconds{3}));
  CHECK(sub.with([](auto& ms) {
    for (const auto& e : ms["m1"].events)
      if (e.value("type", "") == "stop" && e.value("by", "") == "line PLC") return true;
    return false;
  }));
  // While m2 jogs its position changes every report, and its state goes out at most twice a second.
  const auto jog_from = Clock::now();
  auto states_since = [&](Clock::time_point from) {
    return sub.with([&](auto& ms) {
      std::vector<Clock::time_point> t;
      for (auto at : ms["m2"].state_times)
        if (at >= from) t.push_back(at);
      return t;
    });
  };
  REQUIRE(wait_until([&] { return states_since(jog_from).size() >= 4; }, std::chrono::seconds{4}));
  const auto times = states_since(jog_from);
  for (std::size_t i = 1; i < times.size(); ++i)
    CHECK(times[i] - times[i - 1] >= std::chrono::milliseconds{400});  // 500 ms apart, less the delivery's jitter
  const auto status = cells[1].client->request("Status");
  REQUIRE(status);
  CHECK(status->find("State jog") != std::string::npos);  // m2 still jogs: the broker may not stop it
  CHECK_THAT(cells[1].bridge->err(), Catch::Contains("ignored: this bridge may not stop the machine (mqtt.allow_stop is false)"));
  CHECK(cells[1].client->request("StopMv") == std::optional<std::string>("Ok StopMv"));
  CHECK(cells[0].client->until([](const std::string& l) { return l == "State idle"; }, 5));

  // A stop the broker kept (retained) is no order when a bridge connects later.
  sub.publish("imess/m1/cmd/stop", R"({"reason": "last week's", "by": "someone"})", true);
  cells[0].kill_bridge(SIGTERM);
  REQUIRE(cells[0].client->request("StartMv 0 0 5") == std::optional<std::string>("Ok StartMv"));
  cells[0].start_bridge();
  REQUIRE(wait_until([&] { return cells[0].bridge->err().find("ignored a retained message on imess/m1/cmd/stop") != std::string::npos; },
                     std::chrono::seconds{5}));
  const auto m1_status = cells[0].client->request("Status");
  REQUIRE(m1_status);
  CHECK(m1_status->find("State jog") != std::string::npos);
  CHECK(cells[0].client->request("StopMv") == std::optional<std::string>("Ok StopMv"));
  for (auto& c : cells) c.kill_bridge(SIGTERM);
}

TEST_CASE("messmqtt: a wrong mqtt section stops it at start naming the key, the password is never logged, messd refuses an mqtt that is no object") {
  TempDir dir;
  const auto bad = dir.file("bad.json");
  std::ofstream(bad) << R"({"mqtt": {"machine": "m1", "brokr": "localhost"}})";
  auto r = run_program({client_binary("messmqtt"), "--config", bad});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown key 'mqtt.brokr'; accepted here: broker, machine"));
  // The broker password never reaches the log, whatever goes wrong.
  const auto pw = dir.file("pw");
  std::ofstream(pw) << "s3cret-Pw\n";
  {
    ChildProcess bridge({client_binary("messmqtt"), "--machine", "m9", "--broker", "127.0.0.1:" + std::to_string(free_loopback_port()),
                         "--user", "imess", "--password-file", pw, "--state-file", dir.file("m9.json"),
                         "127.0.0.1:" + std::to_string(free_loopback_port())});
    REQUIRE(wait_until([&] { return bridge.err().find("trying again") != std::string::npos; }, std::chrono::seconds{3}));
    bridge.signal(SIGTERM);
    CHECK(bridge.wait() == 0);
    CHECK_THAT(bridge.err(), Catch::Contains("broker 127.0.0.1:"));
    CHECK(bridge.err().find("s3cret") == std::string::npos);
  }
  const auto wrong = dir.file("wrong.json");
  std::ofstream(wrong) << R"({"mqtt": "localhost"})";
  auto d = run_messd_to_exit({"--config", wrong});
  CHECK(d.status == 2);
  CHECK_THAT(d.err + d.out, Catch::Contains("mqtt"));
}

TEST_CASE("messmqtt: a hit damaged in messd's journal is passed with a hits_lost event, every other one is published") {
  TempDir dir;
  const std::string journal = dir.file("journal");
  std::filesystem::create_directory(journal);
  {
    DaemonProcess messd({"--journal", journal, "--config", fast_cmm()});
    LineClient c(messd.port());
    for (int i = 0; i < 10; ++i) REQUIRE(c.request("ForcePt") == std::optional<std::string>("Ok ForcePt"));
  }
  {  // one byte of hit 5's record changed on disk: its checksum fails
    const std::string path = journal + "/hits-000000000001.jnl";
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("Hit 5 ");
    REQUIRE(at != std::string::npos);
    const auto digit = text.find(" 430.", at) + 2;
    text[digit] = text[digit] == '3' ? '4' : '3';
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  }
  DaemonProcess messd({"--journal", journal, "--config", fast_cmm()});
  Broker broker(dir);
  Subscriber sub(broker.port());
  // No state file yet: the bridge starts at the journal's oldest hit.
  ChildProcess bridge({client_binary("messmqtt"), "--machine", "m7", "--broker", "127.0.0.1:" + std::to_string(broker.port()),
                       "--state-file", dir.file("m7.json"), "127.0.0.1:" + std::to_string(messd.port())});
  REQUIRE(wait_until([&] { return sub.with([](auto& ms) { return ms["m7"].have.size() == 9; }); }, std::chrono::seconds{5}));
  REQUIRE(wait_until([&] { return sub.with([](auto& ms) {
    for (const auto& e : ms["m7"].events)
      if (e.value("type", "") == "hits_lost") return e.value("first", 0) == 5 && e.value("last", 0) == 5;
    return false;
  }); }, std::chrono::seconds{3}));
  sub.with([](auto& ms) {
    CHECK(ms["m7"].have == std::set<std::uint64_t>{1, 2, 3, 4, 6, 7, 8, 9, 10});
    CHECK(ms["m7"].live == std::vector<std::uint64_t>{1, 2, 3, 4, 6, 7, 8, 9, 10});
    return 0;
  });
  // The watermark passes the lost hit: a restarted bridge does not ask for it again.
  REQUIRE(wait_until([&] {
    std::ifstream in(dir.file("m7.json"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return text.find("\"acked\":10") != std::string::npos;
  }, std::chrono::seconds{3}));
  CHECK_THAT(bridge.err(), Catch::Contains("hits 5 to 5 are damaged or missing in messd's journal"));
  bridge.signal(SIGTERM);
  CHECK(bridge.wait() == 0);
}
