// Golden G-code (MOTION.md (e)): our canonical emission against LinuxCNC's `rs274 -g`, for a
// few programs, where /usr/bin/rs274 (linuxcnc-uspace) is installed; skipped otherwise.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>
#include <cstdlib>
#include <unistd.h>

#include "imess/programs/canon.hpp"
#include "imess/programs/gcode.hpp"

using namespace imess::programs;

namespace {
constexpr const char* kRs274 = "/usr/bin/rs274";

// The numbers of every motion call (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED,
// STRAIGHT_PROBE) in a text, each call as "NAME n1 n2 ..." keeping the first `keep` numbers.
std::vector<std::string> calls(const std::string& text) {
  static const std::regex call(R"((STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|STRAIGHT_PROBE)\(([^)]*)\))");
  static const std::regex number(R"(-?[0-9]+(\.[0-9]+)?)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    const std::string args = (*it)[2];
    std::string c = name;
    int kept = 0;
    const int keep = name == "ARC_FEED" ? 6 : 3;  // positions in XYZ; ABC differ by version
    for (auto n = std::sregex_iterator(args.begin(), args.end(), number); n != std::sregex_iterator() && kept < keep; ++n, ++kept) {
      char buf[32];
      std::snprintf(buf, sizeof buf, " %.3f", std::stod((*n)[0]));
      c += buf;
    }
    out.push_back(c);
  }
  return out;
}
}  // namespace

TEST_CASE("rs274: canonical emission matches LinuxCNC's rs274 -g (skipped without linuxcnc-uspace)") {
  if (!std::filesystem::exists(kRs274)) {
    WARN("rs274 not installed here (Debian package linuxcnc-uspace): comparison skipped");
    return;
  }
  const std::vector<std::string> programs = {
      "G21 G90 G17\nG0 X10 Y5\nG1 Z-1 F600\nX20\nG91 Y5\nM2\n",
      "G21 G90 G17\nG0 X0 Y0 Z0\nG2 X10 Y0 I5 J0 F60\nG3 X0 Y0 R5\nG3 X0 Y0 Z-3 I-5 F60\nM2\n",
      "G21 G90 G18\nG0 X0 Y0 Z0\nG2 X10 I5 F60\nG19 G3 Y10 J5\nM2\n",
      "G21 G90 G17\nG0 X1 Y1\nG1 X2 F10\nG38.2 Z-5 F60\nM2\n",
  };
  const auto dir = std::filesystem::temp_directory_path() / ("imess_rs274_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (std::size_t k = 0; k < programs.size(); ++k) {
    const auto ngc = dir / ("p" + std::to_string(k) + ".ngc");
    const auto out = dir / ("p" + std::to_string(k) + ".out");
    std::ofstream(ngc) << programs[k];
    const std::string cmd = std::string(kRs274) + " -g " + ngc.string() + " > " + out.string() + " 2>&1 </dev/null";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(out);
    const std::string theirs((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const GcodeOptions o;
    const auto t = translate_gcode(programs[k], o);
    REQUIRE(t.ok);
    std::string ours;
    for (const auto& it : t.items) ours += canonical(it, o.machine) + "\n";
    INFO("program " << k << "\n" << programs[k] << "rs274:\n" << theirs << "ours:\n" << ours);
    CHECK(calls(ours) == calls(theirs));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("rs274: the form of our canonical calls (first, second, centre, rotation, axis end, A B C)") {
  const GcodeOptions o;
  const auto t = translate_gcode("G0 X1 Y2 Z3\nG1 X0 Y0 Z0 F60\nG18 G2 X10 I5\nG17 G3 I-5 P3\nG4 P2\nG38.2 Z-5\nM2\n", o);
  REQUIRE(t.ok);
  std::vector<std::string> got;
  for (const auto& it : t.items) got.push_back(canonical(it, o.machine));
  CHECK(got == std::vector<std::string>{
                   "STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)",
                   "STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
                   "ARC_FEED(0.0000, 10.0000, 0.0000, 5.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)",
                   "ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, 3, 0.0000, 0.0000, 0.0000, 0.0000)",
                   "DWELL(2.0000)",
                   "STRAIGHT_PROBE(10.0000, 0.0000, -5.0000, 0.0000, 0.0000, 0.0000)",
                   ""});
}
