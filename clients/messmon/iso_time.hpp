// ISO-8601 local time with milliseconds and UTC offset: "2024-05-01T14:03:07.042+02:00".
#pragma once
#include <chrono>
#include <string>

namespace imess::messmon {

std::string iso_local_time(std::chrono::system_clock::time_point t);

}  // namespace imess::messmon
