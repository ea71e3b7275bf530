// The motion loop's runtime parameters (Set/Get, the configuration's "motion" keys) in one
// table: each row gives the code name (ParamId), the CoreParams field and its default, the
// wire name, unit (ASCII), range, configuration key and help. CoreParams, ParamId, the
// constexpr kCoreParams and param_ref all follow from it, and so does the daemon's parameter
// registry (daemon/net/src/params.cpp), so adding a parameter is one row here (plus its row
// in docs/protocol.md's parameter table, which test_params compares).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace imess::core {

// A range's max this large reads "any" in messages and docs.
inline constexpr double kUnbounded = 1e9;

// X(id, field, default, wire name, unit, min, max, configuration key, help)
// max_accel: per axis; it only lowers the axes' configured max_accel. The probing rows
// (SearchDist, PrehitDist, ProbeSpeed) shape the Probe cycle (DirectCMM, BRIEF §2).
#define IMESS_CORE_PARAMS(X)                                                                                        \
  X(TipRadius, tip_radius, 2.0, "TipRadius", "mm", 0, 50, "motion.tip_radius",                                      \
    "probe ball radius used for compensation; 0 = none")                                                            \
  X(SpeedLevel, speed_level, 1.0, "SpeedLevel", "", 0.01, 2, "motion.speed_level",                                  \
    "multiplier for every speed (1996: 0.1 ... 1.5)")                                                               \
  X(MaxSpeed, max_speed, 100, "MaxSpeed", "mm/s", 0.1, 1000, "motion.max_speed", "speed of StartMv 100")            \
  X(MaxAccel, max_accel, 1000, "MaxAccel", "mm/s2", 1, 20000, "motion.max_accel", "acceleration of every move")     \
  X(RetractDistance, retract_distance, 0.5, "RetractDist", "mm", 0, 20, "motion.retract_distance",                  \
    "retract behind the latched point")                                                                             \
  X(RetractSpeed, retract_speed, 10, "RetractSpeed", "mm/s", 0.1, 200, "motion.retract_speed",                      \
    "speed of the retract")                                                                                         \
  X(RetractTimeout, retract_timeout, 5, "RetractTime", "s", 0.1, 60, "motion.retract_timeout_s",                    \
    "time for the tip to re-seat")                                                                                  \
  X(IdleOpenTime, idle_open_time, 7, "IdleOpen", "s", 0.1, kUnbounded, "motion.idle_open_s",                        \
    "loops open this long after the last stop")                                                                     \
  X(GoToSpeed, goto_speed, 50, "GoToSpeed", "mm/s", 0.1, 1000, "motion.goto_speed", "GoTo speed when none is given") \
  X(HandMinTravel, hand_min_travel, 1.0, "HandTravel", "mm", 0.1, 50, "motion.hand_min_travel",                     \
    "travel that gives a hand hit its direction")                                                                   \
  X(HandMinInterval, hand_min_interval, 1.0, "HandInterval", "s", 0, 60, "motion.hand_min_interval_s",              \
    "minimum time between hand hits")                                                                               \
  X(SearchDistance, search_distance, 10, "SearchDist", "mm", 0.1, 100, "motion.search_distance",                    \
    "probing: searched past the target before the part counts as not found")                                        \
  X(PrehitDistance, prehit_distance, 2, "PrehitDist", "mm", 0, 50, "motion.prehit_distance",                        \
    "probing: before the target, where the touch speed is reached")                                                 \
  X(ProbeSpeed, probe_speed, 5, "ProbeSpeed", "mm/s", 0.1, 50, "motion.probe_speed", "probing: the touch speed")     \
  X(ScanDeflection, scan_deflection, 0.3, "ScanDeflection", "mm", 0.02, 5, "motion.scan_deflection",                 \
    "scanning: the measuring probe's deflection held in contact")                                                   \
  X(ScanBand, scan_band, 0.1, "ScanBand", "mm", 0.005, 5, "motion.scan_band",                                       \
    "scanning: the deflection's band around ScanDeflection")                                                        \
  X(ScanStep, scan_step, 0.1, "ScanStep", "mm", 0.001, 100, "motion.scan_step", "scanning: distance between points") \
  X(ScanSpeed, scan_speed, 5, "ScanSpeed", "mm/s", 0.1, 100, "motion.scan_speed",                                   \
    "scanning: speed along the surface when a scan names none")

#define IMESS_CORE_PARAM_ID(id, field, initial, ...) id,
#define IMESS_CORE_PARAM_FIELD(id, field, initial, ...) double field = initial;
#define IMESS_CORE_PARAM_ROW(id, field, initial, name, unit, min, max, config, help) \
  CoreParamSpec{ParamId::id, &CoreParams::field, name, unit, min, max, config, help},

enum class ParamId : std::uint8_t { IMESS_CORE_PARAMS(IMESS_CORE_PARAM_ID) };

// The values the loop runs with (Set/Get; the snapshot carries them). Ranges: kCoreParams.
struct CoreParams {
  IMESS_CORE_PARAMS(IMESS_CORE_PARAM_FIELD)
};

struct CoreParamSpec {
  ParamId id;
  double CoreParams::*field;
  std::string_view name;    // on the wire, matched case-insensitively
  std::string_view unit;    // ASCII, as in error texts ("mm/s2")
  double min, max;          // accepted by Set and by the configuration key
  std::string_view config;  // the configuration key setting it at start
  std::string_view help;    // one line
  constexpr double initial() const noexcept { return CoreParams{}.*field; }
};

inline constexpr std::array kCoreParams{IMESS_CORE_PARAMS(IMESS_CORE_PARAM_ROW)};

#undef IMESS_CORE_PARAM_ID
#undef IMESS_CORE_PARAM_FIELD
#undef IMESS_CORE_PARAM_ROW

// Row i is ParamId i, and every field of CoreParams has its row.
constexpr bool core_param_rows_in_order() noexcept {
  for (std::size_t i = 0; i < kCoreParams.size(); ++i)
    if (static_cast<std::size_t>(kCoreParams[i].id) != i) return false;
  return true;
}
static_assert(core_param_rows_in_order());
static_assert(sizeof(CoreParams) == kCoreParams.size() * sizeof(double));

constexpr double& param_ref(CoreParams& p, ParamId id) noexcept { return p.*kCoreParams[static_cast<std::size_t>(id)].field; }
constexpr double param_value(const CoreParams& p, ParamId id) noexcept {
  return p.*kCoreParams[static_cast<std::size_t>(id)].field;
}

}  // namespace imess::core
