// The io side put together: the services and front ends built and wired, the event drain's
// wake-up and backstop, the periodic debug log.
#include "imess/net/server.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace imess::net {

namespace asio = boost::asio;

Server::Server(asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
               journal::Journal& journal, core::EventFd* wake)
    : io_(io),
      config_(std::move(config)),
      journal_(journal),
      wake_(wake),
      gateway_(io, core, observers_, log_limiter_, config_.log_motion),
      frames_(observers_, log_limiter_),
      programs_(gateway_, config_.programs, frames_, log_limiter_,
                [this](const std::string& line) { sessions_.broadcast(line); }),
      control_(gateway_, programs_, observers_, log_limiter_, config_.control.handover_s),
      hits_(journal, observers_, config_.probe_offset, {config_.log_motion, config_.beep}),
      sessions_(io, config_, log_limiter_),
      stream_(io, config_, gateway_, sessions_,
              [this] {
                programs_.show_block(false);
                move_reports();
              }),
      liveness_(io, config_, sessions_, control_, gateway_, journal, log_limiter_),
      stats_(io, runner, sessions_, [this] { return gateway_.snapshot().link_errors; }),
      frame_verbs_(sessions_, frames_, gateway_, journal, log_limiter_),
      events_(sessions_, gateway_, frames_, log_limiter_, config_.log_motion),
      dispatch_(config_, {sessions_, gateway_, control_, hits_, programs_, frame_verbs_, stream_, stats_, observers_, log_limiter_}),
      event_timer_(io),
      log_timer_(io) {
  sessions_.set_handlers({[this](Session& s, const protocol::FramedLine& l) {
                            dispatch_.on_line(s, l);
                            liveness_.arm_housekeeping();  // a Watch, a new owner, a hit to sync: each may bring a deadline
                          },
                          [this](Session& s) { stream_.connected(s); }, [this](Session& s) { dispatch_.gone(s); }});
}

void Server::start() {
  frames_.open(config_.frames_file);  // a store that does not load is a start-up error naming it
  sessions_.start();
  const auto& layout = gateway_.layout();
  if (config_.ippdme.on) {
    if (layout.cartesian_axis(0) >= 0 && layout.cartesian_axis(1) >= 0 && layout.cartesian_axis(2) >= 0) {
      ipp_ = std::make_unique<IppServer>(io_, IppServices{gateway_, control_, frames_, programs_, config_.control.hosts},
                                         config_.ippdme);
      ipp_->start(config_.listen);
      ipp_events_ = std::make_unique<IppEvents>(*ipp_, gateway_);
    } else {
      spdlog::info("I++ DME: off, this machine has no linear X Y Z axes (axes {})", layout.names());
    }
  }
  if (config_.web.on) {
    web_ = std::make_unique<WebServer>(io_, config_, sessions_, log_limiter_, &programs_);
    web_->start();
  }
  add_observers();
  running_ = true;
  if (wake_) {
    int fd = ::dup(wake_->fd());  // the descriptor object closes its own copy
    if (fd < 0) throw std::runtime_error("cannot duplicate the event descriptor: " + std::string(std::strerror(errno)));
    wake_wait_.emplace(io_, fd);
    wait_for_events();
  }
  // Without an EventFd the timer is the only drain, so it keeps the old millisecond.
  const double drain_ms = wake_ ? config_.event_backstop_ms : 1.0;
  const std::chrono::microseconds drain_every(static_cast<long>(drain_ms * 1000));
  event_timer_.start(drain_every, [drain_every] { return drain_every; }, [this] { backstop_events(); });
  liveness_.start();
  stream_.start();
  if (config_.log_status || config_.log_timing) {
    const std::chrono::microseconds every = std::chrono::seconds(5);
    log_timer_.start(every, [every] { return every; }, [this] { log_periodic(); });
  }
}

// The order every fan-out follows: the journal first (HitService), then the MESSD clients'
// lines (MessdEvents, also the owner of the queued ids nobody else claims), the housekeeping
// a hit may arm, the I++ DME session, the program, the position stream.
void Server::add_observers() {
  observers_.add(hits_);
  observers_.add(events_);
  observers_.set_fallback(events_);
  observers_.add(liveness_);
  if (ipp_events_) observers_.add(*ipp_events_);
  observers_.add(programs_);
  observers_.add(stream_);
}

void Server::stop() {
  running_ = false;
  if (ipp_) ipp_->stop();
  if (web_) web_->stop();
  event_timer_.cancel();
  liveness_.stop();
  boost::system::error_code ec;
  if (wake_wait_) wake_wait_->close(ec);
  stream_.stop();
  log_timer_.cancel();
  sessions_.stop();
}

void Server::move_reports() {
  observers_.each("MoveReport", [](MotionObserver& o) { o.move_report(); });
}

void Server::wait_for_events() {
  wake_wait_->async_wait(boost::asio::posix::stream_descriptor::wait_read, [this](boost::system::error_code ec) {
    if (ec || !running_) return;
    wake_->drain();  // before the drain: a notify after this point wakes us again
    ++woken_;
    gateway_.pump_events();
    wait_for_events();
  });
}

void Server::backstop_events() {
  if (gateway_.pump_events() > 0) ++backstop_found_;  // a wake-up was missed (or none is wired)
}

void Server::log_periodic() {
  const auto& snap = gateway_.snapshot();
  if (config_.log_status)
    spdlog::info("status X {:#07x} Y {:#07x} Z {:#07x} inputs {:#04x} {:#04x} {:#04x} hw errors {} events dropped {}",
                 snap.status[0], snap.status[1], snap.status[2], snap.inputs[0], snap.inputs[1], snap.inputs[2],
                 snap.hardware_errors, snap.events_dropped);
  if (config_.log_timing) spdlog::info("loop: {}", stats_.stats_line());
  if (config_.log_timing)
    spdlog::info("io: {} wake-ups, {} times the {:g} ms backstop found events first", woken_, backstop_found_,
                 config_.event_backstop_ms);
}

}  // namespace imess::net
