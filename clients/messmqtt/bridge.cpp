// messmqtt's loop (bridge.hpp).
#include "bridge.hpp"

#include <poll.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "broker_input.hpp"
#include "imess/client/stop_signal.hpp"
#include "payloads.hpp"
#include "seq_file.hpp"

namespace imess::mqtt {

namespace {

constexpr auto kStateInterval = std::chrono::milliseconds{500};  // imess/<machine>/state: at most 2 Hz
constexpr auto kSaveInterval = std::chrono::milliseconds{100};
constexpr std::size_t kMaxRequests = 8;  // broker replay requests answered at once

std::string now_text() { return iso_utc(std::chrono::system_clock::now()); }

std::uint64_t to_u64(std::string_view s) {
  std::uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') break;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return v;
}

// "Ok Replay <count> <newest>"
bool replay_counts(std::string_view reply, std::uint64_t& count, std::uint64_t& newest) {
  constexpr std::string_view prefix = "Ok Replay ";
  if (reply.substr(0, prefix.size()) != prefix) return false;
  reply.remove_prefix(prefix.size());
  const auto space = reply.find(' ');
  if (space == std::string_view::npos) return false;
  count = to_u64(reply.substr(0, space));
  newest = to_u64(reply.substr(space + 1));
  return true;
}

// "Err 212 hit 5 is no longer in the journal; the oldest kept is 1001": the last word.
std::uint64_t oldest_kept(std::string_view reply) {
  const auto space = reply.rfind(' ');
  return space == std::string_view::npos ? 0 : to_u64(reply.substr(space + 1));
}

}  // namespace

Bridge::Bridge(BridgeConfig cfg, std::string password, std::uint64_t acked)
    : cfg_(std::move(cfg)),
      topics_(cfg_.machine),
      tracker_(acked),
      broker_(LinkOptions{cfg_.broker.host, cfg_.broker.port, "messmqtt-" + cfg_.machine, cfg_.user, std::move(password),
                          cfg_.tls_ca, topics_.online, online_payload(cfg_.machine, false, false, ""), 10,
                          std::chrono::milliseconds{500}},
              LinkHandlers{[this] { broker_connected(); },
                           [this](const std::string& why) {
                             if (why == last_broker_error_) return;
                             last_broker_error_ = why;
                             log("broker " + cfg_.broker.to_string() + ": " + why + "; trying again every 0.5 s");
                           },
                           [this](int mid) { tracker_.acknowledged(mid); },
                           [this](std::string_view t, std::string_view p, bool r) { broker_message(t, p, r); }}),
      messd_(cfg_.messd, MessdSide::Handlers{[this] { messd_connected(); },
                                             [this](const std::string& why) { messd_lost(why); },
                                             [this](std::string_view l) { messd_line(l); },
                                             [this](const Command& c, std::string_view r) { messd_replied(c, r); },
                                             [this](std::string_view l) { messd_replay_data(l); }}),
      saved_acked_(acked) {}

void Bridge::log(const std::string& text) const { std::cerr << "messmqtt " << cfg_.machine << ": " << text << std::endl; }

// ---- messd ----

void Bridge::messd_connected() {
  log("connected to messd at " + cfg_.messd.to_string());
  state_.messd = true;
  state_dirty_ = true;
  order_.messd_reconnected();
  order_.catch_up_dropped();
  messd_.send({Command::Kind::Hello, 0, {}});
  messd_.send({Command::Kind::Status, 0, {}});
  messd_.send({Command::Kind::Program, 0, {}});
  publish_online(true);
}

void Bridge::messd_lost(const std::string& why) {
  if (state_.messd) log("messd at " + cfg_.messd.to_string() + ": " + why + "; trying again every 0.5 s");
  state_.messd = false;
  state_dirty_ = true;
  order_.catch_up_dropped();
  for (const auto& r : requests_)
    broker_.publish(topics_.replay_answer(r.reply_to),
                    nlohmann::json{{"machine", cfg_.machine}, {"from", r.from}, {"error", "the link to messd broke; ask again"}}.dump(),
                    1, false);
  requests_.clear();
  publish_online(true);
}

void Bridge::messd_line(std::string_view line) {
  const auto now = now_text();
  auto folded = fold_line(state_, line, now);
  state_dirty_ = state_dirty_ || folded.changed;
  if (folded.event) publish_event(std::move(*folded.event));
  if (line.substr(0, 4) == "Hit ") {
    const auto msg = protocol::parse_message(line);
    if (const auto* hit = std::get_if<protocol::HitMsg>(&msg)) on_hit(*hit);
  }
}

void Bridge::on_hit(const protocol::HitMsg& hit) {
  for (auto& r : requests_)
    if (hit.seq >= r.from) r.hits[hit.seq] = hit;
  if (!broker_.connected()) return;  // published after the broker is back, from the journal
  if (order_.offer(hit.seq) != HitOrder::Offer::Publish) return;
  const int mid = broker_.publish(topics_.hit, hit_payload(cfg_.machine, hit), 1, false);
  if (mid >= 0) {
    tracker_.published(mid, hit.seq);
    ++hits_published_;
  }
}

void Bridge::messd_replay_data(std::string_view line) {
  const auto lost = protocol::parse_replay_lost(line.substr(7));
  if (!lost || messd_.in_flight().empty()) return;
  const auto& c = messd_.in_flight().front();
  if (c.kind == Command::Kind::Request) {
    for (auto& r : requests_)
      if (r.from == c.from && r.reply_to == c.reply_to) {
        r.lost.emplace_back(lost->first, lost->last);
        break;
      }
    return;
  }
  if (c.kind == Command::Kind::CatchUp && broker_.connected() && order_.pass_lost(lost->first, lost->last)) {
    tracker_.skip(lost->first, lost->last);
    log("hits " + std::to_string(lost->first) + " to " + std::to_string(lost->last) +
        " are damaged or missing in messd's journal: they cannot be published (event hits_lost)");
    publish_event({{"type", "hits_lost"}, {"first", lost->first}, {"last", lost->last},
                   {"text", "damaged or missing in the journal"}});
  }
}

void Bridge::messd_replied(const Command& c, std::string_view reply) {
  switch (c.kind) {
    case Command::Kind::Status:
    case Command::Kind::Program: {
      auto folded = fold_line(state_, reply, now_text());
      state_dirty_ = state_dirty_ || folded.changed;
      break;
    }
    case Command::Kind::CatchUp: catch_up_replied(c, reply); break;
    case Command::Kind::Request: request_replied(c, reply); break;
    case Command::Kind::Stop: log("messd answered the stop: " + std::string(reply)); break;
    case Command::Kind::Hello: break;
  }
}

void Bridge::catch_up_replied(const Command& c, std::string_view reply) {
  order_.catch_up_dropped();
  std::uint64_t count = 0, newest = 0;
  if (replay_counts(reply, count, newest)) {
    order_.replay_answered(c.from, count, newest);
    if (broker_.connected() && count == 0 && newest + 1 < order_.next()) {
      log("messd's journal ends at hit " + std::to_string(newest) + ", before the hits the broker has (up to " +
          std::to_string(order_.next() - 1) + "): its numbers are given again (a power cut, or a new journal); "
          "publishing from " + std::to_string(newest + 1));
      publish_event({{"type", "journal_restarted"}, {"newest", newest}, {"published", order_.next() - 1}});
      tracker_.restart_at(newest);
      order_.journal_restarted(newest);
      save(true);
    }
    return;
  }
  if (reply.substr(0, 8) == "Err 212 ") {
    const auto oldest = oldest_kept(reply);
    if (oldest > order_.next()) {
      if (tracker_.acked() > 0)
        log("hits " + std::to_string(order_.next()) + " to " + std::to_string(oldest - 1) +
            " were rotated out of messd's journal before the broker had them (event hits_lost)");
      if (tracker_.acked() > 0)
        publish_event({{"type", "hits_lost"}, {"first", order_.next()}, {"last", oldest - 1},
                       {"text", "rotated out of the journal"}});
      tracker_.skip(order_.next(), oldest - 1);
      order_.rotated_out(oldest);
    }
    return;
  }
  log("messd refused the catch-up '" + std::string(reply) + "'; trying again in 1 s");
  catch_up_not_before_ = Clock::now() + std::chrono::seconds{1};
}

void Bridge::request_replied(const Command& c, std::string_view reply) {
  auto it = std::find_if(requests_.begin(), requests_.end(),
                         [&](const Collect& r) { return r.from == c.from && r.reply_to == c.reply_to; });
  if (it == requests_.end()) return;
  const std::string topic = topics_.replay_answer(it->reply_to);
  nlohmann::json done{{"machine", cfg_.machine}, {"from", it->from}};
  std::uint64_t count = 0, newest = 0;
  if (replay_counts(reply, count, newest)) {
    std::uint64_t sent = 0;
    for (const auto& [seq, hit] : it->hits)
      if (seq < it->from + count) {
        broker_.publish(topic, hit_payload(cfg_.machine, hit), 1, false);
        ++sent;
      }
    done["done"] = true;
    done["count"] = count;
    done["hits"] = sent;
    done["newest"] = newest;
    done["lost"] = it->lost;
    if (it->from + count <= newest) done["next"] = it->from + count;  // ask again from there
  } else {
    done["error"] = std::string(reply.size() > 4 ? reply.substr(4) : reply);  // without "Err "
    if (reply.substr(0, 8) == "Err 212 ") done["oldest"] = oldest_kept(reply);
  }
  broker_.publish(topic, done.dump(), 1, false);
  requests_.erase(it);
}

// ---- broker ----

void Bridge::broker_connected() {
  log("connected to the broker " + cfg_.broker.to_string() + "; publishing hits from " +
      std::to_string(tracker_.acked() + 1));
  last_broker_error_.clear();
  tracker_.connection_lost();  // what was in flight goes again
  order_.start_at(tracker_.acked() + 1);
  order_.catch_up_dropped();   // an answer still coming is harmless: order_ skips nothing on it
  broker_.subscribe(topics_.replay, 1);
  broker_.subscribe(topics_.stop, 1);
  publish_online(true);
  state_dirty_ = true;
  last_state_ = {};
}

void Bridge::broker_message(std::string_view topic, std::string_view payload, bool retained) {
  if (retained) {  // an old message kept by the broker: a stop or request of the past is no order now
    log("ignored a retained message on " + std::string(topic) + " (requests and stops are never acted on when retained)");
    return;
  }
  if (topic == topics_.replay) handle_replay_request(payload);
  if (topic == topics_.stop) handle_stop(payload);
}

void Bridge::handle_replay_request(std::string_view payload) {
  auto parsed = parse_replay_request(payload);
  if (auto* refusal = std::get_if<Refusal>(&parsed)) {
    log(refusal->text);
    publish_event({{"type", "request_refused"}, {"text", refusal->text}});
    return;
  }
  const auto& req = std::get<ReplayRequest>(parsed);
  const std::string topic = topics_.replay_answer(req.reply_to);
  auto refuse = [&](const std::string& why) {
    broker_.publish(topic, nlohmann::json{{"machine", cfg_.machine}, {"from", req.from}, {"error", why}}.dump(), 1, false);
  };
  if (!messd_.connected()) return refuse("messd is not reachable now; ask again");
  if (requests_.size() >= kMaxRequests)
    return refuse("busy: " + std::to_string(kMaxRequests) + " replay requests are being answered; ask again");
  requests_.push_back({req.from, req.reply_to, {}, {}});
  messd_.send({Command::Kind::Request, req.from, req.reply_to});
}

void Bridge::handle_stop(std::string_view payload) {
  auto parsed = parse_stop_request(payload);
  if (auto* refusal = std::get_if<Refusal>(&parsed)) {
    log(refusal->text + "; the machine was not stopped");
    publish_event({{"type", "stop_refused"}, {"text", refusal->text}});
    return;
  }
  const auto& req = std::get<StopRequest>(parsed);
  const std::string who = (req.by.empty() ? std::string("someone") : req.by) + (req.reason.empty() ? "" : " (" + req.reason + ")");
  if (!cfg_.allow_stop) {
    log("stop request by " + who + " on " + topics_.stop +
        " ignored: this bridge may not stop the machine (mqtt.allow_stop is false)");
    publish_event({{"type", "stop_ignored"}, {"by", req.by}, {"reason", req.reason},
                   {"text", "mqtt.allow_stop is false"}});
    return;
  }
  if (!messd_.send({Command::Kind::Stop, 0, {}})) {
    log("stop request by " + who + ": messd is not reachable, nothing to stop through");
    publish_event({{"type", "stop_failed"}, {"by", req.by}, {"reason", req.reason}, {"text", "messd is not reachable"}});
    return;
  }
  log("stop request by " + who + " from the broker: StopMv sent");
  publish_event({{"type", "stop"}, {"by", req.by}, {"reason", req.reason}});
}

void Bridge::publish_event(nlohmann::json fields) {
  if (broker_.connected()) broker_.publish(topics_.event, event_payload(cfg_.machine, std::move(fields), now_text()), 1, false);
}

void Bridge::publish_online(bool online) {
  if (broker_.connected())
    broker_.publish(topics_.online, online_payload(cfg_.machine, online, state_.messd, now_text()), 1, true);
}

// ---- the loop ----

void Bridge::save(bool force) {
  if (tracker_.acked() == saved_acked_ && !force) return;
  save_acked(cfg_.state_file, cfg_.machine, tracker_.acked());
  saved_acked_ = tracker_.acked();
  last_save_ = Clock::now();
}

void Bridge::pump(Clock::time_point now) {
  if (broker_.connected() && messd_.connected() && order_.catch_up_due() && now >= catch_up_not_before_) {
    if (messd_.send({Command::Kind::CatchUp, order_.next(), {}})) order_.catch_up_sent();
  }
  if (state_dirty_ && broker_.connected() && now - last_state_ >= kStateInterval) {
    broker_.publish(topics_.state, state_payload(cfg_.machine, state_, now_text()), 1, true);
    state_dirty_ = false;
    last_state_ = now;
  }
  if (tracker_.acked() != saved_acked_ && now - last_save_ >= kSaveInterval) save(false);
}

int Bridge::run() {
  client::install_stop_signals({SIGINT, SIGTERM});
  log("bridging messd at " + cfg_.messd.to_string() + " to the broker " + cfg_.broker.to_string() + " as imess/" +
      cfg_.machine + "/... (stop from the broker: " + (cfg_.allow_stop ? "allowed" : "not allowed") +
      "; acknowledged up to hit " + std::to_string(tracker_.acked()) + ", state file " + cfg_.state_file + ")");
  while (!client::stop_requested()) {
    const auto now = Clock::now();
    messd_.service(false, now);
    broker_.service(false, false, now);
    pump(now);
    pollfd fds[2] = {{messd_.fd(), POLLIN, 0}, {broker_.fd(), static_cast<short>(POLLIN | (broker_.wants_write() ? POLLOUT : 0)), 0}};
    auto wait = std::min(std::chrono::milliseconds{100}, broker_.until_due(now));
    if (!messd_.connected()) wait = std::min(wait, messd_.until_due());  // zero while connected: not a deadline
    if (state_dirty_) wait = std::min(wait, std::chrono::milliseconds{50});
    if (::poll(fds, 2, static_cast<int>(std::max<long>(wait.count(), 1))) < 0) continue;  // EINTR: check the flag
    const auto after = Clock::now();
    if (fds[0].fd >= 0 && (fds[0].revents & (POLLIN | POLLHUP | POLLERR))) messd_.service(true, after);
    if (fds[1].fd >= 0 && fds[1].revents)
      broker_.service((fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0, (fds[1].revents & POLLOUT) != 0, after);
    pump(after);
  }
  log("stopping: " + std::to_string(hits_published_) + " hits published, acknowledged up to hit " +
      std::to_string(tracker_.acked()));
  try {
    save(true);
  } catch (const std::exception& e) {
    log(e.what());
  }
  publish_online(false);
  broker_.disconnect();
  messd_.finish();
  return 0;
}

}  // namespace imess::mqtt
