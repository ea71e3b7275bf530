// Property tests of messd's I++ DME server (daemon/net/src/ipp_*.cpp) on every shipped
// configuration whose machine has linear X Y Z axes (the others have no I++ server): for fixed
// seeds, random sessions of an inspection program on the I++ port — StartSession, GoTo inside
// and outside the travel (partial axes too), PtMeas on the scene's surfaces and in the air
// (with and without IJK), SetProp/GetProp (out-of-range values too), Get, ClearAllErrors,
// AbortE at random moments, EnableUser/DisableUser, a move daemon, a moved and turned part
// frame, tools that measure or not, garbled lines (bad and reused tags, bad syntax, bytes
// outside 32–126), EndSession, drops mid-move, a second client refused — beside a MESSD jog
// panel (client 1) that asks Status, presses StopMv, tries to move and takes over to Reset.
// Replayed against messd's own parts in virtual time (the golden harness), then checked:
//
//  1. the protocol (IPPDME.md §§1-8): every line sent is answered in the step it was sent as
//     the library's parser and the open tags say — `tag &` for every line whose tag can be
//     read and is free (a refused line's `tag !` with the parser's error number comes after its
//     `&`, in its turn), or one `E0000 !` for an unreadable or reused tag; no line ever carries
//     a tag the client did not send; refusals and queries' errors leave the error state alone;
//     every accepted command gets exactly one `%` (unless its client dropped first)
//     and nothing on its tag afterwards but its move daemon's reports; command tags complete
//     in the order they were accepted; every `& # ! %` line carries an open tag or E0000;
//     every line is printable ASCII ending in CR LF; every `!` is `Error(F1, F2, F3, "text")`
//     with F1 and the text of F2 in the library's table (ippdme::find_error). The session and
//     the error state: outside a session only StartSession and EndSession succeed (0008),
//     StartSession inside one is 0008; 0514 only in the error state, and nothing but the
//     exempt commands completes without an error in it; `ErrStatus` tells it; AbortE's `%`
//     comes after every command transaction has closed; a second move daemon is 0515; a move
//     daemon reports at most 10 lines a second, with Time(s) at least every s whatever else
//     happens (AbortE, errors), and nothing after StopDaemon or EndSession; a PtMeas that
//     completes without an error sent exactly one point;
//  2. the machine never leaves its travel: every position seen (MESSD Status, I++ Get and the
//     move reports in the machine frame, the motion core after the last step) lies within each
//     axis' travel (± 0.05 mm: a servo settles up to 41 µm past a move's end at a travel's end);
//  3. after AbortE's `%`, EndSession's `%` and a drop, client 1's Status a second later finds
//     the machine standing (idle, free, or a fault's open loops; still backing off a hit, it
//     stands within RetractTime); after EndSession and a drop the session's control is given
//     back (client 1 hears it leave in that step, Status does not name the session);
//  4. messd keeps serving: at the end a new I++ client starts a session and reads a position
//     within the travel, and client 1 still answers Status;
//  5. while the session holds control (client 1 heard `Control ippdme`; EnableUser gives it
//     up, so the user is not enabled then), client 1's motion commands get `Err 209`;
//  6. a Get queued right behind a GoTo that completed without an error reads the GoTo's
//     target on every axis it named (within 0.2 mm: the map-A drive kit counts 0.1 mm).
//
// Each kind of event the rules speak about is counted; every configuration must show the
// main ones over its seeds (a rule never exercised proves nothing). IMESS_PROPERTY_SEEDS="7"
// replaces the fixed seeds; a failing seed leaves its transcript, "# step N" before each step
// as the messages count them, in the temp directory (the path is in the failure message).
// What messd was found doing against IPPDME.md is in test_ippdme_findings.cpp, each with a
// minimal script; the sessions leave out what would break the rules until it is fixed
// (kBurstsBeyondOneRead, kQueueBeyondItsLimit in ippdme_properties.hpp).
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>

#include "config_rig.hpp"
#include "golden_harness.hpp"
#include "ippdme_properties.hpp"
#include "property_support.hpp"

using namespace imess;
using namespace imess::golden;
using namespace imess::golden::ippdme_properties;

namespace {
constexpr int kActions = 80;
}  // namespace

