// Fuzz target: what anyone on an MQTT broker may publish to a bridge or a fleet view — the
// same bytes as a replay request, as a stop request (messmqtt) and as each kind of message
// messfleet folds. A request is accepted only in its documented form (a seq from 1 to 2^53 - 1,
// a reply_to that is one topic level, printable texts of at most 200 characters); else a
// refusal that names the request. Nothing throws; the fleet's JSON and table always print.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "broker_input.hpp"
#include "fleet_view.hpp"
#include "topics.hpp"

using namespace imess::mqtt;

namespace {
bool printable(const std::string& s) {
  if (s.size() > kMaxReasonLength) return false;
  for (unsigned char c : s)
    if (c < 32 || c > 126) return false;
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto replay = parse_replay_request(bytes);
  if (const auto* r = std::get_if<ReplayRequest>(&replay)) {
    if (r->from < 1 || r->from > 9007199254740991ULL) std::abort();
    if (!name_problem(r->reply_to).empty()) std::abort();
  } else if (std::get<Refusal>(replay).text.rfind("replay request", 0) != 0) {
    std::abort();
  }
  auto stop = parse_stop_request(bytes);
  if (const auto* s = std::get_if<StopRequest>(&stop)) {
    if (!printable(s->reason) || !printable(s->by)) std::abort();
  } else if (std::get<Refusal>(stop).text.rfind("stop request", 0) != 0) {
    std::abort();
  }
  FleetView view;
  for (const char* topic : {"imess/m1/state", "imess/m1/online", "imess/m1/hit", "imess/m1/event", "imess/m1/cmd/stop"})
    view.fold(topic, bytes);
  if (view.to_json().dump().empty() || view.table().empty()) std::abort();
  return 0;
}
