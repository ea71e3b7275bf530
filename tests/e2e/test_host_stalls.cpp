// Issue 27, section 3: a machine that survives a busy host. messd on the default simulated CMM
// (its card streamed in process, 60 ms lead, wall-clock time: SIGSTOP stops the card with it,
// which then catches up on the ticks it missed with the setpoints it had) through the busy
// host of busy_host.hpp: probe cycles and a program (the request/reply link faults at the
// first probe). The whole workload, the cube inspection too, over messcard on a
// pseudo-terminal, where the card runs on through messd's stops as hardware does, is
// test_busy_host_card.cpp. This one is in test_serial_card's executable: one test of a real
// line or of stalls at a time.
#include "busy_host.hpp"

using namespace imess::test;

TEST_CASE("host stalls: 30 ms stops once a second beside two CPU hogs: probe cycles and a program without a fault", "[long]") {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/wall-cmm.json"},
                      DaemonProcess::Scheduling::RealtimeIfPermitted);
  busy_host::run_through_stalls(messd.port(), messd.pid(), "host stalls (in-process card)", false);
}
