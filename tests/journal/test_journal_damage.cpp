// A damaged journal: a record that fails its checksum is named as lost (start-up warning,
// read()'s lost ranges), and a file that does not belong never makes a number be given twice.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "imess/journal/journal.hpp"
#include "journal_dir.hpp"

using namespace imess::journal;
using imess::protocol::HitMsg;
using imess::test::hit_at;

namespace {


std::vector<std::string> fill(const JournalConfig& cfg, int n) {
  Journal j(cfg);
  std::vector<std::string> sent;
  for (int i = 0; i < n; ++i) {
    HitMsg h = hit_at(i);
    sent.push_back(j.append(h));
  }
  return sent;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Changes one byte of the record of hit `seq` in `path` (a digit of its coordinates).
void damage(const std::string& path, std::uint64_t seq) {
  std::string text = read_all(path);
  const auto at = text.find("Hit " + std::to_string(seq) + " ");
  REQUIRE(at != std::string::npos);
  const auto digit = text.find("430.", at) + 1;
  text[digit] = text[digit] == '3' ? '4' : '3';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::string joined(const std::vector<std::string>& v) {
  std::string all;
  for (const auto& s : v) all += s + "\n";
  return all;
}

}  // namespace

TEST_CASE("a damaged record in the middle is named as lost at start and in every read that covers it") {
  imess::test::TempDir dir;
  auto sent = fill({dir.path()}, 10);
  const std::string file = dir.path() + "/hits-000000000001.jnl";
  damage(file, 5);
  Journal j({dir.path()});
  CHECK(j.newest() == 10);
  // The start-up log names it and says where.
  INFO(joined(j.warnings()));
  REQUIRE(j.warnings().size() == 1);
  CHECK_THAT(j.warnings()[0], Catch::Contains("hit 5 ") && Catch::Contains("hits-000000000001.jnl") &&
                                  Catch::Contains("damaged"));
  CHECK_THAT(joined(j.notes()), Catch::Contains("hits 1 to 10 kept, 1 of them lost (5)"));
  REQUIRE(j.lost().size() == 1);
  CHECK(j.lost()[0].first == 5);
  CHECK(j.lost()[0].last == 5);

  auto r = j.read(3, 1000);
  CHECK(r.lines == std::vector<std::string>{sent[2], sent[3], sent[5], sent[6], sent[7], sent[8], sent[9]});
  REQUIRE(r.lost.size() == 1);
  CHECK(r.lost[0].first == 5);
  CHECK(r.lost[0].last == 5);
  CHECK(r.lost[0].before == 2);  // between hit 4 (lines[1]) and hit 6 (lines[2])
  CHECK(r.covered == 8);         // 3 … 10

  auto from_lost = j.read(5, 2);  // the start itself is lost; capped at two hits
  CHECK(from_lost.lines == std::vector<std::string>{sent[5], sent[6]});
  REQUIRE(from_lost.lost.size() == 1);
  CHECK(from_lost.lost[0].before == 0);
  CHECK(from_lost.covered == 3);  // 5 … 7

  auto after = j.read(6, 1000);
  CHECK(after.lost.empty());
  CHECK(after.covered == 5);

  HitMsg h = hit_at(1);
  j.append(h);
  CHECK(h.seq == 11);
}

TEST_CASE("records lost at the end of a rotated file and a wholly damaged file are named as ranges") {
  imess::test::TempDir dir;
  JournalConfig cfg{dir.path()};
  cfg.max_bytes = 400;  // four records per file
  cfg.files = 8;
  auto sent = fill(cfg, 16);
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() == 4);  // 1-4, 5-8, 9-12, 13-16
  damage(files[0], 4);         // the last of the first file
  std::ofstream(files[1], std::ios::binary | std::ios::trunc) << std::string(200, 'x') << "\n";
  Journal j(cfg);
  CHECK(j.newest() == 16);
  REQUIRE(j.lost().size() == 1);  // 4 and 5 … 8 together
  CHECK(j.lost()[0].first == 4);
  CHECK(j.lost()[0].last == 8);
  CHECK_THAT(joined(j.warnings()), Catch::Contains("hits 4 to 8 "));
  auto r = j.read(1, 1000);
  CHECK(r.lines.size() == 11);
  REQUIRE(r.lost.size() == 1);
  CHECK(r.lost[0].first == 4);
  CHECK(r.lost[0].last == 8);
  CHECK(r.lost[0].before == 3);
  CHECK(r.covered == 16);
}

TEST_CASE("a stray journal file that would make numbers be given again stops start-up naming it") {
  imess::test::TempDir dir;
  fill({dir.path()}, 30);
  const std::string stray = dir.path() + "/hits-000000000005.jnl";
  SECTION("garbage") { std::ofstream(stray) << "garbage\nmore garbage\n"; }
  SECTION("empty") { std::ofstream{stray}; }
  SECTION("a copy of another journal's hits") {
    std::ofstream(stray) << read_all(dir.path() + "/hits-000000000001.jnl");
  }
  try {
    Journal j({dir.path()});
    FAIL("started; the next hit would be " << j.newest() + 1);
  } catch (const JournalError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK_THAT(what, Catch::Contains("'" + stray + "'") && Catch::Contains("hits-000000000001.jnl") &&
                         Catch::Contains("30") && Catch::Contains("move it out of"));
  }
  CHECK(read_all(dir.path() + "/hits-000000000001.jnl").size() > 0);  // nothing cut or deleted
}

TEST_CASE("a file whose hits are not the numbers its name gives stops start-up") {
  imess::test::TempDir dir;
  fill({dir.path()}, 3);
  std::filesystem::rename(dir.path() + "/hits-000000000001.jnl", dir.path() + "/hits-000000000002.jnl");
  try {
    Journal j({dir.path()});
    FAIL("started");
  } catch (const JournalError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("hits-000000000002.jnl") && Catch::Contains("holds hit 1"));
  }
}
