// Fixed-capacity little-endian frame writer/reader for the card link (no allocation).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace imess::hal {

inline constexpr std::size_t kMaxFrame = 256;

class LinkWriter {
 public:
  LinkWriter& u8(std::uint8_t v) noexcept;
  LinkWriter& u16(std::uint16_t v) noexcept;
  LinkWriter& u32(std::uint32_t v) noexcept;
  LinkWriter& i32(std::int32_t v) noexcept { return u32(static_cast<std::uint32_t>(v)); }
  LinkWriter& f32(float v) noexcept;
  LinkWriter& f64(double v) noexcept;
  std::span<const std::uint8_t> bytes() const noexcept { return {buf_.data(), size_}; }
  bool ok() const noexcept { return !overflow_; }
  void clear() noexcept { size_ = 0; overflow_ = false; }

 private:
  std::array<std::uint8_t, kMaxFrame> buf_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

class LinkReader {
 public:
  explicit LinkReader(std::span<const std::uint8_t> data) noexcept : data_(data) {}
  std::uint8_t u8() noexcept;
  std::uint16_t u16() noexcept;
  std::uint32_t u32() noexcept;
  std::int32_t i32() noexcept { return static_cast<std::int32_t>(u32()); }
  float f32() noexcept;
  double f64() noexcept;
  bool ok() const noexcept { return ok_; }          // no read ran past the end
  bool at_end() const noexcept { return pos_ == data_.size(); }
  std::size_t remaining() const noexcept { return data_.size() - pos_; }

 private:
  bool need(std::size_t n) noexcept;
  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace imess::hal
