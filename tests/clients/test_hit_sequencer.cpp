// HitSequencer: whatever order and repetition hits arrive in, they leave once each, in
// sequence, and a Replay is asked exactly when something is missing.
#include <catch2/catch.hpp>

#include "hit_sequencer.hpp"
#include "imess/protocol/numbers.hpp"

using imess::messcap::HitSequencer;
using imess::protocol::HitMsg;

namespace {
HitMsg hit(std::uint64_t seq) { return HitMsg{seq, 0, {0, 0, double(seq)}, {0, 0, -1}, 2, 0}; }
std::vector<std::uint64_t> seqs(const std::vector<HitMsg>& hits) {
  std::vector<std::uint64_t> out;
  for (const auto& h : hits) out.push_back(h.seq);
  return out;
}
}  // namespace

TEST_CASE("a new capture starts after the newest hit when it connected, and asks nothing while all is in order") {
  HitSequencer s;
  s.on_connected();
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(imess::protocol::kMaxSequenceNumber));  // the probe
  CHECK(s.on_hit(hit(41)).empty());  // live, before the probe's answer: kept
  CHECK(seqs(s.on_replay_ok(0, 41)) == std::vector<std::uint64_t>{41});
  CHECK_FALSE(s.take_replay_request());
  CHECK(seqs(s.on_hit(hit(42))) == std::vector<std::uint64_t>{42});
  CHECK(s.on_hit(hit(42)).empty());  // a duplicate
  CHECK_FALSE(s.take_replay_request());
}

TEST_CASE("a gap holds later hits back and asks for a Replay from the first missing one") {
  HitSequencer s(0);
  s.take_replay_request();
  s.on_replay_ok(0, 0);
  s.on_hit(hit(1));
  CHECK(s.on_hit(hit(4)).empty());
  CHECK(s.on_hit(hit(5)).empty());
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(2));
  CHECK_FALSE(s.take_replay_request());  // one at a time
  CHECK(seqs(s.on_hit(hit(2))) == std::vector<std::uint64_t>{2});
  CHECK(seqs(s.on_hit(hit(3))) == std::vector<std::uint64_t>{3, 4, 5});
  CHECK(s.on_hit(hit(4)).empty());
  CHECK(s.on_replay_ok(4, 5).empty());
  CHECK_FALSE(s.take_replay_request());
  CHECK(s.next() == std::optional<std::uint64_t>(6));
}

TEST_CASE("after --append or a reconnect the Replay starts at the next number - a capped Replay is continued") {
  HitSequencer s(10);
  s.on_connected();
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(11));
  for (std::uint64_t n = 11; n <= 1010; ++n) REQUIRE(s.on_hit(hit(n)).size() == 1);
  s.on_replay_ok(1000, 1500);
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(1011));
  s.on_connected();  // the link broke meanwhile: ask again on the new one
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(1011));
}

TEST_CASE("hits rotated out of the journal are skipped, counted and reported") {
  HitSequencer s(10);
  s.take_replay_request();
  CHECK(s.on_hit(hit(60)).empty());
  CHECK(s.on_replay_gone(50).empty());
  CHECK(s.skipped() == 39);
  auto notes = s.take_notes();
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("hits 11 to 49 are missing") != std::string::npos);
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(50));
  CHECK(s.on_replay_ok(0, 49).empty() == true);
}

TEST_CASE("a messd without Replay: the hits held back are released, no more requests") {
  HitSequencer s(3);
  s.take_replay_request();
  s.on_hit(hit(9));
  CHECK(seqs(s.on_replay_refused()) == std::vector<std::uint64_t>{9});
  s.on_connected();
  CHECK_FALSE(s.take_replay_request());
}

TEST_CASE("a journal behind the capture (another directory) is followed, with a note") {
  HitSequencer s(500);
  s.take_replay_request();
  s.on_replay_ok(0, 20);
  CHECK(s.next() == std::optional<std::uint64_t>(21));
  CHECK(s.take_notes().size() == 1);
  CHECK(seqs(s.on_hit(hit(21))) == std::vector<std::uint64_t>{21});
}

TEST_CASE("a new capture from a messd without Replay starts with the first hit") {
  HitSequencer s;
  s.take_replay_request();
  CHECK(s.on_hit(hit(7)).empty());
  CHECK(seqs(s.on_replay_refused()) == std::vector<std::uint64_t>{7});
  CHECK(seqs(s.on_hit(hit(8))) == std::vector<std::uint64_t>{8});
  CHECK(s.skipped() == 0);
}

TEST_CASE("hits messd names lost in its journal (Replay Lost) are skipped once, counted and reported") {
  HitSequencer s(2);
  s.on_connected();
  CHECK(s.take_replay_request() == std::optional<std::uint64_t>(3));
  // Replay 3's answer: Hit 3, Hit 4, Replay Lost 5 5, Hit 6 … 10, Ok Replay 8 10.
  CHECK(seqs(s.on_hit(hit(3))) == std::vector<std::uint64_t>{3});
  CHECK(seqs(s.on_hit(hit(4))) == std::vector<std::uint64_t>{4});
  CHECK(s.on_replay_lost(5, 5).empty());
  CHECK(seqs(s.on_hit(hit(6))) == std::vector<std::uint64_t>{6});
  for (std::uint64_t n = 7; n <= 10; ++n) REQUIRE(s.on_hit(hit(n)).size() == 1);
  CHECK(s.on_replay_ok(8, 10).empty());
  CHECK_FALSE(s.take_replay_request());  // nothing left to ask: no endless Replay 5
  CHECK(s.skipped() == 1);
  auto notes = s.take_notes();
  REQUIRE(notes.size() == 1);
  CHECK(notes[0] == "hit 5 is missing: its record in messd's journal is damaged or missing");
  CHECK(s.lost_text() == "5");
}

TEST_CASE("a lost range named before the hits ahead of it arrive is skipped when the capture reaches it") {
  HitSequencer s(0);
  s.take_replay_request();
  CHECK(s.on_hit(hit(1)).size() == 1);
  CHECK(s.on_hit(hit(9)).empty());   // live, while hits 2 … 8 are being replayed
  CHECK(s.on_replay_lost(4, 6).empty());  // named before hits 2 and 3 came
  CHECK(seqs(s.on_hit(hit(2))) == std::vector<std::uint64_t>{2});
  CHECK(seqs(s.on_hit(hit(3))) == std::vector<std::uint64_t>{3});
  CHECK(seqs(s.on_hit(hit(7))) == std::vector<std::uint64_t>{7});
  CHECK(seqs(s.on_hit(hit(8))) == std::vector<std::uint64_t>{8, 9});
  CHECK(s.skipped() == 3);
  CHECK(s.take_notes() == std::vector<std::string>{"hits 4 to 6 are missing: their records in messd's journal are damaged or missing"});
}
