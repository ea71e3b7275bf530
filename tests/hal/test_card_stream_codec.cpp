// The servo card stream's framing and frames: CRC-16, frames through the decoder, every
// single-bit error caught, resynchronisation (FrameReceiver), and the status and setpoint
// frames round trip.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "imess/hal/card_stream.hpp"
#include "imess/hal/stream_frame.hpp"

using namespace imess::hal;
using card::kAxes;
using Result = FrameDecoder::Result;

namespace {
std::vector<std::uint8_t> wire(const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> out(kMaxWireFrame);
  out.resize(encode_frame(payload, out));
  return out;
}

// Feeds bytes; returns the payloads of the frames decoded and counts the damaged ones.
std::vector<std::vector<std::uint8_t>> decode(FrameDecoder& d, const std::vector<std::uint8_t>& bytes, int* damaged = nullptr) {
  std::vector<std::vector<std::uint8_t>> frames;
  for (auto b : bytes) {
    const Result r = d.feed(b);
    if (r == Result::Frame) frames.emplace_back(d.payload().begin(), d.payload().end());
    if (r == Result::Damaged && damaged) ++*damaged;
  }
  return frames;
}

std::vector<std::uint8_t> random_payload(std::mt19937& rng) {
  std::uniform_int_distribution<int> len(1, static_cast<int>(kMaxPayload)), byte(0, 255);
  std::vector<std::uint8_t> p(static_cast<std::size_t>(len(rng)));
  for (auto& b : p) b = static_cast<std::uint8_t>(byte(rng));
  return p;
}
}  // namespace

TEST_CASE("stream frames: CRC-16/CCITT-FALSE check value, frame layout, refused sizes") {
  const std::uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  CHECK(crc16(check) == 0x29B1);
  const auto w = wire({0x01, 0x02, 0x03});
  REQUIRE(w.size() == 7);
  CHECK(w[0] == kFrameSync);
  CHECK(w[1] == 3);
  CHECK(crc16(std::span<const std::uint8_t>(w.data() + 1, 4)) == (w[5] | (w[6] << 8)));
  std::array<std::uint8_t, kMaxWireFrame + 8> out{};
  CHECK(encode_frame({}, out) == 0);
  const std::vector<std::uint8_t> too_long(kMaxPayload + 1, 0);
  CHECK(encode_frame(too_long, out) == 0);
  const std::vector<std::uint8_t> three{1, 2, 3};
  CHECK(encode_frame(three, std::span<std::uint8_t>(out.data(), 6)) == 0);  // no room for the CRC
}

TEST_CASE("stream frames: random payloads come through the decoder intact, back to back and after garbage") {
  std::mt19937 rng(20261123);
  FrameDecoder d;
  for (int i = 0; i < 200; ++i) {
    const auto p = random_payload(rng), q = random_payload(rng);
    std::vector<std::uint8_t> bytes = {0x00, 0x13, 0x37};  // line noise before the sync
    for (auto b : wire(p)) bytes.push_back(b);
    for (auto b : wire(q)) bytes.push_back(b);
    const auto frames = decode(d, bytes);
    REQUIRE(frames.size() == 2);
    CHECK(frames[0] == p);
    CHECK(frames[1] == q);
  }
}

