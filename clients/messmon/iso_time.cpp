// iso_local_time via localtime_r/strftime (libstdc++ 12 has no chrono time-zone support).
#include "iso_time.hpp"

#include <cstdio>
#include <ctime>

namespace imess::messmon {

std::string iso_local_time(std::chrono::system_clock::time_point t) {
  using namespace std::chrono;
  auto ms_total = duration_cast<milliseconds>(t.time_since_epoch()).count();
  auto seconds = static_cast<std::time_t>(ms_total / 1000);
  auto ms = static_cast<int>(ms_total % 1000);
  if (ms < 0) {  // before 1970: floor, not truncate
    ms += 1000;
    --seconds;
  }
  std::tm local{};
  localtime_r(&seconds, &local);
  char date[32], zone[8];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S", &local);
  std::strftime(zone, sizeof zone, "%z", &local);  // "+0200"
  char out[64];
  std::snprintf(out, sizeof out, "%s.%03d%.3s:%.2s", date, ms, zone, zone + 3);
  return out;
}

}  // namespace imess::messmon
