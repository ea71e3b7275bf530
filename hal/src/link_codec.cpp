// Little-endian encoding independent of the host's byte order.
#include "imess/hal/link_codec.hpp"

#include <bit>
#include <cstring>

namespace imess::hal {

LinkWriter& LinkWriter::u8(std::uint8_t v) noexcept {
  if (size_ >= buf_.size()) {
    overflow_ = true;
    return *this;
  }
  buf_[size_++] = v;
  return *this;
}

LinkWriter& LinkWriter::u16(std::uint16_t v) noexcept {
  return u8(static_cast<std::uint8_t>(v)).u8(static_cast<std::uint8_t>(v >> 8));
}

LinkWriter& LinkWriter::f32(float v) noexcept { return u32(std::bit_cast<std::uint32_t>(v)); }

LinkWriter& LinkWriter::u32(std::uint32_t v) noexcept {
  for (int i = 0; i < 4; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
  return *this;
}

LinkWriter& LinkWriter::f64(double v) noexcept {
  auto bits = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) u8(static_cast<std::uint8_t>(bits >> (8 * i)));
  return *this;
}

bool LinkReader::need(std::size_t n) noexcept {
  if (!ok_ || data_.size() - pos_ < n) {
    ok_ = false;
    return false;
  }
  return true;
}

std::uint8_t LinkReader::u8() noexcept { return need(1) ? data_[pos_++] : 0; }

std::uint16_t LinkReader::u16() noexcept {
  if (!need(2)) return 0;
  const auto lo = data_[pos_++];
  return static_cast<std::uint16_t>(lo | (data_[pos_++] << 8));
}

float LinkReader::f32() noexcept { return std::bit_cast<float>(u32()); }

std::uint32_t LinkReader::u32() noexcept {
  if (!need(4)) return 0;
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= std::uint32_t{data_[pos_++]} << (8 * i);
  return v;
}

double LinkReader::f64() noexcept {
  if (!need(8)) return 0;
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= std::uint64_t{data_[pos_++]} << (8 * i);
  return std::bit_cast<double>(bits);
}

}  // namespace imess::hal