TEST_CASE("I++ DME properties: random sessions on every configuration with an I++ server", "[long]") {
  const auto configs = ipp_configs();
  REQUIRE(configs.size() >= 6);  // the six X Y Z machines shipped today; a new one joins by itself
  Counts total;
  std::string summary;
  const auto started = std::chrono::steady_clock::now();
  for (const auto& config : configs) {
    const Machine m = machine_of(config);
    Counts per_config;
    for (const std::uint64_t seed : property_seeds({1, 2, 3, 4, 5, 6})) {
      INFO(config << " seed " << seed << " (IMESS_PROPERTY_SEEDS=\"" << seed << "\" runs it alone)");
      const Script script = make_script(m, mixed_seed(seed, config), kActions);
      const auto path = std::filesystem::temp_directory_path() /
                        ("imess-ippdme-properties-" + std::filesystem::path(config).stem().string() + "-" + std::to_string(seed) + ".txt");
      std::vector<Entry> out;
      std::optional<core::Snapshot> end;
      try {
        out = replay(script.entries, config + " seed " + std::to_string(seed), [&](test::ConfigRig& rig) { end = rig.core().snapshot(); });
      } catch (const std::exception& e) {
        std::ofstream(path) << format_transcript(script.entries);
        FAIL_CHECK("messd's parts threw while replaying (the script: " << path.string() << "): " << e.what());
        continue;
      }
      const Verdict verdict = check_session(m, script, out, end);
      if (!verdict.problems.empty()) {
        std::ofstream(path) << numbered(out);
        std::string first;
        for (std::size_t i = 0; i < verdict.problems.size() && i < 8; ++i) first += "\n  " + verdict.problems[i];
        FAIL_CHECK(verdict.problems.size() << " rule(s) broken; the transcript: " << path.string() << first);
      }
      per_config.add(verdict.counts);
    }
    INFO(config << ": " << per_config.text());
    summary += config + ": " + per_config.text() + "\n";
    CHECK(per_config.accepted > 0);
    CHECK(per_config.garbled > 0);
    CHECK(per_config.tag_errors > 0);
    CHECK(per_config.goto_done > 0);
    CHECK(per_config.goto_limit > 0);
    CHECK(per_config.ptmeas_points > 0);
    CHECK(per_config.ptmeas_errors > 0);
    CHECK(per_config.error_state_refusals > 0);
    CHECK(per_config.move_reports > 0);
    CHECK(per_config.drops > 0);
    CHECK(per_config.rest_checked > 0);
    CHECK(per_config.control_given_back > 0);
    CHECK(per_config.refused_209 > 0);
    CHECK(per_config.final_checks > 0);
    total.add(per_config);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  WARN(summary << "all: " << total.text() << "; " << num(wall, 1) << " s");
  CHECK(total.drops_mid_move > 0);
  CHECK(total.aborts_in_motion > 0);
  CHECK(total.refused_clients > 0);
  CHECK(total.panel_moves_ok > 0);
  CHECK(total.arrivals_checked > 0);
}

namespace {

// A copy of `out` with one received line changed (or dropped, or doubled, or one inserted
// before it): the first for which `pick` returns true.
struct Mutation {
  std::string what;
  std::function<bool(const std::vector<Entry>&, std::size_t)> pick;
  std::function<void(std::vector<Entry>&, std::size_t)> change;
};

bool received(const Entry& e, int client, const std::string& prefix) {
  return e.kind == EntryKind::Receive && e.client == client && starts(e.text, prefix);
}

std::optional<std::vector<Entry>> mutated(const std::vector<Entry>& out, const Mutation& m) {
  for (std::size_t i = 0; i < out.size(); ++i)
    if (m.pick(out, i)) {
      auto copy = out;
      m.change(copy, i);
      return copy;
    }
  return std::nullopt;
}

}  // namespace

TEST_CASE("I++ DME properties: the rules catch what they are about (a lost or doubled %, a wrong severity, a missing CR, ...)", "[long]") {
  const std::string config = "config/sim-servo-card.json";
  const Machine m = machine_of(config);
  auto is_ack = [](const std::string& t) { return t.size() == 7 && t.substr(5) == " %"; };
  const std::vector<Mutation> mutations = {
      {"a % lost", [&](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2 && is_ack(o[i].text); },
       [](auto& o, std::size_t i) { o.erase(o.begin() + static_cast<long>(i)); }},
      {"a % doubled", [&](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2 && is_ack(o[i].text); },
       [](auto& o, std::size_t i) { o.insert(o.begin() + static_cast<long>(i), o[i]); }},
      {"a wrong severity", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].text.find(" ! Error(3, ") == 5; },
       [](auto& o, std::size_t i) { o[i].text.replace(14, 1, "2"); }},
      {"a wrong error text", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].text.find(" ! Error(") == 5; },
       [](auto& o, std::size_t i) { o[i].text.insert(o[i].text.size() - 2, "!"); }},
      {"a missing CR", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2; },
       [](auto& o, std::size_t i) { o[i].text += " [no CR]"; }},
      {"a control byte", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2 && o[i].text.size() > 8; },
       [](auto& o, std::size_t i) { o[i].text[8] = '\x01'; }},
      {"a tag never sent", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2; },
       [](auto& o, std::size_t i) { o.insert(o.begin() + static_cast<long>(i), Entry{EntryKind::Receive, o[i].client, "77777 # X(1)"}); }},
      {"an error before its & (a refused line not acknowledged)", [](const auto& o, std::size_t i) {
         return i + 1 < o.size() && o[i].kind == EntryKind::Receive && o[i].client >= 2 && o[i].text.size() == 7 && o[i].text.find(" &") == 5 &&
                o[i + 1].kind == EntryKind::Receive && o[i + 1].client == o[i].client && o[i + 1].text.rfind(o[i].text.substr(0, 5) + " ! ", 0) == 0;
       },
       [](auto& o, std::size_t i) { o.erase(o.begin() + static_cast<long>(i)); }},
      {"an E0000 error on a tag the client did not send", [](const auto& o, std::size_t i) {
         return o[i].kind == EntryKind::Receive && o[i].client >= 2 && o[i].text.rfind("E0000 ! ", 0) == 0;
       },
       [](auto& o, std::size_t i) { o[i].text.replace(0, 5, "01234"); }},
      {"an answer missing", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].client >= 2 && o[i].text.find(" &") == 5; },
       [](auto& o, std::size_t i) { o.erase(o.begin() + static_cast<long>(i)); }},
      {"a move beside the session", [](const auto& o, std::size_t i) { return received(o[i], 1, "Err 209 "); },
       [](auto& o, std::size_t i) { o[i].text = "Ok GoTo"; }},
      {"a position off the travel", [](const auto& o, std::size_t i) { return received(o[i], 1, "Ok Status "); },
       [&](auto& o, std::size_t i) {
         auto w = words(o[i].text);
         w[5] = num(m.hi[0] + 0.5);
         std::string t;
         for (const auto& x : w) t += (t.empty() ? "" : " ") + x;
         o[i].text = t;
       }},
      {"control kept after a drop", [](const auto& o, std::size_t i) { return i > 0 && o[i - 1].kind == EntryKind::Close && received(o[i], 1, "Control none"); },
       [](auto& o, std::size_t i) { o.erase(o.begin() + static_cast<long>(i)); }},
      {"moving after the drop", [](const auto& o, std::size_t i) {  // the rest probe's Status after a drop
         if (!received(o[i], 1, "Ok Status State idle ")) return false;
         std::size_t j = i;
         while (j > 0 && !(o[j].kind == EntryKind::Send && o[j].client == 1)) --j;
         while (j > 0 && (o[j - 1].kind == EntryKind::Advance || o[j - 1].kind == EntryKind::Time || o[j - 1].kind == EntryKind::Receive)) --j;
         return j > 0 && o[j - 1].kind == EntryKind::Close;
       },
       [](auto& o, std::size_t i) { o[i].text.replace(16, 4, "move"); }},
      {"an ErrStatus that lies", [](const auto& o, std::size_t i) { return o[i].kind == EntryKind::Receive && o[i].text.find(" # ErrStatus(") == 5; },
       [](auto& o, std::size_t i) { o[i].text.back() == ')' && o[i].text[o[i].text.size() - 2] == '0' ? o[i].text[o[i].text.size() - 2] = '1' : o[i].text[o[i].text.size() - 2] = '0'; }},
  };
  // The first seed whose session has every line the mutations change.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Script script = make_script(m, mixed_seed(seed, config), kActions);
    const auto out = replay(script.entries, config + " seed " + std::to_string(seed));
    bool all = true;
    for (const auto& mu : mutations)
      if (!mutated(out, mu)) {
        UNSCOPED_INFO("seed " << seed << " has nothing for " << mu.what);
        all = false;
      }
    if (!all) continue;
    INFO(config << " seed " << seed);
    REQUIRE(check_session(m, script, out, std::nullopt).problems.empty());
    for (const auto& mu : mutations) {
      const auto problems = check_session(m, script, *mutated(out, mu), std::nullopt).problems;
      INFO(mu.what);
      CHECK_FALSE(problems.empty());
      if (std::getenv("IMESS_SHOW")) WARN(mu.what << " -> " << (problems.empty() ? "" : problems[0]));
    }
    return;
  }
  FAIL("no seed up to 20 has every line the mutations change");
}
