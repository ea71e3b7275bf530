// The programs folder of a real messd (--programs DIR): Programs lists the files of the known
// languages, Load reads one, and a symbolic link to a file outside the folder is refused
// without a word of that file in the reply.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "child_process.hpp"
#include "daemon_process.hpp"

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
