// The programs folder of a real messd (--programs DIR): Programs lists the files of the known
// languages, Load reads one, and a symbolic link to a file outside the folder is refused
// without a word of that file in the reply.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "private_config.hpp"

using namespace imess::test;

TEST_CASE("programs folder: Programs lists it, Load reads it, a link to a file outside is refused") {
  TempDir dir;
  const std::filesystem::path folder = dir.file("progs");
  std::filesystem::create_directory(folder);
  std::ofstream(folder / "square.ngc") << "G0 X420\nG0 X430\nM2\n";
  std::ofstream(folder / "notes.txt") << "not a program\n";
  std::ofstream(dir.file("secret.ngc")) << "confidential words\n";
  std::filesystem::create_symlink(dir.file("secret.ngc"), folder / "outside.ngc");

  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json", "--programs", folder.string()});
  LineClient c(messd.port());
  CHECK(c.request("Programs") == "Ok Programs outside.ngc square.ngc");  // not notes.txt
  const auto ok = c.request("Load square.ngc");
  REQUIRE(ok);
  CHECK_THAT(*ok, Catch::StartsWith("Ok Load square.ngc Lang gcode Lines 3 Blocks 3 Segments 2"));
  const auto link = c.request("Load outside.ngc");
  REQUIRE(link);
  CHECK_THAT(*link, Catch::StartsWith("Err 105 Load outside.ngc: the file lies outside the programs folder"));
  CHECK(link->find("confidential") == std::string::npos);
  CHECK_THAT(*c.request("Load ../secret.ngc"), Catch::StartsWith("Err 105 Load ../secret.ngc: expected a file name"));
  CHECK_THAT(*c.request("Program"), Catch::StartsWith("Ok Program square.ngc loaded"));  // refusals kept the loaded one
}

namespace {

// "Lines 35 Blocks 28 Segments 27 Length 384.256 Time 40.1" of a Load reply, and the same
// figures from messprog check's report ("lines 35, blocks 28, segments 27", "path length
// 384.256 mm", "estimated time 40.1 s").
std::string load_figures(const std::string& reply) {
  const auto at = reply.find(" Lines ");
  return at == std::string::npos ? reply : reply.substr(at + 1);
}

std::string check_figures(const std::string& report) {
  auto after = [&](const std::string& key, const std::string& end) {
    const auto at = report.find(key);
    if (at == std::string::npos) return std::string("?");
    const auto from = at + key.size();
    return report.substr(from, report.find(end, from) - from);
  };
  char time[32];  // Load rounds to 0.1 s
  std::snprintf(time, sizeof time, "%.1f", std::stod(after("estimated time ", " s")));
  return "Lines " + after("lines ", ",") + " Blocks " + after("blocks ", ",") + " Segments " + after("segments ", "\n") +
         " Length " + after("path length ", " mm") + " Time " + std::string(time);
}

}  // namespace

TEST_CASE("messprog check --config answers what messd's Load answers, for every shipped example on its machine") {
  const std::string root = IMESS_SOURCE_DIR;
  // Each example on a shipped configuration that runs its language.
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"bore-inspection.ngc", "config/sim-servo-card.json"},
      {"pocket-helix.ngc", "config/sim-servo-card.json"},
      {"pocket-helix.ngc", "config/sim-parport-3dstep.json"},
      {"shd-drawing.plt", "config/sim-parport-shd.json"},
      {"mrm-manual.mrm", "config/sim-mrm-arm.json"},
  };
  for (const auto& [program, config] : runs) {
    INFO(program << " on " << config);
    const bool ports = config.find("parport") != std::string::npos || config.find("mrm") != std::string::npos;
    const std::string used = ports ? private_port_config(root + "/" + config) : root + "/" + config;
    DaemonProcess messd({"--config", used, "--programs", root + "/examples/programs"});
    LineClient c(messd.port());
    const auto loaded = c.request("Load " + program);
    REQUIRE(loaded);
    REQUIRE_THAT(*loaded, Catch::StartsWith("Ok Load " + program));
    const auto checked = run_program({client_binary("messprog"), "check", root + "/examples/programs/" + program,
                                      "--config", root + "/" + config});
    INFO(checked.out << checked.err);
    REQUIRE(checked.status == 0);
    CHECK(check_figures(checked.out) == load_figures(*loaded));
    if (ports) std::filesystem::remove(used);
  }
}
