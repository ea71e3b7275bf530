// messcap captures scans from the real messd on a simulated CMM with a measuring probe
// (tests/e2e/scan-cmm.json): every Scan point into every kind of file, marked as a scan's and
// numbered by the journal; and a capture killed with SIGKILL in the middle of a 16 000-point
// scan, continued with --append, holds every number the journal gave the scan exactly once.
#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <regex>
#include <thread>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "daemon_process.hpp"

using namespace imess::test;

namespace {

std::string scan_config() { return std::string(IMESS_SOURCE_DIR) + "/tests/e2e/scan-cmm.json"; }

// The numbers (seq) of the Scan lines of scan `id` among `lines`, in the order sent.
std::vector<std::uint64_t> scan_numbers(const std::vector<std::string>& lines, int id) {
  std::vector<std::uint64_t> seqs;
  const std::string want = " " + std::to_string(id) + " ";
  for (const auto& l : lines) {
    if (l.rfind("Scan ", 0) != 0) continue;
    const auto sp = l.find(' ', 5);
    if (l.compare(sp, want.size(), want) == 0) seqs.push_back(std::stoull(l.substr(5, sp - 5)));
  }
  return seqs;
}

// Over the bore (the worked example's Ø 30 at 460 350) and down into it, 20 mm below the top.
void into_the_bore(LineClient& c) {
  REQUIRE(c.request("Take") == "Ok Take");
  c.send("MoveTo 1 X460 Y350 Z100");
  c.send("MoveTo 2 X460 Y350 Z60");
  REQUIRE(c.until_prefix("Done 2", 20.0));
}

// Reads the lines of scan `id` until its Done (every line kept for scan_numbers), calling
// `on_point(count)` after each Scan line.
std::vector<std::string> until_scan_done(LineClient& c, int id, const std::function<void(int)>& on_point, double timeout_s) {
  std::vector<std::string> lines;
  const std::string done = "Done " + std::to_string(id), failed = "Failed " + std::to_string(id);
  int points = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    REQUIRE(std::chrono::steady_clock::now() < deadline);
    auto l = c.next(1.0);
    if (!l) continue;
    if (l->rfind("Scan ", 0) == 0) {
      lines.push_back(*l);
      on_point(++points);
    }
    INFO(*l);
    REQUIRE(l->rfind(failed, 0) != 0);
    if (*l == done) return lines;
  }
}