TEST_CASE("stream frames: every single-bit error is caught, and the decoder finds the frames after it") {
  std::mt19937 rng(7);
  for (int i = 0; i < 40; ++i) {
    const auto p = random_payload(rng);
    const auto good = wire(p);
    for (std::size_t bit = 0; bit < good.size() * 8; ++bit) {
      auto bad = good;
      bad[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
      FrameDecoder d;
      std::vector<std::uint8_t> bytes = bad;
      for (int k = 0; k < 90; ++k)  // enough short frames to outlast a length byte made 250
        for (auto b : wire({0x42, static_cast<std::uint8_t>(k)})) bytes.push_back(b);
      int damaged = 0;
      const auto frames = decode(d, bytes, &damaged);
      INFO("payload " << i << ", bit " << bit);
      for (const auto& f : frames) REQUIRE((f.size() == 2 && f[0] == 0x42));  // never the damaged payload, never a mix
      REQUIRE(!frames.empty());
      CHECK(frames.back()[1] == 89);  // back in step by the end
      if (bit >= 8) CHECK(damaged >= 1);  // a flipped sync byte is never seen as a frame at all
    }
  }
}

TEST_CASE("stream frames: the status frame and the timed setpoint round trip — short or long frames are refused") {
  card::StatusFrame s;
  s.clock = 0xFFFFFFF0u;
  s.ack = 200;
  s.ack_status = 5;
  s.flags = card::flag::kLatchData | card::flag::kResendWanted;
  s.starvations = 3;
  s.knots = 4;
  s.margin = 117;
  s.held = 0xA00F;
  s.mask = (1u << kAxes) - 1;
  for (int a = 0; a < kAxes; ++a) {
    s.position[a] = -123.4567 + a;
    s.latched[a] = 987.6543 - a;
    s.status[a] = 0x12345u + static_cast<unsigned>(a);
    s.inputs[a] = static_cast<std::uint8_t>(0x8 | a);
  }
  LinkWriter w;
  card::write_status(w, s);
  REQUIRE(w.ok());
  CHECK(w.bytes().size() == 12u + 2 + 1 + kAxes + 9u * kAxes + 4u * kAxes);  // held: with kResendWanted
  card::StatusFrame back;
  REQUIRE(card::read_status(w.bytes(), back));
  CHECK(back.clock == s.clock);
  CHECK(back.ack == 200);
  CHECK(back.ack_status == 5);
  CHECK(back.flags == s.flags);
  CHECK(back.margin == 117);
  CHECK(back.held == 0xA00F);
  for (int a = 0; a < kAxes; ++a) {
    CHECK(back.position[a] == Approx(s.position[a]).margin(card::kStreamUnit / 2));
    CHECK(back.latched[a] == Approx(s.latched[a]).margin(card::kStreamUnit / 2));
    CHECK(back.status[a] == s.status[a]);
    CHECK(back.inputs[a] == s.inputs[a]);
  }
  for (std::size_t n = 0; n < w.bytes().size(); ++n) CHECK_FALSE(card::read_status(w.bytes().first(n), back));

  card::Knot k;
  k.tick = 123456;
  k.mask = 0b101;
  k.position[0] = 430.12345;
  k.position[2] = -0.00004;
  k.velocity[0] = 99.5;
  k.velocity[2] = -12.25;
  w.clear();
  card::write_knot(w, k);
  CHECK(w.bytes().size() == 4u + 3 + 2 * 8u);
  LinkReader r(w.bytes());
  card::Knot kb;
  REQUIRE(card::read_knot(r, kb) == card::Status::Ok);
  CHECK(kb.tick == k.tick);
  CHECK(kb.mask == k.mask);
  CHECK(kb.position[0] == Approx(430.1234).margin(1e-9));  // 0.1 µm units, rounded
  CHECK(kb.position[2] == Approx(0.0).margin(1e-9));
  CHECK(kb.velocity[0] == 99.5);
  CHECK(kb.velocity[2] == -12.25);
  LinkReader shorter(w.bytes().first(w.bytes().size() - 1));
  CHECK(card::read_knot(shorter, kb) == card::Status::BadLength);
}

TEST_CASE("stream frames: the deflection follows the latch data with flag 0x4 — i32 dx dy dz in 0.1 µm, u8 probe flags") {
  card::StatusFrame s;
  s.clock = 4242;
  s.flags = card::flag::kLatchData | card::flag::kDeflection;
  s.mask = (1u << kAxes) - 1;
  for (int a = 0; a < kAxes; ++a) {
    s.position[a] = 100.0 + a;
    s.latched[a] = 50.0 - a;
  }
  s.deflection = Vec3(0.12344, -0.00004, 0.99996);
  s.probe = card::probe::kAnalogPresent | card::probe::kContact;
  LinkWriter w;
  card::write_status(w, s);
  REQUIRE(w.ok());
  CHECK(w.bytes().size() == 12u + 1 + kAxes + 9u * kAxes + 4u * kAxes + 13);
  // The 13 bytes after the latch data: dz is the last i32 before the flags, 10000 units.
  const auto b = w.bytes();
  CHECK(b[b.size() - 1] == s.probe);
  CHECK((b[b.size() - 5] | b[b.size() - 4] << 8 | b[b.size() - 3] << 16 | b[b.size() - 2] << 24) == 10000);
  card::StatusFrame back;
  REQUIRE(card::read_status(w.bytes(), back));
  CHECK(back.flags == s.flags);
  CHECK(back.probe == s.probe);
  CHECK(back.deflection.x() == Approx(0.1234).margin(1e-12));  // 0.1 µm units, rounded
  CHECK(back.deflection.y() == Approx(0.0).margin(1e-12));
  CHECK(back.deflection.z() == Approx(1.0).margin(1e-12));
  for (int a = 0; a < kAxes; ++a) CHECK(back.latched[a] == Approx(s.latched[a]).margin(1e-9));
  for (std::size_t n = 0; n < w.bytes().size(); ++n) CHECK_FALSE(card::read_status(w.bytes().first(n), back));
  // Without the flag the same bytes are one probe reading too long.
  std::vector<std::uint8_t> unflagged(b.begin(), b.end());
  unflagged[7] = card::flag::kLatchData;
  CHECK_FALSE(card::read_status(unflagged, back));
}

TEST_CASE("stream frames: an axis table with no axis, too many, an unknown or a repeated one is refused") {
  auto table = [](std::vector<std::uint8_t> bytes) {
    LinkReader r(bytes);
    unsigned mask = 0;
    return card::read_table(r, mask);
  };
  CHECK(table({0}) == card::Status::BadAxis);
  CHECK(table({static_cast<std::uint8_t>(kAxes + 1), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9}) == card::Status::BadAxis);
  CHECK(table({1, static_cast<std::uint8_t>(kAxes)}) == card::Status::BadAxis);
  CHECK(table({2, 0, 0}) == card::Status::BadAxis);
  CHECK(table({2, 0}) == card::Status::BadLength);
  CHECK(table({}) == card::Status::BadLength);
  CHECK(table({1, 0}) == card::Status::Ok);
}

TEST_CASE("stream frames: a false sync byte in a damaged frame's CRC costs that frame only (FrameReceiver)") {
  // A damaged frame whose CRC's high byte reads as a sync byte: the plain decoder takes the
  // next frame's sync (0xA5 = 165) for a length and swallows the frames behind it; the
  // receiver looks at those bytes again and finds them.
  std::vector<std::uint8_t> damaged = wire({0x10, 0x11, 0x12, 0x13});
  damaged[damaged.size() - 2] ^= 0x01;  // the CRC's low byte: damaged
  damaged.back() = kFrameSync;          // its high byte a false sync
  std::vector<std::vector<std::uint8_t>> sent;
  std::vector<std::uint8_t> bytes = damaged;
  std::mt19937 rng(7);
  for (int i = 0; i < 6; ++i) {
    std::vector<std::uint8_t> p(40);
    for (auto& b : p) b = static_cast<std::uint8_t>(rng() % 256);
    sent.push_back(p);
    const auto w = wire(p);
    bytes.insert(bytes.end(), w.begin(), w.end());
  }
  FrameDecoder plain;
  int plain_damaged = 0;
  const auto plain_frames = decode(plain, bytes, &plain_damaged);
  CHECK(plain_frames.size() < sent.size());  // what the receiver is for

  FrameReceiver receiver;
  std::vector<std::vector<std::uint8_t>> got;
  int damaged_count = 0;
  for (auto b : bytes)
    receiver.feed(b, [&](Result r, const FrameDecoder& d) {
      if (r == Result::Frame) got.emplace_back(d.payload().begin(), d.payload().end());
      else ++damaged_count;
    });
  CHECK(got == sent);
  // The damaged frame, and the false sync's own attempt (no receiver can tell it from a frame
  // damaged on the line); not the sync bytes found again among bytes looked at twice.
  CHECK(damaged_count == 2);
}
