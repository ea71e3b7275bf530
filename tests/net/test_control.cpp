// Control: implicit take, refusals, Take force, release; which verbs need control; the
// Control event's wording and length.
#include <catch2/catch.hpp>

#include "imess/net/control.hpp"
#include "imess/protocol/verbs.hpp"

using namespace imess::net;
namespace p = imess::protocol;

namespace {
Controller who(std::uint32_t id, std::string host = "127.0.0.1") { return {id, "client" + std::to_string(id), host}; }
CommandNeed need(std::string_view line) { return command_need(std::get<p::Command>(p::parse_command(line))); }
}  // namespace

TEST_CASE("command_need: motion and changes need control, StopMv is open to all and never takes it") {
  for (auto line : {"StartMv 1 0 0", "GoTo 1 2 3", "Home", "Free", "Reset", "Set TipRadius 1", "HandMv 1 0 0", "ForcePt"}) {
    INFO(line);
    CHECK(need(line) == CommandNeed::Controlling);
  }
  CHECK(need("StopMv") == CommandNeed::Stop);
  for (auto line : {"Hello x", "Help", "Status", "Get", "Get TipRadius", "Stats", "Quit", "Watch 250", "Version"}) {
    INFO(line);
    CHECK(need(line) == CommandNeed::Open);
  }
  CHECK(need("Take") == CommandNeed::Own);
  CHECK(need("Take force") == CommandNeed::Own);
  CHECK(need("Release") == CommandNeed::Own);
  CHECK(need("Key Done") == CommandNeed::Operator);  // the operator's keys: from any control host
}

TEST_CASE("Control: the first controlling command takes free control, others are refused naming the owner") {
  Control c;
  CHECK_FALSE(c.owner());
  CHECK(c.claim(who(1), true) == ControlOutcome::Taken);
  CHECK(c.owns(1));
  CHECK(c.claim(who(1), true) == ControlOutcome::Kept);
  CHECK(c.claim(who(2), true) == ControlOutcome::HeldByOther);
  CHECK(c.owner()->session == 1);
  CHECK(describe(*c.owner()) == "client1 at 127.0.0.1 (client 1)");
}

TEST_CASE("Control: a host that may only observe never takes control, not even free control") {
  Control c;
  CHECK(c.claim(who(3, "192.168.7.7"), false) == ControlOutcome::HostNotAllowed);
  CHECK(c.take(who(3, "192.168.7.7"), false, false, false) == ControlOutcome::HostNotAllowed);
  CHECK(c.take(who(3, "192.168.7.7"), false, true, false) == ControlOutcome::HostNotAllowed);
  CHECK_FALSE(c.owner());
}

TEST_CASE("Control: Take waits for free control, Take force only from force hosts, and names who lost it") {
  Control c;
  REQUIRE(c.take(who(1), true, false, false) == ControlOutcome::Taken);
  CHECK(c.take(who(2), true, false, true) == ControlOutcome::HeldByOther);
  CHECK(c.take(who(2), true, true, false) == ControlOutcome::ForceNotAllowed);
  CHECK(c.owns(1));
  CHECK(c.take(who(2), true, true, true) == ControlOutcome::TakenOver);
  CHECK(c.owns(2));
  REQUIRE(c.previous());
  CHECK(c.previous()->session == 1);
  CHECK(c.claim(who(1), true) == ControlOutcome::HeldByOther);  // the old owner is an observer now
}

TEST_CASE("Control: an idle owner hands over to the next who asks, a busy or recent one does not") {
  Control c(2.0);
  REQUIRE(c.claim(who(1), true) == ControlOutcome::Taken);
  const Activity idle{false, false, 2.0};
  // Each condition alone keeps control where it is.
  CHECK(c.claim(who(2), true, Activity{true, false, 60}) == ControlOutcome::HeldByOther);   // the machine moves
  CHECK(c.claim(who(2), true, Activity{false, true, 60}) == ControlOutcome::HeldByOther);   // moves are queued
  CHECK(c.claim(who(2), true, Activity{false, false, 1.99}) == ControlOutcome::HeldByOther);  // the owner spoke lately
  CHECK(c.claim(who(2), true) == ControlOutcome::HeldByOther);  // the default: a busy owner
  CHECK(c.take(who(2), true, false, false, Activity{false, false, 1.0}) == ControlOutcome::HeldByOther);
  CHECK(c.claim(who(3, "192.168.7.7"), false, idle) == ControlOutcome::HostNotAllowed);  // an observer host never
  CHECK(c.owns(1));
  CHECK(c.claim(who(2), true, idle) == ControlOutcome::HandedOver);
  CHECK(c.owns(2));
  CHECK(c.previous()->session == 1);
  CHECK(c.take(who(1), true, false, false, idle) == ControlOutcome::HandedOver);  // Take asks as well
  CHECK(c.owns(1));
  CHECK(c.previous()->session == 2);
}

