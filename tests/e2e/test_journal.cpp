// The hit journal through the protocol: Hit before every MeasPt (which stays byte-exact),
// Replay of exactly the live lines, numbering across restarts, rotation, the per-request cap.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "imess/protocol/messages.hpp"

using namespace imess::test;
namespace p = imess::protocol;

namespace {

// Sends n ForcePt in batches the command ring takes, waits for every reply; returns the Hit lines.
std::vector<std::string> force_points(LineClient& c, int n) {
  std::vector<std::string> hits;
  for (int done = 0; done < n;) {
    int batch = std::min(30, n - done);  // within the per-client in-flight cap (32)
    for (int i = 0; i < batch; ++i) c.send("ForcePt");
    int replies = 0;
    REQUIRE(c.until(
        [&](const std::string& l) {
          if (l.rfind("Hit ", 0) == 0) hits.push_back(l);
          if (l == "Ok ForcePt") ++replies;
          else if (l.rfind("Err", 0) == 0) FAIL(l);
          return replies == batch;
        },
        20.0));
    done += batch;
  }
  return hits;
}

// Replay from `from`: the Hit lines before the Ok, and the Ok line.
std::pair<std::vector<std::string>, std::string> replay(LineClient& c, std::uint64_t from) {
  c.send("Replay " + std::to_string(from));
  std::vector<std::string> lines;
  std::string ok;
  REQUIRE(c.until(
      [&](const std::string& l) {
        if (l.rfind("Hit ", 0) == 0) lines.push_back(l);
        if (l.rfind("Ok Replay", 0) == 0 || l.rfind("Err", 0) == 0) ok = l;
        return !ok.empty();
      },
      10.0));
  return {lines, ok};
}

std::string temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("imess-test-" + std::to_string(getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

}  // namespace

TEST_CASE("every point comes as Hit, then the unchanged MeasPt - Replay gives the same Hit lines") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.request("StartMv 0 0 -20") == std::optional<std::string>("Ok StartMv"));
  auto hit = c.until_prefix("Hit ", 10.0);
  REQUIRE(hit);
  CHECK(c.next() == std::optional<std::string>("MeasPt 430.000 330.000 80.000"));
  auto m = p::parse_message(*hit);
  REQUIRE(std::holds_alternative<p::HitMsg>(m));
  auto h = std::get<p::HitMsg>(m);
  CHECK(h.seq == 1);
  CHECK(h.id == 0);
  CHECK(h.p == p::Xyz{430, 330, 80});
  CHECK(h.dir == p::Xyz{0, 0, -1});
  CHECK(h.radius == 2.0);
  CHECK(h.time > 0);
  REQUIRE(c.until_prefix("State idle", 5.0));
  // ForcePt: marked by no direction and no radius.
  c.send("ForcePt");
  auto forced = c.until_prefix("Hit ", 5.0);
  REQUIRE(forced);
  auto f = std::get<p::HitMsg>(p::parse_message(*forced));
  auto measpt = c.next();  // right after its Hit; the same point to 3 decimals
  REQUIRE(measpt);
  auto mp = p::parse_message(*measpt);
  REQUIRE(std::holds_alternative<p::MeasPtMsg>(mp));
  CHECK(std::abs(std::get<p::MeasPtMsg>(mp).p.z - f.p.z) <= 0.00051);
  CHECK(f.p.z == Approx(82.5).margin(0.01));
  CHECK(f.seq == 2);
  CHECK(f.dir == p::Xyz{0, 0, 0});
  CHECK(f.radius == 0);
  CHECK(f.time > h.time);

  auto [lines, ok] = replay(c, 1);
  CHECK(lines == std::vector<std::string>{*hit, *forced});
  CHECK(ok == "Ok Replay 2 2");
  auto [none, ok_none] = replay(c, 3);
  CHECK(none.empty());
  CHECK(ok_none == "Ok Replay 0 2");
  // Replay goes to the asker only.
  LineClient other(messd.port());
  REQUIRE(other.next());  // CurrCor
  replay(c, 1);
  CHECK_FALSE(other.until_prefix("Hit ", 0.5));
}

TEST_CASE("the numbering continues after a restart, also after kill -9") {
  auto dir = temp_dir("journal-restart");
  std::vector<std::string> before;
  {
    DaemonProcess messd({"--journal", dir});
    LineClient c(messd.port());
    before = force_points(c, 3);
    messd.stop(SIGKILL);
  }
  DaemonProcess messd({"--journal", dir});
  LineClient c(messd.port());
  auto after = force_points(c, 1);
  REQUIRE(after.size() == 1);
  CHECK(std::get<p::HitMsg>(p::parse_message(after[0])).seq == 4);
  auto [lines, ok] = replay(c, 0);
  CHECK(ok == "Ok Replay 4 4");
  before.push_back(after[0]);
  CHECK(lines == before);
  std::filesystem::remove_all(dir);
}

