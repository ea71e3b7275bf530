// Encoding and checking of journal records (see record.hpp for the line form).
#include "imess/journal/record.hpp"

#include <charconv>
#include <cstdio>

#include "imess/protocol/numbers.hpp"

namespace imess::journal {

std::string encode_record(std::string_view wire_line) {
  if (!wire_line.empty() && wire_line.back() == '\n') wire_line.remove_suffix(1);
  char sum[16];
  std::snprintf(sum, sizeof sum, " *%08x\n", static_cast<unsigned>(crc32(wire_line)));
  std::string out(wire_line);
  out += sum;
  return out;
}

std::optional<std::uint64_t> record_seq(std::string_view line) {
  // A hit or a scanning point: both are numbered in the one sequence.
  if (line.substr(0, 4) == "Hit ")
    line.remove_prefix(4);
  else if (line.substr(0, 5) == "Scan ")
    line.remove_prefix(5);
  else
    return std::nullopt;
  return protocol::parse_sequence_number(line.substr(0, line.find(' ')));
}

std::optional<Record> decode_record(std::string_view line) {
  constexpr std::size_t kSum = 10;  // " *" + 8 hex digits
  if (line.size() <= kSum || line[line.size() - kSum] != ' ' || line[line.size() - kSum + 1] != '*')
    return std::nullopt;
  std::string_view wire = line.substr(0, line.size() - kSum), hex = line.substr(line.size() - 8);
  std::uint32_t sum = 0;
  auto [end, ec] = std::from_chars(hex.data(), hex.data() + hex.size(), sum, 16);
  if (ec != std::errc{} || end != hex.data() + hex.size() || sum != crc32(wire)) return std::nullopt;
  auto seq = record_seq(wire);
  if (!seq) return std::nullopt;
  return Record{*seq, wire};
}

}  // namespace imess::journal
