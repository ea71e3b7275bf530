// The journal: numbering that survives restarts, torn ends cut off, rotation by size, reading
// back exactly what was sent live, and a clear error for a directory it cannot use.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "imess/journal/journal.hpp"
#include "journal_dir.hpp"

using namespace imess::journal;
using imess::protocol::HitMsg;
using imess::test::hit_at;

namespace {


std::vector<std::filesystem::path> files_in(const std::string& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void append_bytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::app | std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("hits are numbered from 1 and read back exactly as they were sent") {
  imess::test::TempDir dir;
  Journal j({dir.path()});
  CHECK(j.newest() == 0);
  std::vector<std::string> sent;
  for (int i = 0; i < 5; ++i) {
    HitMsg h = hit_at(80 - i);
    sent.push_back(j.append(h));
    CHECK(h.seq == static_cast<std::uint64_t>(i + 1));
  }
  CHECK(sent[0] == "Hit 1 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 17.250000\n");
  auto all = j.read(0, 100);
  CHECK(all.lines == sent);
  CHECK(all.newest == 5);
  auto part = j.read(3, 2);
  CHECK(part.lines == std::vector<std::string>{sent[2], sent[3]});
  CHECK(j.read(6, 100).lines.empty());
  CHECK(j.read(99, 100).lines.empty());
}

TEST_CASE("numbering survives a restart") {
  imess::test::TempDir dir;
  {
    Journal j({dir.path()});
    for (int i = 0; i < 3; ++i) {
      HitMsg h = hit_at(i);
      j.append(h);
    }
  }
  Journal again({dir.path()});
  CHECK(again.newest() == 3);
  HitMsg h = hit_at(9);
  again.append(h);
  CHECK(h.seq == 4);
  CHECK(again.read(1, 10).lines.size() == 4);
}

TEST_CASE("a torn last record from a crash is detected, cut off and its number given again") {
  imess::test::TempDir dir;
  std::string third;
  {
    Journal j({dir.path()});
    for (int i = 0; i < 2; ++i) {
      HitMsg h = hit_at(i);
      j.append(h);
    }
  }
  auto file = files_in(dir.path()).at(0);
  const auto intact = std::filesystem::file_size(file);
  SECTION("a line without its end") { append_bytes(file, "Hit 3 0 430.0000 330.00"); }
  SECTION("a whole line with a wrong checksum") {
    append_bytes(file, "Hit 3 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 1.000000 *00000000\n");
  }
  SECTION("zeros after a power cut") { append_bytes(file, std::string(300, '\0')); }
  Journal j({dir.path()});
  CHECK(j.newest() == 2);
  CHECK(std::filesystem::file_size(file) == intact);
  bool noted = false;
  for (const auto& n : j.notes()) noted |= n.find("torn") != std::string::npos;
  CHECK(noted);
  HitMsg h = hit_at(7);
  std::string line = j.append(h);
  CHECK(h.seq == 3);
  auto all = j.read(1, 10).lines;
  REQUIRE(all.size() == 3);
  CHECK(all[2] == line);
}

TEST_CASE("files rotate by size, the oldest are deleted, and Replay across files is gap-free") {
  imess::test::TempDir dir;
  JournalConfig cfg{dir.path()};
  cfg.max_bytes = 400;  // about four records per file
  cfg.files = 3;
  std::vector<std::string> sent;
  {
    Journal j(cfg);
    for (int i = 0; i < 40; ++i) {
      HitMsg h = hit_at(i);
      sent.push_back(j.append(h));
    }
    CHECK(files_in(dir.path()).size() == 3);
    for (const auto& f : files_in(dir.path())) CHECK(std::filesystem::file_size(f) <= 400);
    const auto oldest = j.oldest();
    CHECK(oldest > 1);
    CHECK(oldest < 40);
    auto gone = j.read(1, 100);
    CHECK(gone.rotated_away);
    CHECK(gone.oldest == oldest);
    CHECK(gone.lines.empty());
    auto kept = j.read(oldest, 100);
    CHECK_FALSE(kept.rotated_away);
    CHECK(kept.lines == std::vector<std::string>(sent.begin() + static_cast<long>(oldest - 1), sent.end()));
    // From the middle of a later file, capped.
    auto some = j.read(38, 2);
    CHECK(some.lines == std::vector<std::string>{sent[37], sent[38]});
  }
  Journal again(cfg);
  CHECK(again.newest() == 40);
}

TEST_CASE("a new file begun just before a crash, still empty, continues the numbering") {
  imess::test::TempDir dir;
  {
    Journal j({dir.path()});
    for (int i = 0; i < 4; ++i) {
      HitMsg h = hit_at(i);
      j.append(h);
    }
  }
  std::ofstream(dir.path() + "/hits-000000000005.jnl");
  Journal j({dir.path()});
  CHECK(j.newest() == 4);
  HitMsg h = hit_at(1);
  j.append(h);
  CHECK(h.seq == 5);
  CHECK(j.read(1, 10).lines.size() == 5);
}

TEST_CASE("every hit is written before append returns, synced by interval") {
  imess::test::TempDir dir;
  JournalConfig cfg{dir.path()};
  cfg.fsync_interval = std::chrono::milliseconds(0);  // every hit: on disk when append returns
  Journal j(cfg);
  HitMsg h = hit_at(1);
  std::string line = j.append(h);
  std::ifstream in(files_in(dir.path()).at(0));
  std::string got;
  std::getline(in, got);
  CHECK(got.rfind(line.substr(0, line.size() - 1) + " *", 0) == 0);
}

TEST_CASE("a directory that cannot be created is a clear error") {
  imess::test::TempDir dir;
  std::ofstream(dir.path() + "/plain-file") << "x";
  try {
    Journal j({dir.path() + "/plain-file/journal"});
    FAIL("no error");
  } catch (const JournalError& e) {
    std::string what = e.what();
    CHECK(what.find("cannot create the journal directory '" + dir.path() + "/plain-file/journal'") != std::string::npos);
    CHECK(what.find("--journal DIR") != std::string::npos);
  }
}
