// Every golden transcript replays byte for byte; IMESS_GOLDEN_REGENERATE=1 (scripts/golden
// --regenerate) rewrites their observed lines from today's behaviour instead.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>

#include "golden_files.hpp"
#include "golden_harness.hpp"

using namespace imess::golden;

namespace {

// "line N: expected / actual" for the first line where the two texts part.
std::string first_difference(const std::string& expected, const std::string& actual) {
  std::istringstream e(expected), a(actual);
  std::string le, la;
  for (int n = 1;; ++n) {
    bool more_e = static_cast<bool>(std::getline(e, le)), more_a = static_cast<bool>(std::getline(a, la));
    if (!more_e && !more_a) return "the texts differ only in their line ends";
    if (!more_e) le = "(end of file)";
    if (!more_a) la = "(end of output)";
    if (le != la || !more_e || !more_a)
      return "line " + std::to_string(n) + ":\n  expected: " + le + "\n  actual:   " + la;
  }
}

std::string replayed(const std::string& text, const std::string& name) {
  return format_transcript(replay(parse_transcript(text, name), name));
}

}  // namespace

TEST_CASE("every golden transcript replays byte for byte", "[long]") {
  const char* regenerate = std::getenv("IMESS_GOLDEN_REGENERATE");
  const char* only = std::getenv("IMESS_GOLDEN_ONLY");
  const auto files = golden_files();
  REQUIRE(!files.empty());  // how many: test_golden_coverage.cpp
  for (const auto& path : files) {
    const std::string name = path.filename().string();
    if (only && *only && name.find(only) == std::string::npos) continue;
    const std::string expected = read_text(path);
    const std::string actual = replayed(expected, name);
    if (regenerate && *regenerate == '1') {
      if (actual != expected) {
        std::ofstream(path, std::ios::binary) << actual;
        WARN("rewrote " << name);
      }
      continue;
    }
    const bool same = actual == expected;
    if (same)
      std::filesystem::remove(name + ".actual");
    else
      std::ofstream(name + ".actual", std::ios::binary) << actual;  // for a diff
    INFO(name << ": today's output is in " << (std::filesystem::current_path() / (name + ".actual")).string()
              << " (scripts/golden --regenerate accepts it); first difference at " << first_difference(expected, actual));
    CHECK(same);
  }
}

TEST_CASE("a golden transcript fails on a changed word or number and on a missing or extra line") {
  const std::string text = read_text(golden_dir() / "sim-servo-card.txt");
  const std::string actual = replayed(text, "sim-servo-card.txt");
  REQUIRE(actual == text);
  auto mutated = [&](const std::string& from, const std::string& to) {
    auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    std::string t = text;
    t.replace(at, from.size(), to);
    return t;
  };
  // The replay rebuilds the observed lines, so each of these differs from its own result.
  for (const std::string& t : {mutated("\n< Ok GoTo\n", "\n< Ok Goto\n"),                  // wording
                               mutated("\n< Ok GoTo\n", "\n"),                                // a line gone
                               mutated("\n< Ok GoTo\n", "\n< Ok GoTo\n< Ok GoTo\n"),          // a line more
                               mutated("\n< MeasPt ", "\n< MeasPt 1")}) {                      // a number
    CHECK(replayed(t, "mutated") != t);
  }
}
