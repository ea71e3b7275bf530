// The I++ DME server's connection and transaction rules: one client at a time, CR LF lines,
// Ack on receipt, the normal queue run in order (one command at a time), the fast queue
// answered at once, the error state and 0514, the session, and who controls the machine.
// Rules and choices: docs/ippdme.md, "Server".
#include <spdlog/spdlog.h>

#include "imess/net/ipp_server.hpp"
#include "imess/net/server_config.hpp"

namespace imess::net {

namespace asio = boost::asio;
using asio::ip::tcp;
using ippdme::ErrorCode;
using ippdme::Tag;

namespace {
// Commands in the normal queue; beyond it a command's Ack waits until there is room (the
// spec's flow control). The server reads on — an AbortE or the client's drop must be seen
// while a move runs — and holds unacknowledged commands up to kMaxUnackedBytes (a client
// that waits for each Ack, as the spec asks, never gets near it); beyond that it stops reading.
constexpr std::size_t kMaxQueued = 64;
constexpr std::size_t kMaxUnackedBytes = 1u << 20;
constexpr const char* kControllerName = "ippdme";
}  // namespace

struct IppTransactions::Connection {
  explicit Connection(tcp::socket s) : socket(std::move(s)) {
    boost::system::error_code ec;
    const auto ep = socket.remote_endpoint(ec);
    if (!ec) address = ep.address();
    socket.set_option(tcp::no_delay(true), ec);
  }
  tcp::socket socket;
  asio::ip::address address;
  ippdme::LineFramer framer;
  std::array<char, 4096> buffer{};
  std::deque<std::string> out;
  std::size_t out_bytes = 0;
  bool writing = false, reading = false;
  bool broken = false;  // dropped: nothing more is sent; closed() runs from the io loop
};

namespace {
ippdme::ToolBox make_tools(const IppConfig& config, double tip_radius, const ippdme::Range (&ranges)[ippdme::kParamCount]) {
  std::vector<ippdme::ToolSpec> specs;
  auto one = [&](std::string name, double radius) {
    ippdme::ToolSpec t;
    t.name = std::move(name);
    t.radius = radius;
    for (int p = 0; p < ippdme::kParamCount; ++p) t.params[p] = ranges[p];
    specs.push_back(std::move(t));
  };
  for (const auto& t : config.tools) one(t.name, t.radius.value_or(tip_radius));
  if (specs.empty()) one("RefTool", tip_radius);
  return ippdme::ToolBox(std::move(specs));
}
}  // namespace

IppTransactions::IppTransactions(asio::io_context& io, const HostList& hosts, IppConfig config)
    : io_(io), hosts_(hosts), config_(std::move(config)), acceptor_(io) {}

IppServer::IppServer(asio::io_context& io, IppServices services, IppConfig config)
    : IppTransactions(io, services.hosts, std::move(config)),
      gateway_(services.gateway),
      control_(services.control),
      frames_(services.frames),
      programs_(services.programs),
      tools_([&] {
        // The ranges every tool's values keep (docs/ippdme.md, "Tools and properties"): speeds
        // up to what every linear axis can do, the machine's one acceleration, the probing
        // distances the MESSD parameters also bound.
        const auto& m = gateway_.machine();
        const auto& p = gateway_.params();
        double vmax = 1e9, amax = 1e9;
        for (int c = 0; c < 3; ++c)
          if (const int a = gateway_.layout().cartesian_axis(c); a >= 0) {
            vmax = std::min(vmax, m.axes[a].max_velocity);
            amax = std::min(amax, m.axes[a].max_accel);
          }
        amax = std::min(amax, p.max_accel);
        const double goto_def = std::min(p.goto_speed * p.speed_level, vmax);
        const ippdme::Range ranges[ippdme::kParamCount] = {
            {0.1, vmax, goto_def},                                        // GoToPar.Speed
            {std::min(1.0, amax), amax, amax},                            // GoToPar.Accel: kept; moves plan with the machine's
            {0.1, std::max(0.1, vmax), std::min(p.probe_speed, vmax)},    // PtMeasPar.Speed
            {std::min(1.0, amax), amax, amax},                            // PtMeasPar.Accel
            {0.1, 100, std::clamp(p.prehit_distance, 0.1, 100.0)},        // Approach
            {0.1, 100, std::clamp(p.search_distance, 0.1, 100.0)},        // Search
            {-1, 100, std::clamp(p.retract_distance, 0.0, 100.0)},        // Retract (< 0: back to the approach point)
            {0.1, std::min(100.0, vmax), std::min(p.scan_speed * p.speed_level, vmax)},  // ScanPar.Speed (the scan's speed range)
            {std::min(1.0, amax), amax, amax},                            // ScanPar.Accel
            {0, 100, std::max(p.prehit_distance, 2.0)},                   // ScanPar.Retract: off the surface at the end (at least 2 mm)
        };
        return make_tools(config_, p.tip_radius, ranges);
      }()) {}

void IppServer::start(const std::string& listen) {
  port_ = open_listener(acceptor_, listen, config_.port, " for I++ DME",
                        " - is another messd running? (--ippdme-port chooses another, 0 turns it off)");
  spdlog::info("I++ DME: listening on {}:{}", listen, port_);
  part_frame_changed();  // PartCsy starts as the controller's active frame
  accept();
}

void IppTransactions::stop() {
  boost::system::error_code ec;
  acceptor_.close(ec);
  if (conn_) conn_->socket.close(ec);
  conn_.reset();
}

void IppTransactions::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) return;
    if (!ec) {
      boost::system::error_code e2;
      const auto peer = socket.remote_endpoint(e2);
      const bool may = !e2 && hosts_.contains(peer.address());
      if (conn_ || !may) {
        // One session drives the machine; a second client, or a host that may not control
        // it (control.hosts), is told so and closed.
        auto s = std::make_shared<tcp::socket>(std::move(socket));
        auto line = std::make_shared<std::string>(ippdme::format_error(ippdme::kServerTag, ErrorCode::ErrorProcessingMethod,
                                                                       conn_ ? "OneSessionAtATime" : "HostNotAllowed"));
        spdlog::info("I++ DME: refused a connection from {} ({})", e2 ? std::string("?") : peer.address().to_string(),
                     conn_ ? "a session is connected" : "host not in control.hosts");
        asio::async_write(*s, asio::buffer(*line), [s, line](boost::system::error_code, std::size_t) {
          boost::system::error_code ignored;
          s->shutdown(tcp::socket::shutdown_both, ignored);
          s->close(ignored);
        });
      } else {
        conn_ = std::make_shared<Connection>(std::move(socket));
        tags_.clear();
        spdlog::info("I++ DME: client {} connected", conn_->address.to_string());
        read();
      }
    }
    accept();
  });
}

