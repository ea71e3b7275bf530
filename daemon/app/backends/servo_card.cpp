// "servo-card": the real servo-card driver streaming to a card on a serial device
// (backend.device, or messd --device; a USB-serial adapter, a UART, or messcard's
// pseudo-terminal). A SerialCardLink's I/O thread does the reading and writing; a keeper
// thread re-boots the card when Reset finds it came back after it was gone.
#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "imess/hal/serial_card_link.hpp"
#include "imess/hal/serial_line.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "json_object.hpp"

namespace imess::app {

namespace {

constexpr int kLinkPriority = 82;  // SCHED_FIFO for the link's I/O thread, above the motion loop's 80 and messcard's 75: short bursts that must not wait behind them

// The link, its errors as messd reports them: a device that is missing or no tty is the
// configuration's fault (exit 2), one that is busy is not (exit 1).
std::unique_ptr<hal::SerialCardLink> open_card_line(const DaemonConfig& cfg) {
  hal::SerialLinkSettings line = cfg.card_line;
  line.realtime_priority = cfg.realtime ? kLinkPriority : 0;
  if (line.device.empty())
    throw ConfigError("servo-card: backend.device is missing: give the card's serial device (such as \"/dev/ttyIMESS0\" "
                      "or \"/dev/ttyUSB0\") or messd --device PATH");
  try {
    return std::make_unique<hal::SerialCardLink>(line);
  } catch (const hal::SerialLineError& e) {
    if (e.configuration()) throw ConfigError(std::string("servo-card: ") + e.what());
    throw std::runtime_error(std::string("servo-card: ") + e.what());
  }
}

hal::ServoCardConfig card_config(const DaemonConfig& cfg) {
  hal::ServoCardConfig c = cfg.card;
  c.stream.baud = cfg.card_line.baud;
  // Two programs (or a program and a card) on a loaded host: a status frame may come 30 ms
  // late without the card being gone (a tty's bytes are moved by the kernel's worker threads,
  // which run time-shared: behind a build they wait). 40 periods keep CommLost within 45 ms of
  // the last status frame, inside the 50 ms a pulled cable must take at most.
  c.stream.timeout_cycles = 40;
  c.reboot_on_reset = true;
  return c;
}

class ServoCardMachine final : public Machine {
 public:
  ServoCardMachine(const DaemonConfig& cfg, const hal::Clock&)
      : line_(open_card_line(cfg)), driver_(*line_, card_config(cfg), line_.get()) {}
  ~ServoCardMachine() override { stop_base_thread(); }
  void initialise(bool force_reboot) { driver_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return driver_; }
  hal::SimHooks* sim_hooks() override { return nullptr; }
  std::string describe() const override {
    return driver_.describe() + " on " + line_->settings().device + " at " + std::to_string(line_->settings().baud) +
           " baud, streamed";
  }
  // The keeper: runs a re-boot the motion loop asked for (Reset after the card was gone).
  std::string start_base_thread(bool) override {
    keeper_ = std::thread([this] { keep(); });
    return "servo card: link I/O thread on " + line_->settings().device +
           (line_->counters().realtime ? " (SCHED_FIFO " + std::to_string(kLinkPriority) + ")" : " (time-shared)") +
           "; re-boot on Reset when the card was gone";
  }
  void stop_base_thread() override {
    stop_ = true;
    if (keeper_.joinable()) keeper_.join();
  }

 private:
  void keep() {
    while (!stop_) {
      if (driver_.reboot_wanted()) {
        spdlog::info("servo card: Reset after the card was gone: re-booting it on {}", line_->settings().device);
        const std::string failure = driver_.reboot();
        if (failure.empty())
          spdlog::info("servo card: {} is back and streaming", driver_.describe());
        else
          spdlog::error("servo card: re-boot failed ({}); CommLost until the next Reset", failure);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

  std::unique_ptr<hal::SerialCardLink> line_;
  hal::ServoCardDriver driver_;
  std::thread keeper_;
  std::atomic<bool> stop_{false};
};

void load(JsonObject& b, DaemonConfig& cfg) {
  read_card_keys(b, cfg);
  cfg.card_line.device = b.text("device", cfg.card_line.device);
  const double baud = b.number("baud", cfg.card_line.baud, 9600, 4e6);
  if (!hal::serial_baud_supported(static_cast<int>(baud)) || baud != static_cast<int>(baud))
    b.fail("baud", std::string("a rate a serial line can be set to (") + hal::serial_bauds_text() + ")");
  cfg.card_line.baud = static_cast<int>(baud);
  cfg.card.stream.baud = baud;
}

}  // namespace

const BackendType& servo_card_backend() {
  static const BackendType kType{"servo-card", "the servo card on a serial device, streamed", false, false, load, nullptr,
                                 build_machine<ServoCardMachine>, true};
  return kType;
}

}  // namespace imess::app
