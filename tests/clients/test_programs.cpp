// Every client program: --help, the message and exit 1 when messd is not there, and exit 2
// naming the bad argument.
#include <catch2/catch.hpp>

#include <fstream>

#include "child_process.hpp"
#include "fake_daemon.hpp"

using imess::test::client_binary;
using imess::test::file_exists;
using imess::test::run_program;

TEST_CASE("clients: connection refused -> exit 1 and 'no partner on ... is messd running?'") {
  auto port = std::to_string(imess::test::unused_port());
  imess::test::TempDir dir;
  const auto program = dir.file("p.nc");
  std::ofstream(program) << "G0 X1\n";
  struct Case {
    const char* name;
    std::vector<std::string> before_host;  // arguments before HOST:PORT
  };
  const std::vector<Case> cases = {{"messjog", {}}, {"messmon", {}}, {"messcap", {}}, {"messprog", {"run", program}},
                                 {"messipp", {}}};
  for (const auto& c : cases) {
    INFO(c.name);
    std::vector<std::string> argv{client_binary(c.name)};
    argv.insert(argv.end(), c.before_host.begin(), c.before_host.end());
    argv.push_back("127.0.0.1:" + port);
    auto r = run_program(argv);
    CHECK(r.status == 1);
    CHECK(r.err == std::string(c.name) + ": no partner on 127.0.0.1:" + port +
                       " (connection refused) — is messd running?\n");
  }
}

TEST_CASE("messcap: refused before the first point leaves no empty file behind") {
  imess::test::TempDir dir;
  auto csv = dir.file("none.csv");
  auto port = std::to_string(imess::test::unused_port());
  auto r = run_program({client_binary("messcap"), "127.0.0.1:" + port, "-o", csv});
  CHECK(r.status == 1);
  CHECK_FALSE(file_exists(csv));
}

TEST_CASE("clients: --help prints usage and exits 0") {
  const std::vector<std::pair<const char*, const char*>> usages = {
      {"messjog", "[HOST[:PORT]]"}, {"messmon", "[HOST[:PORT]]"}, {"messcap", "[HOST[:PORT]]"}, {"messprog", "check FILE"},
      {"messipp", "[HOST[:PORT]]"}, {"messoffs", "TABLE"}};
  for (const auto& [name, first] : usages) {
    INFO(name);
    auto r = run_program({client_binary(name), "--help"});
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::StartsWith(std::string("usage: ") + name + " " + first) &&
                          Catch::Contains("Exit status"));
  }
}

TEST_CASE("clients: bad arguments -> exit 2 naming the argument and what is accepted") {
  struct Case {
    const char* name;
    std::vector<std::string> args;
    const char* expected;
  };
  std::vector<Case> cases = {
      {"messjog", {"--bogus"}, "messjog: unknown option '--bogus'; accepted: --wait, --help"},
      {"messmon", {"host:0"}, "messmon: bad address 'host:0': port '0' is not a number 1..65535"},
      {"messmon", {"a", "b"}, "messmon: unexpected argument 'b'; expected a single HOST[:PORT]"},
      {"messcap", {"-o", "points.txt"}, "messcap: output file 'points.txt': unknown extension '.txt'; accepted: .csv"},
      {"messcap", {"-n", "many"}, "messcap: -n 'many': expected a whole number of points"},
      {"messprog", {"frobnicate"}, "messprog: unknown command 'frobnicate'; accepted: check, plot, run"},
      {"messprog", {"check", "part.txt"}, "messprog: program 'part.txt' has the unknown extension '.txt'; accepted: .nc"},
      {"messprog", {"plot", "p.nc", "-o", "p.png"},
       "messprog: -o 'p.png': the plot is an SVG drawing; accepted: a file name ending in .svg"},
      {"messprog", {"run", "p.nc", "host:0"}, "messprog: bad address 'host:0': port '0' is not a number 1..65535"},
      {"messprog", {"run", "p.nc", "--bogus"}, "messprog: unknown option '--bogus' for run; accepted: --detached, --lang L"},
      {"messipp", {"--bogus"}, "messipp: unknown option '--bogus'; accepted: --raw, --timeout S, --help"},
      {"messipp", {"--timeout", "soon"}, "messipp: --timeout 'soon': accepted a number of seconds 0..86400"},
      {"messipp", {"cmm:0"}, "messipp: bad address 'cmm:0': port '0' is not a number 1..65535; expected HOST[:PORT] with PORT 1..65535, e.g. localhost, localhost:1294"},
      {"messoffs", {"t.json", "--clamping", "first"}, "messoffs: --clamping 'first': expected a whole number 1..999"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> argv{client_binary(c.name)};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    INFO(c.expected);
    auto r = run_program(argv);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::StartsWith(c.expected) && Catch::Contains("--help"));
  }
}

TEST_CASE("messcap: an unknown extension is refused before connecting") {
  imess::test::FakeDaemon daemon;
  auto r = run_program({client_binary("messcap"), daemon.address(), "-o", "x.ply.txt"});
  CHECK(r.status == 2);
  CHECK(daemon.accepted() == 0);
}