void IppTransactions::read() {
  if (!conn_ || conn_->broken || conn_->reading || unacked_bytes_ > kMaxUnackedBytes) return;
  conn_->reading = true;
  auto c = conn_;
  c->socket.async_read_some(asio::buffer(c->buffer), [this, c](boost::system::error_code ec, std::size_t n) {
    c->reading = false;
    if (c != conn_) return;
    if (ec) {
      closed();
      return;
    }
    // A copy: answering a line may start the next read into the same buffer.
    const std::string bytes(c->buffer.data(), n);
    c->framer.feed(bytes, [&](const ippdme::FramedLine& line) {
      if (c == conn_ && !c->broken) guarded("IncomingLine", [&] { on_line(line); });
    });
    read();
  });
}

void IppTransactions::send(std::string bytes) {
  if (!conn_ || conn_->broken) return;
  if (conn_->out_bytes + bytes.size() > config_.max_queue_bytes) {
    // Closed from the io loop, not here: the command being answered is still on the stack.
    spdlog::warn("I++ DME: the client does not read its answers ({} bytes waiting): dropped", conn_->out_bytes);
    conn_->broken = true;
    asio::post(io_, [this, c = conn_] {
      if (c == conn_) closed();
    });
    return;
  }
  conn_->out_bytes += bytes.size();
  conn_->out.push_back(std::move(bytes));
  write();
}

void IppTransactions::write() {
  if (!conn_ || conn_->writing || conn_->out.empty()) return;
  conn_->writing = true;
  auto c = conn_;
  asio::async_write(c->socket, asio::buffer(c->out.front()), [this, c](boost::system::error_code ec, std::size_t) {
    c->writing = false;
    if (c != conn_) return;
    if (ec) {
      closed();
      return;
    }
    c->out_bytes -= c->out.front().size();
    c->out.pop_front();
    write();
  });
}

