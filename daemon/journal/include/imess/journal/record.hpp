// One journal record per line: the Hit (or Scan) line exactly as sent live, then " *" and the CRC-32 of
// that text in 8 hex digits. The checksum tells a complete record from a torn or garbled one.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace imess::journal {

std::uint32_t crc32(std::string_view bytes);

// wire_line: "Hit 17 0 ...\n" (protocol::format_hit). Returns "Hit 17 0 ... *89abcdef\n".
std::string encode_record(std::string_view wire_line);

struct Record {
  std::uint64_t seq = 0;
  std::string_view wire;  // the Hit line without the checksum and without "\n"
};

// line: one line of a journal file without its "\n". nullopt when it is not a whole, intact
// record (a torn end after a crash, garbage after a power cut).
std::optional<Record> decode_record(std::string_view line);

// Only the sequence number (for skipping to a Replay's start without checking every CRC).
std::optional<std::uint64_t> record_seq(std::string_view line);

}  // namespace imess::journal
