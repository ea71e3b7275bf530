// The messprog check and plot examples a reader copies — README.md, docs/clients.md, the man
// page — name the machine they plan on (--config or --from), so the path starts where that
// machine stands, not with a rapid from the origin; each one whose program ships is run.
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>

#include "child_process.hpp"

using imess::test::client_binary;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;

namespace {

struct Example {
  std::string where, verb, args;
};

std::vector<Example> examples() {
  std::vector<Example> out;
  const std::string src = IMESS_SOURCE_DIR;
  const std::regex in_text("`(?:build/bin/)?messprog (check|plot) ([^`]+)`");
  for (const char* doc : {"README.md", "docs/clients.md"}) {
    const std::string text = read_file(src + "/" + doc);
    for (std::sregex_iterator m(text.begin(), text.end(), in_text), end; m != end; ++m)
      if ((*m)[2].str().find("FILE") == std::string::npos)  // not a usage line
        out.push_back({doc, (*m)[1], (*m)[2]});
    const std::regex in_block("\\n\\$ messprog (check|plot) ([^\\n]+)");
    for (std::sregex_iterator m(text.begin(), text.end(), in_block), end; m != end; ++m)
      out.push_back({doc, (*m)[1], (*m)[2]});
  }
  const std::string man = read_file(src + "/packaging/man/messprog.1");
  const std::regex in_man("\\n\\.B messprog (check|plot) ([^\\n]+)");
  for (std::sregex_iterator m(man.begin(), man.end(), in_man), end; m != end; ++m) {
    std::string args = std::regex_replace((*m)[2].str(), std::regex("\\\\-"), "-");
    out.push_back({"packaging/man/messprog.1", (*m)[1], args});
  }
  return out;
}

std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

TEST_CASE("the documented messprog check and plot examples plan from where their machine starts") {
  const auto all = examples();
  REQUIRE(all.size() >= 5);
  const std::string src = IMESS_SOURCE_DIR;
  TempDir dir;
  int ran = 0;
  for (const auto& e : all) {
    INFO(e.where << ": messprog " << e.verb << " " << e.args);
    auto w = words(e.args);
    // The examples of what goes wrong without a machine, or of --canon's output, stand for
    // themselves (docs/clients.md's byhand.nc and part.ngc are programs written out there).
    const bool about_generic = e.args.find("--canon") != std::string::npos || e.args.rfind("byhand.nc", 0) == 0;
    if (!about_generic)
      CHECK((e.args.find("--config") != std::string::npos || e.args.find("--from") != std::string::npos));
    // Run those whose program ships: the installed paths are the source tree's.
    std::vector<std::string> argv{client_binary("messprog"), "check"};
    bool runs = true;
    for (std::size_t i = 0; i < w.size(); ++i) {
      std::string a = std::regex_replace(w[i], std::regex("^/usr/share/imess/"), "");
      if (a == "-o") {
        ++i;  // check draws nothing
        continue;
      }
      if (std::regex_search(a, std::regex("\\.(nc|ngc|gcode|tap|plt|hpgl|mrm|json)$"))) {
        if (!std::filesystem::exists(src + "/" + a)) runs = false;
        a = src + "/" + a;
      }
      argv.push_back(a);
    }
    if (!runs || about_generic) continue;
    const auto r = run_program(argv);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("starting at 0\n") == std::string::npos);
    // The box of the path: X from where the simulated machine starts (430), not from 0.
    std::smatch box;
    REQUIRE(std::regex_search(r.out, box, std::regex("\\n  X +([-0-9.]+) \\.\\.")));
    CHECK(std::stod(box[1]) > 100);
    ++ran;
  }
  CHECK(ran >= 4);
}
