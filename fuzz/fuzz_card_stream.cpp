// Fuzz target: the servo card stream's parsers — the frame decoder over arbitrary bytes, the
// driver's status-frame parser and the emulated card's handling of every decoded host frame
// (setpoints, commands) once it streams, and the card's end of a serial line (sim::CardLineEnd:
// set-up frames answered with a set-up frame that must decode with the request's tag). Two
// cards: one with the touch-trigger probe (the 1996 frames) and one with a measuring probe whose
// reading ends every state reply and status frame (LoadParams' analog byte); every status frame
// a card sends must parse as the driver reads it (the deflection included, and only from the
// card that has the measuring probe).
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
  // Boot, parameters, stream: the card as the driver leaves it after set-up.
  auto start = [](sim::SimulatedCmm& cmm, bool analog) {
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
    if (analog) w.u8(1);
    if (cmm.link().transact(w.bytes(), reply) != 1 || reply[0] != 0) __builtin_trap();
    w.clear();
    // A status frame every tick (100 µs): each step below sends one to check.
    w.u8(static_cast<std::uint8_t>(hal::card::Op::StartStream)).u16(100);
    hal::card::write_table(w, 7);
    return cmm.link().transact(w.bytes(), reply) > 0 && reply[0] == 0;
  };
  static sim::SimulatedCmm trigger_cmm(sim::SimulatedCmmConfig{}, clock);
  static sim::SimulatedCmm analog_cmm(
      [] {
        sim::SimulatedCmmConfig c;
        c.mechanics.probe.type = sim::ProbeType::Analog;
        c.mechanics.start[2] = 81.7;  // 0.3 mm into the cube's top: a deflection to report
        return c;
      }(),
      clock);
  static bool streaming = start(trigger_cmm, false) && start(analog_cmm, true);
  (void)streaming;
  sim::SimulatedCmm* const cards[] = {&trigger_cmm, &analog_cmm};
  // A status frame the card sent: the driver's parser must take it whole, the deflection with
  // it exactly when the card has the measuring probe.
  auto check_sent = [&](sim::SimulatedCmm& cmm) {
    std::span<const std::uint8_t> sent;
    if (!cmm.card().take_stream_frame(sent)) return;
    hal::card::StatusFrame back;
    if (!hal::card::read_status(sent, back)) __builtin_trap();
    // (An input's own LoadParams may switch the reading off; only a measuring probe has one.)
    if ((back.flags & hal::card::flag::kDeflection) && (&cmm != &analog_cmm || !(back.probe & hal::card::probe::kAnalogPresent)))
      __builtin_trap();
  };

  for (sim::SimulatedCmm* cmm : cards) {
    hal::FrameReceiver receiver;
    for (std::uint8_t b : bytes) {
      receiver.feed(b, [&](hal::FrameDecoder::Result r, const hal::FrameDecoder& d) {
        if (r == hal::FrameDecoder::Result::Damaged) return cmm->card().on_damaged_frame();
        (void)hal::card::read_status(d.payload(), status);
        cmm->card().on_stream_frame(d.payload());
        cmm->card().step();
        check_sent(*cmm);
      });
    }
    cmm->card().step();  // the state after the last frame
    check_sent(*cmm);

    // The same bytes at the card's end of a line: a set-up frame's reply is a set-up frame. A
    // line end of this input's own (a static one kept a frame begun by the previous input, which
    // this input's request decoder never saw: a false finding, CI of 2026-11-28).
    // The requests are read as the line end reads them (resynchronising: a byte can end more
    // than one frame); its reply answers the last set-up request that byte ended.
    sim::CardLineEnd line_end(cmm->card());
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
  }
  return 0;
}
