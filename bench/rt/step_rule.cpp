// The step rate rule (step_rule.hpp).
#include "step_rule.hpp"

#include <algorithm>
#include <cmath>

namespace imess::bench {

StepRate step_rate(double period_us, double jitter_us, double min_len_us, double min_space_us) {
  auto periods = [&](double min_us) {
    return std::max(1, static_cast<int>(std::ceil((min_us + std::max(0.0, jitter_us)) / period_us - 1e-9)));
  };
  StepRate r;
  r.len_periods = periods(min_len_us);
  r.space_periods = periods(min_space_us);
  r.steps_per_s = 1e6 / ((r.len_periods + r.space_periods) * period_us);
  return r;
}

}  // namespace imess::bench
