#pragma once
// When a run's periodic outputs fall due. One rule for all of them (snapshots and net shapes,
// series rows, probe rows and probe samples): due at the run's start, then every `every`
// seconds of simulated time, and the default intervals derived from the case in one place.
// Two clocks keep rules of their own, which their files give: checkpoints (runner.cpp: by
// simulated time or wall time, never at the start) and the standalone net run's fixed-step
// loop (standalone_net_run.cpp, which takes its intervals from here).
#include <array>

#include "netsph/case/case_spec.hpp"

namespace netsph {

/// A periodic output's clock. `next` is saved in checkpoints as it is.
struct OutputSchedule {
  double every = 0;  ///< s
  double next = 0;   ///< s: when the output is due next

  /// Whether the output is due at `t` (a schedule_time); if so, moves `next` past `t` (by
  /// whole intervals, so that a step longer than the interval writes once).
  bool take(double t) {
    if (!(t >= next)) return false;
    while (next <= t) next += every;
    return true;
  }
};

/// The simulated time to compare with a schedule: padded by a relative 1e-12, so that
/// round-off in the accumulated time does not skip an output.
inline double schedule_time(double time) {
  return time * (1 + 1e-12);
}

/// Intervals after defaults: snapshot_every 0 -> end_time / 50; series_every 0 -> snapshot / 10.
double snapshot_interval(const CaseSpec& spec);
double series_interval(const CaseSpec& spec);
/// The force-averaging window: output.force_window, or the second half of the run.
std::array<double, 2> force_window(const CaseSpec& spec);

}  // namespace netsph
