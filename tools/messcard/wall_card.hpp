// WallCard: the emulated card on a real line in real time. Its firmware ticks at 10 kHz by the
// steady clock (ticks caught up after the thread overslept); bytes cross the line at the baud
// rate each way (a sim::SerialChannel per direction, in wall-clock seconds) and may be dropped
// or corrupted on the way; a stall stops the card answering for a while; pull() is the cable
// pulled: the line goes, the firmware runs on until its watchdog has braked.
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "imess/sim/card_line_end.hpp"
#include "imess/sim/emulated_card.hpp"
#include "imess/sim/mechanics.hpp"
#include "imess/sim/serial_channel.hpp"
#include "imess/sim/simulated_cmm.hpp"

namespace imess::messcard {

struct Faults {
  double drop = 0, corrupt = 0;  // per byte
  double from_s = 0;             // from this long after the stream started (0: from the start)
  double stall_s = 0, stall_at_s = 1;
  unsigned seed = 1;
};

class WallCard {
 public:
  WallCard(const sim::SimulatedCmmConfig& machine, int fd, double baud, Faults faults);
  // Runs until stop() is true; then the cable is pulled and run() returns once the card rests.
  template <class Stop>
  void run(Stop&& stop) {
    while (!stop()) step();
    pull();
  }
  void stall_now() noexcept { stall_request_ = true; }
  void faults_now() noexcept { faults_request_ = true; }

 private:
  void step();  // one pass: read, tick up to now, write, sleep
  void pull();
  double now() const;
  void tick(double at);
  void from_host(const std::uint8_t* bytes, std::size_t n, double at);
  void to_host(std::span<const std::uint8_t> bytes, double at);
  bool fault(double rate) { return rate > 0 && faulty_ && uniform_(rng_) < rate; }
  void report();  // what the card did that people should see (watchdog, damaged frames)

  sim::Mechanics mechanics_;
  sim::EmulatedCard card_;
  sim::CardLineEnd line_end_;
  int fd_;
  double baud_;
  Faults faults_;
  sim::SerialChannel rx_, tx_;  // host → card, card → host
  std::vector<std::uint8_t> out_;  // arrived at the host's end, not yet written
  std::mt19937 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  long long t0_ns_ = 0;
  long ticks_ = 0;
  bool streaming_ = false;
  bool faulty_ = false;  // the line damages and loses bytes (from the start, or from --faults-at-ms)
  double stream_at_ = 0;
  bool stalled_ = false, stall_done_ = false, stall_request_ = false, faults_request_ = false;
  double stall_until_ = 0;
  unsigned long starvations_ = 0, damaged_ = 0, dropped_ = 0, corrupted_ = 0;
  std::uint32_t last_faults_ = 0;
};

}  // namespace imess::messcard
