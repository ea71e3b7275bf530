// SerialCardLink against messcard on a pseudo-terminal, in real time: set-up over a lossy line
// retries until it gets through; once streaming, the driver's real-time calls and the link's
// I/O thread allocate nothing (counted by replacing the global allocator).
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include "imess/hal/serial_card_link.hpp"
#include "imess/hal/serial_line.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "messcard_process.hpp"

#include "allocation_counter.hpp"

using namespace imess;
using namespace imess::test;

TEST_CASE("serial card link: set-up over a line that loses bytes retries and the card starts streaming") {
  // Which bytes are lost depends on the seed: the first seeds whose set-up needed a retry.
  unsigned long retries = 0;
  for (int seed = 1; seed <= 8 && retries == 0; ++seed) {
    MesscardProcess card({"--drop", "0.005", "--seed", std::to_string(seed)});
    hal::SerialCardLink link({card.tty(), 115200});
    hal::ServoCardConfig cfg;
    hal::ServoCardDriver drv(link, cfg, &link);
    REQUIRE_NOTHROW(drv.initialise(false));
    CHECK(drv.stream() != nullptr);
    const auto n = link.counters();
    std::printf("serial card link: --drop 0.005 --seed %d: set-up needed %lu retries; %lu frames damaged\n", seed,
                n.setup_retries, n.damaged);
    retries = n.setup_retries;
  }
  CHECK(retries >= 1);
}

TEST_CASE("serial card link: a device that is missing, or no tty, is refused naming it") {
  try {
    hal::SerialCardLink link({"/nonexistent/tty", 115200});
    FAIL("opened");
  } catch (const hal::SerialLineError& e) {
    CHECK(e.kind() == hal::SerialLineError::Kind::Missing);
    CHECK(e.configuration());
    CHECK_THAT(e.what(), Catch::Contains("/nonexistent/tty"));
  }
  try {
    hal::SerialCardLink link({"/dev/null", 115200});
    FAIL("opened");
  } catch (const hal::SerialLineError& e) {
    CHECK(e.kind() == hal::SerialLineError::Kind::NotATty);
  }
  MesscardProcess card;
  hal::SerialCardLink first({card.tty(), 115200});
  try {
    hal::SerialCardLink second({card.tty(), 115200});
    FAIL("opened twice");
  } catch (const hal::SerialLineError& e) {
    CHECK(e.kind() == hal::SerialLineError::Kind::Busy);
    CHECK_FALSE(e.configuration());
  }
  CHECK_THROWS_AS(hal::SerialCardLink({card.tty(), 12345}), hal::SerialLineError);
}

TEST_CASE("serial card link: streaming, the driver's real-time calls and the I/O thread allocate nothing") {
  MesscardProcess card;
  hal::SerialCardLink link({card.tty(), 115200});
  hal::ServoCardConfig cfg;
  hal::ServoCardDriver drv(link, cfg, &link);
  drv.initialise(false);
  hal::MachineState ms;
  REQUIRE(drv.read_state(ms));
  hal::Setpoint sp;
  for (int a = 0; a < 3; ++a) sp.position[a] = ms.position[a];
  hal::AxisArray<hal::AxisMove> moves{};
  moves[0] = {ms.position[0] - 5, 50, 500};
  hal::AxisVec latched = hal::AxisVec::Zero();
  long failures = 0;
  double v = 0;
  auto next = std::chrono::steady_clock::now();
  g_allocations = 0;
  g_counting = true;
  if (!drv.set_loops(true)) ++failures;
  for (int i = 0; i < 2000; ++i) {
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
    if (!drv.read_state(ms)) ++failures;
    if (ms.latch_valid() && !drv.read_latch(latched)) ++failures;
    if (i < 800) {  // a path along X: setpoints out, status frames in
      v = std::min(30.0, v + 0.5);
      sp.position[0] += v * 0.001;
      sp.velocity[0] = v;
      if (!drv.follow(sp)) ++failures;
    }
    if (i == 800 && !drv.stop(hal::AxisVec::Constant(1000))) ++failures;
    if (i == 1200 && !drv.move(moves, 1u)) ++failures;
    if (i % 500 == 0 && !drv.set_output(1, (i / 500) % 2 == 1)) ++failures;
    if (i == 1800 && (!drv.set_position(0, 100) || !drv.reset_faults())) ++failures;
    (void)drv.link_errors();
  }
  g_counting = false;
  std::printf("serial card link: 2000 cycles: %ld allocations, %ld failed calls (late wake-ups on a busy host), "
              "%lu frames out, %lu status frames, %lu link errors\n",
              g_allocations.load(), failures, drv.stream()->frames_sent(), drv.stream()->status_frames(), drv.link_errors());
  std::printf("serial card link: %lu frames in, %lu damaged, %lu bytes in, %lu out\n", link.counters().frames_in,
              link.counters().damaged, link.counters().bytes_in, link.counters().bytes_out);
  CHECK(g_allocations.load() == 0);
  CHECK(drv.stream()->frames_sent() > 200);
  CHECK(drv.stream()->status_frames() > 300);
}

TEST_CASE("serial card link: a damaged length byte costs one frame, the frames behind it are found again") {
  // A pseudo-terminal of the test's own: the test writes what a card would send.
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  REQUIRE(master >= 0);
  REQUIRE(grantpt(master) == 0);
  REQUIRE(unlockpt(master) == 0);
  hal::SerialCardLink link({ptsname(master), 115200});
  std::vector<std::uint8_t> line;
  const auto frame = [&](std::uint8_t first, std::size_t n) {
    std::vector<std::uint8_t> payload(n, 0x11);
    payload[0] = first;
    std::array<std::uint8_t, hal::kMaxWireFrame> wire{};
    const std::size_t len = hal::encode_frame(payload, wire);
    return std::vector<std::uint8_t>(wire.begin(), wire.begin() + static_cast<long>(len));
  };
  auto damaged = frame(1, 43);
  damaged[1] = 0xF0;  // the length byte: 240 instead of 43, so the decoder would wait for the next frames' bytes
  for (auto f : {damaged, frame(2, 43), frame(3, 43), frame(4, 43)}) line.insert(line.end(), f.begin(), f.end());
  REQUIRE(write(master, line.data(), line.size()) == static_cast<ssize_t>(line.size()));
  std::vector<int> got;  // first byte of each frame, -1 for a damaged one
  std::array<std::uint8_t, hal::kMaxPayload> buf{};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (got.size() < 4 && std::chrono::steady_clock::now() < deadline) {
    const int n = link.poll(buf);
    if (n == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    else got.push_back(n < 0 ? -1 : buf[0]);
  }
  CHECK(got == std::vector<int>{-1, 2, 3, 4});
  CHECK(link.counters().damaged == 1);
  close(master);
}
