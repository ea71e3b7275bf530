// The JSON the bridge publishes (docs/mqtt.md, "Payloads"): one object per message, UTF-8
// free ASCII, numbers in mm and seconds as messd prints them.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "imess/protocol/messages.hpp"
#include "machine_state.hpp"

namespace imess::mqtt {

// "2026-11-29T03:14:15.926Z"
std::string iso_utc(std::chrono::system_clock::time_point t);

// imess/<machine>/hit and a replay answer's hits:
// {"machine":"cmm1","seq":12,"id":0,"x":..,"y":..,"z":..,"i":..,"j":..,"k":..,"r":2.0,"t":8012.317804}
std::string hit_payload(const std::string& machine, const protocol::HitMsg& hit);
// imess/<machine>/state (retained).
std::string state_payload(const std::string& machine, const MachineState& s, const std::string& now);
// imess/<machine>/online (retained; the last will is online=false).
std::string online_payload(const std::string& machine, bool online, bool messd, const std::string& now);
// imess/<machine>/event: `fields` (with its "type") plus machine and time.
std::string event_payload(const std::string& machine, nlohmann::json fields, const std::string& now);

}  // namespace imess::mqtt
