// Journal records: the live Hit line plus a checksum; anything torn or altered is refused.
#include <catch2/catch.hpp>

#include "imess/journal/record.hpp"

using namespace imess::journal;

TEST_CASE("crc32 is the standard CRC-32") {
  CHECK(crc32("123456789") == 0xCBF43926u);  // the check value of CRC-32/ISO-HDLC
  CHECK(crc32("") == 0u);
}

TEST_CASE("a record is the Hit line plus its checksum, and decodes back to it") {
  std::string wire = "Hit 17 0 1.0000 2.0000 3.0000 0.000000 0.000000 -1.000000 2.0000 5.000000\n";
  std::string rec = encode_record(wire);
  CHECK(rec.rfind(wire.substr(0, wire.size() - 1) + " *", 0) == 0);
  CHECK(rec.back() == '\n');
  auto r = decode_record(std::string_view(rec).substr(0, rec.size() - 1));
  REQUIRE(r);
  CHECK(r->seq == 17);
  CHECK(std::string(r->wire) + "\n" == wire);
  // A scanning point is a record of the same sequence.
  const std::string scan = "Scan 18 4 1.0000 2.0000 3.0000 -1.000000 0.000000 0.000000 2.0000 5.001000\n";
  const std::string scan_rec = encode_record(scan);
  const auto s = decode_record(std::string_view(scan_rec).substr(0, scan_rec.size() - 1));
  REQUIRE(s);
  CHECK(s->seq == 18);
  CHECK(std::string(s->wire) + "\n" == scan);
}

TEST_CASE("torn, altered and foreign lines are not records") {
  std::string rec = encode_record("Hit 3 0 1.0000 2.0000 3.0000 0.000000 0.000000 1.000000 2.0000 5.000000\n");
  rec.pop_back();
  for (std::size_t cut : {std::size_t{1}, std::size_t{5}, rec.size() / 2, rec.size() - 1}) {
    INFO(cut);
    CHECK_FALSE(decode_record(std::string_view(rec).substr(0, cut)));
  }
  std::string altered = rec;
  altered[10] = altered[10] == '1' ? '2' : '1';
  CHECK_FALSE(decode_record(altered));
  CHECK_FALSE(decode_record(std::string(rec.size(), '\0')));
  CHECK_FALSE(decode_record("MeasPt 1.000 2.000 3.000"));
}