void IppTransactions::closed() {
  if (!conn_) return;
  spdlog::info("I++ DME: client {} disconnected", conn_->address.to_string());
  auto c = std::move(conn_);
  conn_.reset();
  end_session(true);
  boost::system::error_code ec;
  c->socket.close(ec);
  queue_.clear();
  unacked_.clear();
  unacked_bytes_ = 0;
  running_ = false;
  tags_.clear();
}

// Every line whose tag can be read is acknowledged first (a refused one too: it is answered
// with its error in its turn, so completions stay in the order sent); a line whose tag cannot
// be read, or whose tag is open, is answered on E0000 alone.
void IppTransactions::on_line(const ippdme::FramedLine& line) {
  auto result = ippdme::parse_framed(line);
  Pending p;
  if (const auto* err = std::get_if<ippdme::LineError>(&result)) {
    const Tag tag = ippdme::answer_tag(*err, tags_);
    if (tag == ippdme::kServerTag) {
      send(ippdme::format_error(*err, tags_));
      if (in_session_ && ippdme::enters_error_state(err->code)) enter_error(err->code, err->cause);
      return;
    }
    tags_.try_open(tag);
    p.tag = tag;
    p.refused = std::pair(err->code, err->cause);
  } else {
    auto& req = std::get<ippdme::Request>(result);
    if (!tags_.try_open(req.tag)) {  // reused while open (NIST: 0001 on E0000)
      const std::string_view name = ippdme::method_name(req.command);
      send(ippdme::format_error(ippdme::kServerTag, ErrorCode::IllegalTag, name));
      if (in_session_ && ippdme::enters_error_state(ErrorCode::IllegalTag)) enter_error(ErrorCode::IllegalTag, name);
      return;
    }
    p.tag = req.tag;
    p.command = std::move(req.command);
  }
  if (p.tag.kind == ippdme::TagKind::Event) {
    send(ippdme::format_ack(p.tag));
    execute_fast(p);
    return;
  }
  if (queue_.size() >= kMaxQueued || !unacked_.empty()) {  // no room: the Ack waits
    unacked_bytes_ += line.text.size();
    p.bytes = line.text.size();
    unacked_.push_back(std::move(p));
    return;
  }
  send(ippdme::format_ack(p.tag));
  queue_.push_back(std::move(p));
  pump();
}

std::string_view IppTransactions::cause_of(const Pending& p) {
  return p.refused ? std::string_view(p.refused->second) : ippdme::method_name(p.command);
}

bool IppTransactions::guarded(std::string_view what, const std::function<void()>& f) {
  std::string why;
  try {
    f();
    return true;
  } catch (const std::exception& e) {
    why = e.what();
  } catch (...) {
    why = "an exception of unknown type";
  }
  spdlog::error("I++ DME: an unexpected error in {} ended the session: {}; messd goes on", what, why);
  if (conn_ && !conn_->broken) {
    send(ippdme::format_error(ippdme::kServerTag, ErrorCode::ErrorProcessingMethod, what));
    conn_->broken = true;  // nothing more is sent; closed from the io loop, not under this handler
    asio::post(io_, [this, c = conn_] {
      if (c == conn_) closed();
    });
  }
  return false;
}

// Commands whose Ack waited for room: acknowledged and queued (all of them: `all`, before an
// abort answers every queued command).
void IppTransactions::admit_unacked(bool all) {
  while (!unacked_.empty() && (all || queue_.size() < kMaxQueued)) {
    Pending p = std::move(unacked_.front());
    unacked_.pop_front();
    unacked_bytes_ -= p.bytes;
    send(ippdme::format_ack(p.tag));
    queue_.push_back(std::move(p));
  }
}

// Room is made before every command: also while aborted ones drain (an error admits every
// waiting command at once, so the queue may hold more than kMaxQueued; the Acks still waiting
// behind them come as soon as it has room again, not with the client's next line).
void IppTransactions::pump() {
  for (;;) {
    admit_unacked(false);
    if (running_ || queue_.empty() || !conn_) break;
    running_ = true;
    if (queue_.front().aborted) {
      const Pending p = queue_.front();
      queue_.pop_front();
      running_ = false;
      answer_aborted(p);
      continue;
    }
    if (!run_front()) break;  // a motion step: step_done / step_failed go on
  }
  read();
}

