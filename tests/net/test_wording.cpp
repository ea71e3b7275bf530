// The event lines a 1996 client may read (Warn, Fault, State, Limit) fit its 80-byte line
// buffer: at most 78 characters, so that the line and its LF (and a C string's NUL) fit.
#include <catch2/catch.hpp>

#include <string>

#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"

using namespace imess;

namespace {
constexpr std::size_t kMax1996 = 78;

template <class Enum, class Word>
void check_all(std::string_view verb, Word word) {
  int seen = 0;
  for (int i = 0; i < 64; ++i) {
    auto w = word(static_cast<Enum>(i));
    if (w.name == "Unknown") break;
    ++seen;
    std::string line = protocol::format_event(verb, std::string(w.name) + " " + std::string(w.text));
    INFO(line);
    CHECK(line.size() - 1 <= kMax1996);  // format_event ends the line with LF
    CHECK(line.back() == '\n');
  }
  CHECK(seen > 3);
}
}  // namespace

TEST_CASE("every Warn and Fault line fits a 1996 client's line buffer") {
  check_all<core::Warning>("Warn", net::warning_wording);
  check_all<core::FaultKind>("Fault", net::fault_wording);
}

TEST_CASE("every State and Limit line fits a 1996 client's line buffer") {
  for (int i = 0; i < 64; ++i) {
    auto name = net::mode_name(static_cast<core::Mode>(i));
    if (name == "unknown") break;
    CHECK(protocol::format_event("State", name).size() - 1 <= kMax1996);
  }
  CHECK(protocol::format_event("Limit", "X neg").size() - 1 <= kMax1996);
}
