// Fuzz target: the servo card stream's parsers — the frame decoder over arbitrary bytes, the
// driver's status-frame parser and the emulated card's handling of every decoded host frame
// (setpoints, commands) once it streams, and the card's end of a serial line (sim::CardLineEnd:
// set-up frames answered with a set-up frame that must decode with the request's tag).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "imess/hal/card_stream.hpp"
#include "imess/hal/stream_frame.hpp"
#include "imess/sim/card_line_end.hpp"
#include "imess/sim/simulated_cmm.hpp"

namespace {
class StillClock final : public imess::hal::Clock {
 public:
  imess::hal::Nanos now() const noexcept override { return imess::hal::Nanos{1'000'000'000}; }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imess;
  const std::span<const std::uint8_t> bytes(data, size);
  hal::card::StatusFrame status;
  (void)hal::card::read_status(bytes, status);  // the whole input as one status frame
  hal::LinkReader knot_reader(bytes);
  hal::card::Knot knot;
  (void)hal::card::read_knot(knot_reader, knot);

  static StillClock clock;
  static sim::SimulatedCmm cmm(sim::SimulatedCmmConfig{}, clock);
  static bool streaming = [] {
    // Boot, parameters, stream: the card as the driver leaves it after set-up.
    std::array<std::uint8_t, hal::kMaxFrame> reply{};
    hal::LinkWriter w;
    const std::string_view fw = "IMESS-MCU 1.0";
    w.u8(static_cast<std::uint8_t>(hal::card::Op::Boot)).u8(static_cast<std::uint8_t>(fw.size()));
    for (char c : fw) w.u8(static_cast<std::uint8_t>(c));
    cmm.link().transact(w.bytes(), reply);
    w.clear();
    w.u8(static_cast<std::uint8_t>(hal::card::Op::LoadParams)).u8(0);
    hal::card::write_table(w, 7);
    for (int a = 0; a < 3; ++a) w.f64(150).f64(1000).f64(5);
    cmm.link().transact(w.bytes(), reply);
    w.clear();
    w.u8(static_cast<std::uint8_t>(hal::card::Op::StartStream)).u16(5000);
    hal::card::write_table(w, 7);
    return cmm.link().transact(w.bytes(), reply) > 0 && reply[0] == 0;
  }();
  (void)streaming;

  hal::FrameReceiver receiver;
  for (std::uint8_t b : bytes) {
    receiver.feed(b, [&](hal::FrameDecoder::Result r, const hal::FrameDecoder& d) {
      if (r == hal::FrameDecoder::Result::Damaged) return cmm.card().on_damaged_frame();
      (void)hal::card::read_status(d.payload(), status);
      cmm.card().on_stream_frame(d.payload());
      cmm.card().step();
    });
  }

  // The same bytes at the card's end of a line: a set-up frame's reply is a set-up frame. A
  // line end of this input's own (a static one kept a frame begun by the previous input, which
  // this input's request decoder never saw: a false finding, CI of 2026-11-28).
  // The requests are read as the line end reads them (resynchronising: a byte can end more
  // than one frame); its reply answers the last set-up request that byte ended.
  sim::CardLineEnd line_end(cmm.card());
  hal::FrameReceiver request;
  hal::FrameDecoder answer;
  for (std::uint8_t b : bytes) {
    bool setup = false;
    std::uint8_t tag = 0;
    request.feed(b, [&](hal::FrameDecoder::Result r, const hal::FrameDecoder& d) {
      if (r == hal::FrameDecoder::Result::Frame && d.setup() && d.payload().size() >= 2) {
        setup = true;
        tag = d.payload()[0];
      }
    });
    line_end.feed(b);
    if (line_end.reply().empty()) continue;
    if (!setup) __builtin_trap();  // a reply to no set-up request
    hal::FrameDecoder::Result r = hal::FrameDecoder::Result::Pending;
    for (std::uint8_t c : line_end.reply()) r = answer.feed(c);
    if (r != hal::FrameDecoder::Result::Frame || !answer.setup() || answer.payload()[0] != tag)
      __builtin_trap();  // not a set-up frame with the request's tag
  }
  return 0;
}