TEST_CASE("Control: never handed over with handover_s 0, nor from the I++ DME session") {
  const Activity idle{false, false, 1e9};
  Control never(0);
  REQUIRE(never.claim(who(1), true) == ControlOutcome::Taken);
  CHECK(never.claim(who(2), true, idle) == ControlOutcome::HeldByOther);
  Control c(2.0);
  REQUIRE(c.claim(Controller{kIppSession, "ippdme", "127.0.0.1"}, true) == ControlOutcome::Taken);
  CHECK_FALSE(c.hands_over(idle));
  CHECK(c.claim(who(2), true, idle) == ControlOutcome::HeldByOther);
  CHECK(c.take(who(2), true, false, true, idle) == ControlOutcome::HeldByOther);
  CHECK(c.take(who(2), true, true, true, idle) == ControlOutcome::TakenOver);  // the operator's force still works
}

TEST_CASE("Control: release and disconnect free control, only the owner's release counts") {
  Control c;
  REQUIRE(c.claim(who(1), true) == ControlOutcome::Taken);
  CHECK_FALSE(c.release(2));
  CHECK(c.owns(1));
  CHECK(c.release(1));
  CHECK_FALSE(c.owner());
  CHECK_FALSE(c.release(1));  // twice: nothing more to free
  CHECK(c.claim(who(2), true) == ControlOutcome::Taken);
}

TEST_CASE("Control: Hello after taking control renames the owner") {
  Control c;
  REQUIRE(c.claim(who(4), true) == ControlOutcome::Taken);
  c.rename(4, "messjog");
  c.rename(5, "intruder");  // not the owner: ignored
  CHECK(c.owner()->name == "messjog");
}

TEST_CASE("control_event: names owner and host, or none, and never exceeds 79 characters") {
  CHECK(control_event(std::nullopt) == "Control none\n");
  CHECK(control_event(Controller{1, "messjog", "127.0.0.1"}) == "Control messjog 127.0.0.1\n");
  CHECK(controller_name(7, "") == "client7");
  CHECK(controller_name(7, std::string(200, 'n')).size() == kMaxControlName);
  Controller longest{9, controller_name(9, std::string(200, 'n')), "ffff:ffff:ffff:ffff:ffff:ffff:255.255.255.255"};
  CHECK(control_event(longest).size() - 1 <= kMaxEventLine);
  Controller scoped{9, "messjog", "fe80::1234:5678:9abc:def0%a-very-long-interface-name-indeed-0123456789"};
  auto line = control_event(scoped);
  CHECK(line.size() - 1 <= kMaxEventLine);
  CHECK(line.rfind("Control m", 0) == 0);  // at least a letter of the name stays
  CHECK(status_value(std::nullopt) == "none");
  CHECK(status_value(Controller{1, "messjog", "::1"}) == "messjog@::1");
}

TEST_CASE("control_taken_warning: names who took over, within 79 characters") {
  CHECK(control_taken_warning(Controller{2, "operator", "127.0.0.1"}) ==
        "Warn ControlTaken operator 127.0.0.1 took over; machine stopped\n");
  Controller longest{9, controller_name(9, std::string(200, 'n')), "ffff:ffff:ffff:ffff:ffff:ffff:255.255.255.255"};
  auto line = control_taken_warning(longest);
  CHECK(line.size() - 1 <= kMaxEventLine);
  CHECK(line.find("ffff:ffff:ffff:ffff:ffff:ffff:255.255.255.255") != std::string::npos);  // the host stays whole
}
