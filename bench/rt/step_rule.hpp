// The step rate a base thread's jitter honestly allows. The step generator makes a pulse and
// a space of whole base periods T; each edge reaches the port when its tick writes. A tick
// whose write comes d after its deadline (d in [d_min, d_max]) moves that edge by d, so a
// pulse of n periods lasts n·T + d_end − d_start ≥ n·T − J, with J = d_max − d_min: the
// spread of the write lateness. To keep the drive's minimum step length and space, the
// pulse needs n_len = ceil((t_len + J) / T) periods (at least 1) and the space
// n_space = ceil((t_space + J) / T); one step then takes (n_len + n_space)·T, and the
// highest step rate per axis at which no pulse or space is ever short is its inverse.
// A tick late by more than a period (an overrun) stretches a pulse or space, never shortens
// it: the due step waits and no step is lost, but the axis falls behind for that period.
#pragma once

namespace imess::bench {

struct StepRate {
  int len_periods = 0, space_periods = 0;  // base periods of the pulse and of the space
  double steps_per_s = 0;                  // per axis
};

StepRate step_rate(double period_us, double jitter_us, double min_len_us, double min_space_us);

}  // namespace imess::bench