TEST_CASE("rotated-away hits are Err 212 naming the oldest kept - a big Replay is capped at 1000") {
  auto dir = temp_dir("journal-rotate");
  std::filesystem::create_directories(dir);
  const std::string config = dir + "/small-journal.json";
  std::ofstream(config) << R"({"journal": {"dir": ")" << dir << R"(/j", "max_bytes": 8192, "files": 3}})";
  DaemonProcess messd({"--config", config, "--journal", dir + "/j"});
  LineClient c(messd.port());
  auto hits = force_points(c, 1005);
  REQUIRE(hits.size() == 1005);
  auto [gone, err] = replay(c, 1);
  CHECK(gone.empty());
  REQUIRE(err.rfind("Err 212 hit 1 is no longer in the journal; the oldest kept is ", 0) == 0);
  const auto oldest = std::stoull(err.substr(err.rfind(' ') + 1));
  CHECK(oldest > 700);  // 3 files of 8 KiB hold about 170 to 260 hits
  CHECK(oldest < 1005);
  auto [kept, ok] = replay(c, oldest);
  CHECK(ok == "Ok Replay " + std::to_string(1005 - oldest + 1) + " 1005");
  CHECK(kept == std::vector<std::string>(hits.begin() + static_cast<long>(oldest - 1), hits.end()));
  std::filesystem::remove_all(dir);
}

TEST_CASE("Replay sends at most 1000 hits per request - the client asks again") {
  DaemonProcess messd;
  LineClient c(messd.port());
  auto hits = force_points(c, 1003);
  auto [first, ok] = replay(c, 1);
  CHECK(ok == "Ok Replay 1000 1003");
  CHECK(first == std::vector<std::string>(hits.begin(), hits.begin() + 1000));
  auto [rest, ok2] = replay(c, 1001);
  CHECK(ok2 == "Ok Replay 3 1003");
  CHECK(rest == std::vector<std::string>(hits.begin() + 1000, hits.end()));
}

TEST_CASE("a hand hit is journaled with its push direction and the tip radius") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.request("GoTo 430 330 90") == std::optional<std::string>("Ok GoTo"));
  REQUIRE(c.until_prefix("State idle", 5.0));
  REQUIRE(c.request("Free") == std::optional<std::string>("Ok Free"));
  REQUIRE(c.request("HandMv 3 4 -9 10") == std::optional<std::string>("Ok HandMv"));
  auto line = c.until_prefix("Hit ", 5.0);
  REQUIRE(line);
  auto h = std::get<p::HitMsg>(p::parse_message(*line));
  CHECK(h.id == 0);
  CHECK(h.radius == 2.0);
  const double n = std::sqrt(106.0);
  CHECK(h.dir.x == Approx(3 / n).margin(1e-3));
  CHECK(h.dir.y == Approx(4 / n).margin(1e-3));
  CHECK(h.dir.z == Approx(-9 / n).margin(1e-3));
  CHECK(c.next()->rfind("MeasPt ", 0) == 0);
}

