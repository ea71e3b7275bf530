// The card's real-time loop: read, tick, write, sleep; faults on the bytes; the cable pulled.
#include "wall_card.hpp"

#include <poll.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>

namespace imess::messcard {

namespace {
constexpr long kSleepNs = 500'000;  // the loop wakes every 0.5 ms; ticks missed meanwhile are caught up

long long monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}
}  // namespace

WallCard::WallCard(const sim::SimulatedCmmConfig& machine, int fd, double baud, Faults faults)
    : mechanics_(machine.mechanics, machine.scene),
      card_(machine.card, mechanics_),
      line_end_(card_),
      fd_(fd),
      baud_(baud),
      faults_(faults),
      rx_(baud),
      tx_(baud),
      rng_(faults.seed) {
  rx_.set_patience(1e9);
  tx_.set_patience(1e9);
  t0_ns_ = monotonic_ns();
  faulty_ = faults.from_s <= 0;
  card_.advance_to(0);
}

double WallCard::now() const { return static_cast<double>(monotonic_ns() - t0_ns_) * 1e-9; }

// Bytes the host sent, put on the line towards the card (some lost or damaged on the way).
void WallCard::from_host(const std::uint8_t* bytes, std::size_t n, double at) {
  std::array<std::uint8_t, 512> kept{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < n && k < kept.size(); ++i) {
    if (fault(faults_.drop)) {
      ++dropped_;
      continue;
    }
    std::uint8_t b = bytes[i];
    if (fault(faults_.corrupt)) {
      b ^= static_cast<std::uint8_t>(1u << (rng_() % 8));
      ++corrupted_;
    }
    kept[k++] = b;
  }
  if (k > 0) rx_.push(std::span<const std::uint8_t>(kept.data(), k), at);
}

// Bytes the card sends, put on the line towards the host (the same faults).
void WallCard::to_host(std::span<const std::uint8_t> bytes, double at) {
  std::array<std::uint8_t, hal::kMaxWireFrame> kept{};
  std::size_t k = 0;
  for (std::uint8_t b : bytes) {
    if (fault(faults_.drop)) {
      ++dropped_;
      continue;
    }
    if (fault(faults_.corrupt)) {
      b ^= static_cast<std::uint8_t>(1u << (rng_() % 8));
      ++corrupted_;
    }
    kept[k++] = b;
  }
  if (k > 0) tx_.push(std::span<const std::uint8_t>(kept.data(), k), at);
}

// One firmware tick at card time `at`: the bytes that arrived by then, the tick, its output.
void WallCard::tick(double at) {
  rx_.deliver(at, [&](std::uint8_t b) {
    line_end_.feed(b);
    if (!line_end_.reply().empty() && !stalled_) to_host(line_end_.reply(), at);
  });
  card_.step();
  const auto status = line_end_.take_status();
  if (status.empty()) return;
  if (!streaming_) {
    streaming_ = true;
    stream_at_ = at;
  }
  if (!stalled_) to_host(status, at);
}

void WallCard::report() {
  if (card_.starvations() != starvations_) {
    starvations_ = card_.starvations();
    std::printf("messcard: watchdog: the setpoints stopped coming; the axes braked (starvation %lu)\n", starvations_);
    std::fflush(stdout);
  }
  if (line_end_.damaged() != damaged_) {
    damaged_ = line_end_.damaged();
    std::printf("messcard: a damaged frame from the host (%lu so far); the frames after the last one taken are asked for again\n",
                damaged_);
    std::fflush(stdout);
  }
}

void WallCard::step() {
  const double t = now();
  // The stall: once, a while after the stream started, or when asked (SIGUSR1).
  if (!stalled_ && !stall_done_ && faults_.stall_s > 0 &&
      (stall_request_ || (streaming_ && t >= stream_at_ + faults_.stall_at_s))) {
    stalled_ = true;
    stall_until_ = t + faults_.stall_s;
    std::printf("messcard: stalled: not answering for %.0f ms\n", faults_.stall_s * 1e3);
    std::fflush(stdout);
  }
  if (!faulty_ && (faults_request_ || (streaming_ && t >= stream_at_ + faults_.from_s))) {
    faulty_ = true;
    if (faults_.drop > 0 || faults_.corrupt > 0) {
      std::printf("messcard: the line loses %g and damages %g of its bytes from now on\n", faults_.drop, faults_.corrupt);
      std::fflush(stdout);
    }
  }
  if (stalled_ && t >= stall_until_) {
    stalled_ = false;
    stall_done_ = true;
    std::printf("messcard: answering again\n");
    std::fflush(stdout);
  }
  if (!stalled_ && fd_ >= 0) {
    std::array<std::uint8_t, 512> in{};
    for (;;) {
      const ssize_t n = ::read(fd_, in.data(), in.size());
      if (n <= 0) break;
      from_host(in.data(), static_cast<std::size_t>(n), t);
    }
  }
  const double dt = card_.tick_period();
  while (static_cast<double>(ticks_ + 1) * dt <= t) tick(static_cast<double>(++ticks_) * dt);
  report();
  tx_.deliver(t, [&](std::uint8_t b) { out_.push_back(b); });
  if (fd_ >= 0 && !out_.empty()) {
    const ssize_t n = ::write(fd_, out_.data(), out_.size());
    if (n > 0) out_.erase(out_.begin(), out_.begin() + n);
    if (out_.size() > 65536) out_.clear();  // nobody reads the line: what a UART would lose
  }
  const timespec ts{0, kSleepNs};
  clock_nanosleep(CLOCK_MONOTONIC, 0, &ts, nullptr);
}

// The cable pulled: nothing goes in or out any more; the firmware runs on (its watchdog
// brakes a path that stops getting setpoints) until the axes rest, at most 2 s.
void WallCard::pull() {
  fd_ = -1;
  std::printf("messcard: the cable is pulled\n");
  std::fflush(stdout);
  const double t_pull = now();
  double still_since = -1;
  for (;;) {
    const double t = now();
    const double dt = card_.tick_period();
    while (static_cast<double>(ticks_ + 1) * dt <= t) tick(static_cast<double>(++ticks_) * dt);
    report();
    bool still = true;
    for (int a = 0; a < hal::card::kAxes; ++a) still = still && std::abs(mechanics_.velocity(a)) < 1e-3;
    if (!still) still_since = -1;
    else if (still_since < 0) still_since = t;
    if ((still_since >= 0 && t - still_since > 0.05) || t - t_pull > 2) break;
    const timespec ts{0, kSleepNs};
    clock_nanosleep(CLOCK_MONOTONIC, 0, &ts, nullptr);
  }
  const auto& p = mechanics_.carriage();
  std::printf("messcard: card at rest %.0f ms after the cable was pulled, at X %.4f Y %.4f Z %.4f; %lu watchdog "
              "stops, %lu damaged host frames, %lu bytes dropped and %lu corrupted on the line\n",
              (now() - t_pull) * 1e3, p[0], p[1], p[2], starvations_, damaged_, dropped_, corrupted_);
  std::fflush(stdout);
}

}  // namespace imess::messcard