// The `# hit N` numbers of a line-format capture file, in file order, with the lines' scan ids.
struct FileNumbers {
  std::vector<std::uint64_t> seqs;
  std::vector<std::string> scans;  // "" for a hit's line
};
FileNumbers numbers_in(const std::string& text) {
  FileNumbers n;
  static const std::regex comment(R"(# hit (\d+)( scan (\d+))?$)");
  std::size_t at = 0;
  while (at < text.size()) {
    const auto end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    std::smatch m;
    if (std::regex_search(line, m, comment)) {
      n.seqs.push_back(std::stoull(m[1]));
      n.scans.push_back(m[3]);
    }
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return n;
}

// Waits until the capture file holds `text` (messcap writes what reached it).
bool file_gets(const std::string& path, const std::string& text, std::chrono::milliseconds timeout = 5s) {
  for (auto until = std::chrono::steady_clock::now() + timeout; std::chrono::steady_clock::now() < until;) {
    if (file_exists(path) && read_file(path).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(20ms);
  }
  return false;
}

// A capture started and connected (its start probe sent), before anything is measured.
std::unique_ptr<ChildProcess> capture(int port, std::vector<std::string> extra) {
  std::vector<std::string> argv{client_binary("messcap"), "127.0.0.1:" + std::to_string(port)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  auto cap = std::make_unique<ChildProcess>(argv);
  for (auto until = std::chrono::steady_clock::now() + 5s; cap->err().find("connected to") == std::string::npos;) {
    REQUIRE(std::chrono::steady_clock::now() < until);
    std::this_thread::sleep_for(10ms);
  }
  std::this_thread::sleep_for(100ms);  // its Replay probe answered
  return cap;
}

}  // namespace

TEST_CASE("messcap captures a touch and a bore scan into .hits, .csv, .xyz and .json: every point once, a scan's marked") {
  DaemonProcess messd({"--config", scan_config()});
  TempDir dir;
  LineClient c(messd.port());
  REQUIRE(c.next());  // CurrCor: connected
  std::vector<std::unique_ptr<ChildProcess>> caps;
  for (const char* name : {"all.hits", "all.csv", "all.xyz", "all.json"})
    caps.push_back(capture(messd.port(), {"-o", dir.file(name)}));

  // One touch on the top beside the bore (a Hit), then a full turn of the bore (Scan lines).
  REQUIRE(c.request("Take") == "Ok Take");
  c.send("MoveTo 3 X430 Y330 Z90");
  c.send("Probe 4 X430 Y330 Z81 F20");  // 1 mm past the contact (the ball centre at z 82)
  const auto hit = c.until_prefix("Hit ");
  REQUIRE(hit);
  REQUIRE(c.until_prefix("Done 4", 20.0));
  const std::uint64_t hit_seq = std::stoull(hit->substr(4, hit->find(' ', 4) - 4));
  c.send("MoveTo 5 X460 Y350 Z100");
  c.send("MoveTo 6 X460 Y350 Z60");
  REQUIRE(c.until_prefix("Done 6", 20.0));
  c.send("ScanCirc 7 460 350 60 475 350 60 0 0 1 360 bore 20");
  const auto seqs = scan_numbers(until_scan_done(c, 7, [](int) {}, 20.0), 7);
  REQUIRE(seqs.size() > 800);  // a full turn of the bore, a point every 0.1 mm
  const std::string last = "# hit " + std::to_string(seqs.back()) + " scan 7";
  REQUIRE(file_gets(dir.file("all.xyz"), last));
  REQUIRE(file_gets(dir.file("all.hits"), last));
  REQUIRE(file_gets(dir.file("all.csv"), "\n" + std::to_string(seqs.back()) + ","));
  for (auto& cap : caps) {
    cap->signal(SIGINT);
    CHECK(cap->wait() == 0);
  }
  std::vector<std::uint64_t> expected{hit_seq};
  expected.insert(expected.end(), seqs.begin(), seqs.end());

  // .hits and .xyz: the touch as "# hit N", each scan point as "# hit N scan 7", in sequence.
  for (const char* name : {"all.hits", "all.xyz"}) {
    INFO(name);
    const auto n = numbers_in(read_file(dir.file(name)));
    CHECK(n.seqs == expected);
    REQUIRE(n.scans.size() == expected.size());
    CHECK(n.scans.front().empty());
    CHECK(std::count(n.scans.begin(), n.scans.end(), "7") == static_cast<long>(seqs.size()));
  }
  // .hits keeps each scan point's direction and tip radius, so the fit of the scan's lines
  // (the touch on the top left out) is the bore itself.
  std::string bore_only;
  std::istringstream hits(read_file(dir.file("all.hits")));
  for (std::string l; std::getline(hits, l);)
    if (l.find(" scan 7") != std::string::npos) bore_only += l + "\n";
  std::ofstream(dir.file("bore.hits")) << bore_only;
  const auto bore = run_program({client_binary("messcap"), "fit", "circle", dir.file("bore.hits")});
  INFO(bore.err);
  REQUIRE(bore.status == 0);
  const auto j = nlohmann::json::parse(bore.out);
  CHECK(j["diameter"].get<double>() == Approx(30.0).margin(0.0005));
  CHECK(j["center"][0].get<double>() == Approx(460.0).margin(0.0005));
  CHECK(j["center"][1].get<double>() == Approx(350.0).margin(0.0005));

  // .csv: the scan's id in the last column (empty for the touch).
  const std::string csv = read_file(dir.file("all.csv"));
  CHECK(csv.rfind("hit,x,y,z,scan\n" + std::to_string(hit_seq) + ",430.000,330.000,80.000,\n", 0) == 0);
  std::istringstream rows(csv);
  std::string row;
  std::getline(rows, row);
  std::vector<std::uint64_t> csv_seqs;
  int scan_rows = 0;
  while (std::getline(rows, row)) {
    csv_seqs.push_back(std::stoull(row.substr(0, row.find(','))));
    scan_rows += row.size() > 2 && row.compare(row.size() - 2, 2, ",7") == 0;
  }
  CHECK(csv_seqs == expected);
  CHECK(scan_rows == static_cast<int>(seqs.size()));
  // messcap reads its own .csv back without the hit and scan columns.
  const auto csv_fit = run_program({client_binary("messcap"), "fit", "plane", dir.file("all.csv")});
  INFO(csv_fit.err);
  CHECK(csv_fit.status == 0);

  // .json, written whole: every point.
  const auto doc = nlohmann::json::parse(read_file(dir.file("all.json")));
  INFO(doc.dump().substr(0, 300));
  CHECK(doc["points"].size() == expected.size());
}

TEST_CASE("messcap killed (SIGKILL) in the middle of a 16 000-point scan and started again with --append loses no point") {
  DaemonProcess messd({"--config", scan_config()});
  TempDir dir;
  const std::string file = dir.file("scan.xyz");
  LineClient c(messd.port());
  REQUIRE(c.next());
  auto cap = capture(messd.port(), {"-o", file});
  into_the_bore(c);
  REQUIRE(c.request("Set ScanStep 0.01") == "Ok Set");
  // Twice round the bore at 10 mm/s, a point every 0.01 mm: every cycle of the loop one.
  c.send("ScanCirc 3 460 350 60 475 350 60 0 0 1 720 bore 10");
  const auto start = std::chrono::steady_clock::now();
  std::chrono::duration<double> away{};
  const auto lines = until_scan_done(
      c, 3,
      [&](int n) {
        if (n != 5000) return;
        const auto t = std::chrono::steady_clock::now();
        cap->signal(SIGKILL);
        REQUIRE(cap->wait() == 128 + SIGKILL);
        // As if the kill had come in the middle of a write: a line without its end.
        std::ofstream(file, std::ios::app) << "474.998 350.0";
        cap = capture(messd.port(), {"-o", file, "--append"});
        away = std::chrono::steady_clock::now() - t;
      },
      30.0);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  const auto seqs = scan_numbers(lines, 3);
  REQUIRE(seqs.size() >= 10000);
  WARN(seqs.size() << " points in " << took.count() << " s; the capture was away " << away.count() << " s");
  REQUIRE(file_gets(file, "# hit " + std::to_string(seqs.back()) + " scan 3"));
  cap->signal(SIGINT);
  CHECK(cap->wait() == 0);
  CHECK_THAT(cap->err(), Catch::Contains("continuing after hit") &&
                            Catch::Contains("cut the unfinished last line off " + file + " ('474.998 350.0'"));
  const auto n = numbers_in(read_file(file));
  CHECK(n.seqs.size() == seqs.size());
  CHECK(n.seqs == seqs);  // every number once, in order
  CHECK(std::count(n.scans.begin(), n.scans.end(), "3") == static_cast<long>(seqs.size()));
}