// Runs the queue's front; true when it was answered (it has left the queue), false when it
// started a motion step (or waits for the machine to stand).
bool IppTransactions::run_front() {
  const Pending p = queue_.front();
  bool answered = true;
  if (!guarded(cause_of(p), [&] { answered = execute(p); })) {
    // The session ends (closed from the io loop); nothing of its queue runs any more.
    queue_.clear();
    unacked_.clear();
    unacked_bytes_ = 0;
    running_ = false;
    step_ = Step::None;
    return true;
  }
  if (!answered) return false;
  if (!queue_.empty() && queue_.front().tag == p.tag) queue_.pop_front();
  running_ = false;
  return true;
}

void IppTransactions::answer_aborted(const Pending& p) {
  send(ippdme::format_error(p.tag, ErrorCode::TransactionAborted, cause_of(p)));
  finish(p.tag);
}

void IppTransactions::finish(const Tag& tag) {
  send(ippdme::format_done(tag));
  tags_.close(tag);
}

void IppTransactions::fail(const Tag& tag, ErrorCode code, std::string_view cause) {
  send(ippdme::format_error(tag, code, cause));
  finish(tag);
  // Outside a session there is no error state to enter (StartSession would clear it).
  if (ippdme::enters_error_state(code, cause) && in_session_ && !error_state_) enter_error(code, cause);
}

void IppTransactions::enter_error(ErrorCode code, std::string_view cause) {
  if (!error_state_) last_error_ = std::pair(code, std::string(cause));
  error_state_ = true;
  abort_queued();
}

// Every transaction waiting behind the running one: 0006 and its `%`, in the order sent —
// at once when nothing runs, else each when its turn comes, so no `%` overtakes the running
// command's (completions in the order started, IPPDME.md §3).
void IppTransactions::abort_queued() {
  admit_unacked(true);
  const bool behind = running_ && !queue_.empty();
  if (behind) {
    for (std::size_t i = 1; i < queue_.size(); ++i) queue_[i].aborted = true;
    return;
  }
  std::deque<Pending> waiting;
  waiting.swap(queue_);
  for (const auto& p : waiting) answer_aborted(p);
}

// The machine's owner is the session: kept, taken when free, or taken back from the operator
// it was handed to (EnableUser; a jog of theirs is stopped first). Taken over from a MESSD
// client only at StartSession and only while the machine stands (`at_start`). False (why
// says) otherwise — e.g. an operator took it with Take force and has not released it.
bool IppServer::claim_control(bool at_start, std::string& why) {
  auto& control = control_;
  if (control.owns(kClientId)) return true;
  const Controller me{kClientId, kControllerName, conn_ ? conn_->address.to_string() : std::string("?")};
  if (!control.owner()) {
    control.claim(me, true);  // announced
    return true;
  }
  const auto& snap = gateway_.snapshot();
  const bool standing = (snap.mode == core::Mode::Idle || snap.mode == core::Mode::Free) && !gateway_.planning() &&
                        !gateway_.loop_holds_segments() && !programs_.running();
  if (!user_enabled_ && !(at_start && standing)) {
    if (control.claim(me, true) == ControlOutcome::HandedOver) return true;  // an idle owner hands over, as to anyone
    why = "the machine is controlled by " + describe(*control.owner());
    return false;
  }
  if (!standing) gateway_.stop("I++ DME session takes control");
  control.take_over(me);  // the one who had it is warned, everyone told
  return true;
}

void IppServer::release_control() {
  if (!control_.release(kClientId)) return;
  control_.announce();
}

// EndSession or the connection gone: what the session moves stops, daemons end, the
// machine's control is given back. Tools and coordinate systems stay for the next session.
void IppServer::end_session(bool dropped) {
  const bool owns = control_.owns(kClientId);
  const bool moving = step_ != Step::None;
  step_ = Step::None;
  if (owns && (moving || gateway_.planning() || gateway_.loop_holds_segments()))
    gateway_.stop(dropped ? "I++ DME client disconnected" : "EndSession");
  if (daemon_) tags_.close(daemon_->tag);
  daemon_.reset();
  release_control();
  in_session_ = false;
  user_enabled_ = false;
  error_state_ = false;
  last_error_.reset();
  rest_.reset();
}

}  // namespace imess::net
