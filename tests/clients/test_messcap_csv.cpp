// messcap's .csv keeps each hit's number (`hit,x,y,z`), so --append resumes from messd's
// journal as for .xyz; an old `x,y,z` file is refused for --append, never continued with a gap;
// hits messd names lost (`Replay Lost`) are reported, not skipped in silence.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "child_process.hpp"
#include "fake_daemon.hpp"

using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::FakeDaemonScript;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;

namespace {

std::string hit(int seq, double x, double y, double z) {
  char line[160];
  std::snprintf(line, sizeof line, "Hit %d 0 %.4f %.4f %.4f 0.000000 0.000000 -1.000000 2.0000 %d.000000", seq, x, y,
                z, seq);
  return line;
}

// A messd whose journal holds hits 1 … 5 with 4 damaged; it sends 1 and 2 live to a new
// capture, and replays from 3 on when asked.
FakeDaemonScript journal_with_a_lost_hit() {
  return {0, {"CurrCor 0.000 0.000 0.000"}, [](const std::string& line) -> std::vector<std::string> {
            if (line == "Replay 3")
              return {hit(3, 10, 0, 80), "Replay Lost 4 4 damaged or missing in the journal", hit(5, 10, 10, 80),
                      "Ok Replay 3 5"};
            if (line.rfind("Replay ", 0) == 0)  // a new capture's probe: where the journal ends
              return {"Ok Replay 0 0", hit(1, 0, 0, 80), "MeasPt 0.000 0.000 80.000", hit(2, 0, 10, 80),
                      "MeasPt 0.000 10.000 80.000"};
            return {};
          }};
}

}  // namespace

TEST_CASE("messcap -o FILE.csv writes a hit column, and --append resumes after its last hit, naming a lost one") {
  TempDir dir;
  const auto csv = dir.file("pts.csv");
  FakeDaemon daemon(journal_with_a_lost_hit());
  auto first = run_program({client_binary("messcap"), daemon.address(), "-n", "2", "-o", csv});
  INFO(first.err);
  REQUIRE(first.status == 0);
  CHECK(read_file(csv) == "hit,x,y,z,scan\n1,0.000,0.000,80.000,\n2,0.000,10.000,80.000,\n");

  auto again = run_program({client_binary("messcap"), daemon.address(), "-n", "2", "-o", csv, "--append"});
  INFO(again.err);
  REQUIRE(again.status == 0);
  CHECK_THAT(again.err, Catch::Contains("continuing after hit 2"));
  CHECK_THAT(again.err, Catch::Contains("hit 4 is missing: its record in messd's journal is damaged or missing"));
  CHECK_THAT(again.err, Catch::Contains("2 points written") && Catch::Contains("hit 4 missing"));
  CHECK(read_file(csv) ==
        "hit,x,y,z,scan\n1,0.000,0.000,80.000,\n2,0.000,10.000,80.000,\n3,10.000,0.000,80.000,\n5,10.000,10.000,80.000,\n");

  // The readers of CSV take the hit column as what it is, not as x.
  auto fit = run_program({client_binary("messcap"), "fit", "plane", csv});
  INFO(fit.err);
  REQUIRE(fit.status == 0);
  CHECK_THAT(fit.out, Catch::Contains("\"n\":4"));
  auto converted = run_program({client_binary("messcap"), "convert", csv, dir.file("pts.xyz"), "--decimals", "3"});
  REQUIRE(converted.status == 0);
  CHECK(read_file(dir.file("pts.xyz")) ==
        "0.000 0.000 80.000\n0.000 10.000 80.000\n10.000 0.000 80.000\n10.000 10.000 80.000\n");
}

TEST_CASE("messcap --append to a CSV without a hit column is refused, saying which files can be continued") {
  TempDir dir;
  const auto csv = dir.file("old.csv");
  std::ofstream(csv) << "x,y,z\n1.000,2.000,3.000\n";
  FakeDaemon daemon(journal_with_a_lost_hit());
  auto r = run_program({client_binary("messcap"), daemon.address(), "-n", "1", "-o", csv, "--append"});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("'" + csv + "'") && Catch::Contains("no 'hit' column") &&
                        Catch::Contains("hit,x,y,z") && Catch::Contains(".xyz, .asc or .hits"));
  CHECK(read_file(csv) == "x,y,z\n1.000,2.000,3.000\n");  // untouched
}
