// The bridge's readers of broker input and of its configuration: what anyone on a broker may
// publish is refused with a sentence that says what was wrong and what is accepted.
#include <catch2/catch.hpp>

#include "ack_tracker.hpp"
#include "bridge_config.hpp"
#include "broker_input.hpp"
#include "hit_order.hpp"
#include "imess/client/usage_error.hpp"

using namespace imess::mqtt;

namespace {
std::string refusal(const auto& r) {
  const auto* x = std::get_if<Refusal>(&r);
  return x ? x->text : std::string();
}
}  // namespace

TEST_CASE("mqtt requests: a replay request needs a seq from 1 and a reply_to topic level, nothing else") {
  auto ok = parse_replay_request(R"({"from": 12, "reply_to": "fleet-1"})");
  REQUIRE(std::holds_alternative<ReplayRequest>(ok));
  CHECK(std::get<ReplayRequest>(ok).from == 12);
  CHECK(std::get<ReplayRequest>(ok).reply_to == "fleet-1");
  CHECK_THAT(refusal(parse_replay_request(R"({"from": 0, "reply_to": "a"})")), Catch::Contains("'from' must be a whole number from 1"));
  CHECK_THAT(refusal(parse_replay_request(R"({"from": -3, "reply_to": "a"})")), Catch::Contains("got -3"));
  CHECK_THAT(refusal(parse_replay_request(R"({"from": 2.5, "reply_to": "a"})")), Catch::Contains("whole number"));
  CHECK_THAT(refusal(parse_replay_request(R"({"from": 1, "reply_to": "a/#"})")), Catch::Contains("no '/', '+' or '#'"));
  CHECK_THAT(refusal(parse_replay_request(R"({"from": 1})")), Catch::Contains("'reply_to' must be a text"));
  CHECK_THAT(refusal(parse_replay_request(R"({"from": 1, "reply_to": "a", "move": 1})")),
             Catch::Contains("unknown key 'move'; accepted: from, reply_to"));
  CHECK_THAT(refusal(parse_replay_request("12")), Catch::Contains("a JSON object"));
  CHECK_THAT(refusal(parse_replay_request("{\"from\": 1,")), Catch::Contains("replay request"));
  CHECK_THAT(refusal(parse_replay_request(std::string(5000, ' '))), Catch::Contains("at most 4096"));
}

TEST_CASE("mqtt requests: a stop takes an empty payload or a reason and a name of printable text") {
  CHECK(std::holds_alternative<StopRequest>(parse_stop_request("")));
  CHECK(std::holds_alternative<StopRequest>(parse_stop_request("{}")));
  auto ok = parse_stop_request(R"({"reason": "door open", "by": "line 3 PLC"})");
  REQUIRE(std::holds_alternative<StopRequest>(ok));
  CHECK(std::get<StopRequest>(ok).reason == "door open");
  CHECK_THAT(refusal(parse_stop_request(R"({"reason": 5})")), Catch::Contains("'reason' must be a text"));
  CHECK_THAT(refusal(parse_stop_request("{\"by\": \"a\\u0007b\"}")), Catch::Contains("printable ASCII"));
  CHECK_THAT(refusal(parse_stop_request(R"({"goto": [1, 2, 3]})")), Catch::Contains("unknown key 'goto'; accepted: reason, by"));
  CHECK_THAT(refusal(parse_stop_request("stop")), Catch::Contains("stop request"));
}

TEST_CASE("mqtt bridge: the watermark passes only hits the broker acknowledged, in order") {
  AckTracker t(10);
  t.published(1, 11);
  t.published(2, 12);
  t.published(3, 13);
  CHECK_FALSE(t.acknowledged(2));  // 11 still open
  CHECK(t.acked() == 10);
  CHECK(t.acknowledged(1));
  CHECK(t.acked() == 12);
  t.connection_lost();  // 13 was never acknowledged: published again after the break
  CHECK_FALSE(t.acknowledged(3));
  CHECK(t.acked() == 12);
  CHECK(t.skip(13, 15));  // lost in the journal
  CHECK(t.acked() == 15);

  HitOrder o;
  o.start_at(16);
  CHECK(o.catch_up_due());  // what messd holds is unknown
  o.catch_up_sent();
  CHECK(o.offer(15) == HitOrder::Offer::Already);
  CHECK(o.offer(17) == HitOrder::Offer::Gap);
  CHECK(o.offer(16) == HitOrder::Offer::Publish);
  CHECK(o.offer(17) == HitOrder::Offer::Publish);
  o.replay_answered(16, 2, 18);
  CHECK(o.catch_up_due());  // 18 is still to come
  CHECK(o.pass_lost(18, 18));
  CHECK(o.next() == 19);
}

TEST_CASE("mqtt bridge: the mqtt section of the configuration file is read strictly") {
  BridgeConfig cfg;
  load_bridge_config_text(R"({"server": {"port": 2066}, "motion": {"period_us": 1000},
      "mqtt": {"broker": "broker.local:1884", "machine": "cmm-2", "allow_stop": true, "password_file": "pw", "user": "u"}})",
                          "/etc/imess/messd.json", cfg);
  CHECK(cfg.messd.port == 2066);
  CHECK(cfg.broker.host == "broker.local");
  CHECK(cfg.broker.port == 1884);
  CHECK(cfg.machine == "cmm-2");
  CHECK(cfg.allow_stop);
  CHECK(cfg.password_file == "/etc/imess/pw");
  auto error_of = [](const std::string& text) {
    BridgeConfig c;
    try {
      load_bridge_config_text(text, "m.json", c);
    } catch (const imess::client::UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error_of(R"({"mqtt": {"machine": "m", "alow_stop": true}})"),
             Catch::Contains("m.json: unknown key 'mqtt.alow_stop'; accepted here: broker, machine"));
  CHECK_THAT(error_of(R"({"mqtt": {"machine": "a/b"}})"), Catch::Contains("key 'mqtt.machine' 'a/b'"));
  CHECK_THAT(error_of(R"({"mqtt": {"machine": "m", "allow_stop": "yes"}})"), Catch::Contains("'mqtt.allow_stop' must be true or false"));
  CHECK_THAT(error_of(R"({"mqtt": {"machine": "m", "broker": "h:99999"}})"), Catch::Contains("mqtt.broker"));
  CHECK_THAT(error_of(R"({"server": {}})"), Catch::Contains("has no \"mqtt\" section"));
}