TEST_CASE("messcap --append against messd fetches the hits measured while it was not running") {
  TempDir dir;
  const std::string xyz = dir.file("part.xyz");
  DaemonProcess messd;
  const std::string where = "127.0.0.1:" + std::to_string(messd.port());
  LineClient c(messd.port());
  {
    ChildProcess cap({client_binary("messcap"), where, "-n", "2", "-o", xyz});
    for (auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
         cap.err().find("connected to") == std::string::npos;) {
      REQUIRE(std::chrono::steady_clock::now() < until);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    force_points(c, 2);
    REQUIRE(cap.wait() == 0);
  }
  auto missed = force_points(c, 3);  // nobody capturing
  auto r = run_program({client_binary("messcap"), where, "-n", "3", "-o", xyz, "--append"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  std::ifstream in(xyz);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  REQUIRE(lines.size() == 5);
  for (int i = 0; i < 5; ++i) CHECK(lines[i].substr(lines[i].rfind('#')) == "# hit " + std::to_string(i + 1));
  CHECK_THAT(r.err, Catch::Contains("continuing after hit 2"));
}

// Changes one byte of hit `seq`'s record in the journal file at `path` (its checksum then fails).
static void damage_record(const std::string& path, std::uint64_t seq) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("Hit " + std::to_string(seq) + " ");
  REQUIRE(at != std::string::npos);
  const auto digit = text.find(" 430.", at) + 2;
  text[digit] = text[digit] == '3' ? '4' : '3';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

TEST_CASE("a damaged record in the journal is named in Replay's answer as Replay Lost and counted") {
  auto dir = temp_dir("journal-damaged");
  std::vector<std::string> hits;
  {
    DaemonProcess messd({"--journal", dir});
    LineClient c(messd.port());
    hits = force_points(c, 10);
  }
  damage_record(dir + "/hits-000000000001.jnl", 5);
  DaemonProcess messd({"--journal", dir});
  LineClient c(messd.port());
  c.send("Replay 3");
  std::vector<std::string> lines;
  REQUIRE(c.until(
      [&](const std::string& l) {
        if (l.rfind("Hit ", 0) == 0 || l.rfind("Replay ", 0) == 0 || l.rfind("Ok Replay", 0) == 0) lines.push_back(l);
        return l.rfind("Ok Replay", 0) == 0 || l.rfind("Err", 0) == 0;
      },
      10.0));
  std::vector<std::string> want{hits[2], hits[3], "Replay Lost 5 5 damaged or missing in the journal"};
  want.insert(want.end(), hits.begin() + 5, hits.end());
  want.push_back("Ok Replay 8 10");  // 3 … 10: seven hits and one named lost
  CHECK(lines == want);
  auto lost = p::parse_message("Replay Lost 5 5 damaged or missing in the journal");
  REQUIRE(std::holds_alternative<p::DataMsg>(lost));
  auto range = p::parse_replay_lost(std::get<p::DataMsg>(lost).text);
  REQUIRE(range);
  CHECK(range->first == 5);
  CHECK(range->last == 5);
  // Align names it too, rather than "not in the journal".
  auto align = c.request("Align cube 321 1-3 4,5 6");
  REQUIRE(align);
  CHECK(*align == "Err 105 Align cube: hit 5 of the line is lost: its record in the journal is damaged or missing; "
                  "measure the point again and use its new number");
  // New hits continue after the newest, never reusing 5.
  auto next = force_points(c, 1);
  REQUIRE(next.size() == 1);
  CHECK(std::get<p::HitMsg>(p::parse_message(next[0])).seq == 11);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a stray journal file that would restart the numbering stops messd with exit 2 naming it") {
  auto dir = temp_dir("journal-stray");
  {
    DaemonProcess messd({"--journal", dir});
    LineClient c(messd.port());
    force_points(c, 12);
  }
  std::ofstream(dir + "/hits-000000000005.jnl") << "garbage\n";
  auto r = run_messd_to_exit({"--journal", dir});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(dir + "/hits-000000000005.jnl") && Catch::Contains("holds hits up to 12") &&
                        Catch::Contains("move it out of"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("messcap -o FILE.csv killed with SIGKILL and started again with --append keeps every point") {
  TempDir dir;
  const std::string csv = dir.file("pts.csv");
  DaemonProcess messd;
  const std::string where = "127.0.0.1:" + std::to_string(messd.port());
  LineClient c(messd.port());
  {
    ChildProcess cap({client_binary("messcap"), where, "-o", csv});
    for (auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
         cap.err().find("connected to") == std::string::npos;) {
      REQUIRE(std::chrono::steady_clock::now() < until);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    force_points(c, 5);
    REQUIRE(cap.wait_for_output("point 5:"));
    cap.signal(SIGKILL);
    cap.wait();
  }
  force_points(c, 5);  // measured while nobody captures
  auto r = run_program({client_binary("messcap"), where, "-n", "5", "-o", csv, "--append"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("continuing after hit 5"));
  std::ifstream in(csv);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  REQUIRE(lines.size() == 11);
  CHECK(lines[0] == "hit,x,y,z,scan");
  for (int i = 1; i <= 10; ++i) CHECK(lines[i].rfind(std::to_string(i) + ",430.000,330.000,", 0) == 0);
}

TEST_CASE("messcap --append over a damaged journal record reports the lost hit and keeps all the others") {
  auto dir = temp_dir("journal-damaged-messcap");
  {
    DaemonProcess messd({"--journal", dir});
    LineClient c(messd.port());
    force_points(c, 10);
  }
  damage_record(dir + "/hits-000000000001.jnl", 5);
  TempDir out;
  const std::string csv = out.file("pts.csv");
  std::ofstream(csv) << "hit,x,y,z\n1,430.000,330.000,100.000\n2,430.000,330.000,100.000\n";
  DaemonProcess messd({"--journal", dir});
  const std::string where = "127.0.0.1:" + std::to_string(messd.port());
  auto r = run_program({client_binary("messcap"), where, "-n", "7", "-o", csv, "--append"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("hit 5 is missing: its record in messd's journal is damaged or missing"));
  CHECK_THAT(r.err, Catch::Contains("7 points written") && Catch::Contains("hit 5 missing"));
  std::ifstream in(csv);
  std::vector<std::string> numbers;
  for (std::string l; std::getline(in, l);) numbers.push_back(l.substr(0, l.find(',')));
  CHECK(numbers == std::vector<std::string>{"hit", "1", "2", "3", "4", "6", "7", "8", "9", "10"});
  std::filesystem::remove_all(dir);
}
