// Hit sets on the wire (Align): numbers and ranges separated by commas.
#include <catch2/catch.hpp>

#include <random>
#include <set>

#include "imess/protocol/hit_set.hpp"

using imess::protocol::parse_hit_set;

TEST_CASE("hit sets: numbers and ranges in the order written") {
  std::string why;
  CHECK(parse_hit_set("1-3", why) == std::vector<std::uint64_t>{1, 2, 3});
  CHECK(parse_hit_set("4,5", why) == std::vector<std::uint64_t>{4, 5});
  CHECK(parse_hit_set("7,9-12,2", why) == std::vector<std::uint64_t>{7, 9, 10, 11, 12, 2});
  CHECK(parse_hit_set("6", why) == std::vector<std::uint64_t>{6});
  CHECK(parse_hit_set("8-8", why) == std::vector<std::uint64_t>{8});
  CHECK(why.empty());
}

TEST_CASE("hit sets: what is refused says what was wrong and what is accepted") {
  for (const char* bad : {"", "0", "1-", "-3", "3-1", "1,,2", "1,", "a", "1-2-3", "1 2", "2,1-3", "1-1001",
                          "99999999999999999999", "+1", "1e3"}) {
    INFO(bad);
    std::string why;
    CHECK(parse_hit_set(bad, why).empty());
    CHECK(why.find("accepted: hit numbers and ranges") != std::string::npos);
  }
  std::string why;
  parse_hit_set("3-1", why);
  CHECK(why.find("backwards") != std::string::npos);
  parse_hit_set("2,1-3", why);
  CHECK(why.find("twice") != std::string::npos);
  parse_hit_set("1-1000", why);
  CHECK(why.empty());
}

TEST_CASE("hit sets: any set written as ranges reads back as the same numbers (seeded)") {
  std::mt19937_64 rng(20261126);
  for (int round = 0; round < 500; ++round) {
    std::set<std::uint64_t> used;
    std::vector<std::uint64_t> expected;
    std::string text;
    const int parts = 1 + static_cast<int>(rng() % 6);
    for (int p = 0; p < parts; ++p) {
      const std::uint64_t from = 1 + rng() % 200, length = rng() % 4;
      bool clash = false;
      for (std::uint64_t n = from; n <= from + length; ++n) clash = clash || used.count(n);
      if (clash) continue;
      text += (text.empty() ? "" : ",") + std::to_string(from) + (length ? "-" + std::to_string(from + length) : "");
      for (std::uint64_t n = from; n <= from + length; ++n) {
        used.insert(n);
        expected.push_back(n);
      }
    }
    std::string why;
    INFO(text);
    CHECK(parse_hit_set(text, why) == expected);
  }
}
