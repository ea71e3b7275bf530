// What the I++ DME properties (test_ippdme_properties.cpp) found messd doing against
// IPPDME.md and docs/ippdme.md, each alone in a minimal script on the default simulated CMM.
// All are fixed; each case stays against a relapse.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ipp_script.hpp"

namespace imess::golden {
namespace {

std::vector<std::string> finding_lines(const std::string& script) { return ipp_session_lines(script, "finding"); }

// "" when equal, else where they part: "line N: 'got' where 'want'".
std::string first_difference(const std::vector<std::string>& got, const std::vector<std::string>& want) {
  for (std::size_t i = 0; i < std::max(got.size(), want.size()); ++i) {
    const std::string g = i < got.size() ? got[i] : "(none)", w = i < want.size() ? want[i] : "(none)";
    if (g != w) return "line " + std::to_string(i + 1) + ": '" + g + "' where '" + w + "'";
  }
  return "";
}


// IPPDME.md §3: completions come back in the order the commands were started. A garbled line
// while a GoTo runs (so do a reused tag, or a fast command's error) puts the session into the
// error state; the Get queued behind the GoTo got its 0006 and `%` before the GoTo's `%`. Fixed
// (the queue is answered in its turn after the move's `%`): kept as a regression case. (Since
// issue 25 a garbled line is a refusal and no longer enters the error state: the order holds
// either way.)
TEST_CASE("I++ DME finding: an error while a GoTo runs answers the queue behind it after the GoTo") {
  const auto lines = finding_lines(
      "@ config/sim-servo-card.json\n"
      "+2 ipp\n"
      "2> 00001 StartSession()\n"
      "2> 00002 GoTo(Z(300))\n"
      "2>> 00003 Get(Z())\n"
      "= 100 ms\n"
      "2> 00004 Get(Z()\n"
      "= 5000 ms\n");
  const long go_to = index_of(lines, "00002 %"), get = index_of(lines, "00003 %");
  REQUIRE(go_to >= 0);
  REQUIRE(get >= 0);
  CHECK(go_to < get);
}

// IPPDME.md §§1-2: every line is answered by its own tag. 200 Get lines in one write (5.4 KB,
// more than one read of the server takes: 4 KiB) come back spliced: a fragment of a line is
// answered `E0000 ! Error(2, 0001, " Y(), Z())", "Illegal tag")` (the session enters the error
// state, the rest gets 0514), lines are answered twice, others never. IppServer::read feeds the
// framer from the connection's buffer while on_line -> pump -> read() starts the next
// async_read_some into that same buffer (asio reads at once when data waits), overwriting the
// bytes still being framed. Kept out of the properties' sessions as kBurstsBeyondOneRead
// (ippdme_properties.hpp).
TEST_CASE("I++ DME finding: more than 4 KiB of lines in one write are answered line by line") {
  std::string script = "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n";
  for (int tag = 2; tag <= 201; ++tag) {
    char line[64];
    std::snprintf(line, sizeof line, "%s %05d Get(X(), Y(), Z())\n", tag == 2 ? "2>" : "2>>", tag);
    script += line;
  }
  const auto lines = finding_lines(script);
  std::vector<std::string> want = {"00001 &", "00001 %"};
  for (int tag = 2; tag <= 201; ++tag) {
    char prefix[8];
    std::snprintf(prefix, sizeof prefix, "%05d", tag);
    want.push_back(std::string(prefix) + " &");
    want.push_back(std::string(prefix) + " # X(430.0000), Y(330.0000), Z(100.0000)");
    want.push_back(std::string(prefix) + " %");
  }
  const std::string difference = first_difference(lines, want);
  INFO(difference);
  CHECK(difference.empty());
}

// A GoTo and 68 Gets behind it in one write, one Get more: the normal queue holds 64
// commands (kMaxQueued in ipp_server.cpp) and IppServer::read stops reading the connection.
// IPPDME.md §6: an event tag's command bypasses the normal queue — but AbortE is not even read:
// it is answered only when the GoTo has run to its end, 4 s later, and aborts nothing. The
// same for a client that drops then: messd sees the connection close only when the queue
// drains, so the machine goes on moving under a session nobody holds (and a new client is
// refused as a second session). Kept out of the properties' sessions as kQueueBeyondItsLimit
// (ippdme_properties.hpp).
std::string full_queue_script(const std::string& then) {
  std::string script = "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n2> 00002 GoTo(Z(300))\n";
  for (int tag = 3; tag <= 70; ++tag) {
    char line[64];
    std::snprintf(line, sizeof line, "2>> %05d Get(Z())\n", tag);
    script += line;
  }
  return script + "= 100 ms\n2> 00071 Get(Z())\n= 100 ms\n" + then;
}

TEST_CASE("I++ DME finding: AbortE behind a full queue stops the GoTo at once") {
  const auto lines = finding_lines(full_queue_script("2> E0001 AbortE()\n= 5000 ms\n"));
  CHECK(index_of(lines, "00002 ! Error(2, 0006, GoTo, \"Transaction aborted (Use ClearAllErrors To Continue)\")") >= 0);
}

TEST_CASE("I++ DME finding: a client dropping behind a full queue stops the machine at once") {
  const auto out = replay(parse_transcript(full_queue_script("-2\n= 1000 ms\n> Status\n"), "finding"), "finding");
  std::string status;
  for (const auto& e : out)
    if (e.kind == EntryKind::Receive && e.client == 1 && e.text.rfind("Ok Status ", 0) == 0) status = e.text;
  INFO(status);
  CHECK(status.rfind("Ok Status State idle ", 0) == 0);
  CHECK(status.find(" Control none") != std::string::npos);
}

// A GoTo sent while the machine still brakes is refused with 0511 (severity 3: the error
// state) instead of waiting for it to stand: IppServer::plan_lines wants an idle machine. It
// hits two ordinary sequences. After EnableUser the operator jogs; the session's GoTo takes the
// machine back (claim_control stops the jog, IPPDME.md §7: a moving command disables the user)
// and is then refused because of that very stop — it can never succeed while the operator
// moves. And AbortE, ClearAllErrors, GoTo in one go, as a client recovers, is refused while the
// machine brakes from the AbortE.
TEST_CASE("I++ DME finding: a GoTo taking the machine back from a jogging operator moves") {
  const auto lines = finding_lines(
      "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n2> 00002 EnableUser()\n"
      "> StartMv 0 0 20\n= 300 ms\n2> 00003 GoTo(Z(150))\n= 3000 ms\n");
  CHECK(index_of(lines, "00003 ! Error(3, 0511, GoTo, \"Error processing method\")") < 0);
}

TEST_CASE("I++ DME finding: a GoTo right after AbortE and ClearAllErrors moves once the machine stands") {
  const auto lines = finding_lines(
      "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n2> 00002 GoTo(Z(300))\n= 300 ms\n"
      "2> E0001 AbortE()\n2>> 00003 ClearAllErrors()\n2>> 00004 GoTo(Z(100))\n= 3000 ms\n");
  CHECK(index_of(lines, "00004 ! Error(3, 0511, GoTo, \"Error processing method\")") < 0);
}

}  // namespace
}  // namespace imess::golden

namespace imess::golden {
namespace {
std::vector<std::string> client2_lines(const std::string& script) {
  std::vector<std::string> lines;
  for (const auto& e : replay(parse_transcript(script, "finding"), "finding"))
    if (e.kind == EntryKind::Receive && e.client == 2) lines.push_back(e.text);
  return lines;
}
}  // namespace

// An error admits every command waiting for its Ack at once (abort_queued), so the normal queue
// may hold more than 64; a command sent behind them then waits for room — and got its Ack
// only with the client's next line: IppServer::pump drained the aborted commands without
// making room for it (found by the properties once refused lines took their turn, issue 25).
TEST_CASE("I++ DME finding: a command waiting for room behind aborted ones is acknowledged when they drain") {
  const auto lines = client2_lines(full_queue_script("2> 00002 Get(X())\n= 100 ms\n2> 00072 Get(Z())\n= 5000 ms\n"));
  CHECK(std::find(lines.begin(), lines.end(), "E0000 ! Error(2, 0001, Get, \"Illegal tag\")") != lines.end());
  CHECK(std::find(lines.begin(), lines.end(), "00072 &") != lines.end());
  CHECK(std::find(lines.begin(), lines.end(), "00072 %") != lines.end());
}

}  // namespace imess::golden
