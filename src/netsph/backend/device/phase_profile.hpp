#pragma once
// Where the device step's time goes: wall seconds per phase of DeviceStepper::step, measured
// only when asked (`netsph bench --profile`). Each timed phase waits for the device before it
// starts and again before it stops (Exec::synchronize), so the figures are the device's work
// in that phase plus one launch latency per kernel; profiling thus slows the step a little and
// is off in runs.
#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>

namespace netsph {

enum class DevicePhase : int {
  OpenBoundaries,  ///< buffer transitions, inlet particles created
  SortKeys,        ///< cell keys, radix sort
  Gather,          ///< every array reordered by the sort (gather into scratch, copy back)
  CellTable,       ///< first particle of every cell
  BoundaryState,   ///< mDBC ghost nodes of walls and bodies, open-boundary buffer state
  View,            ///< float positions, velocities and pressures of the interaction
  Rates,           ///< the pair sums of both passes
  Bodies,          ///< body particles placed, contacts, loads reduced, bodies advanced (host)
  TimeStep,        ///< dt's reductions, the step start saved
  Integration,     ///< predictor and corrector (with their displacement and finiteness checks)
  Count
};

inline constexpr std::array<std::string_view, static_cast<int>(DevicePhase::Count)>
    kDevicePhaseNames{"open boundaries", "sort keys",  "gather", "cell table",
                      "boundary state",  "view",       "rates",  "bodies",
                      "time step",       "integration"};

/// Seconds and entries of each phase since profiling was switched on.
struct DevicePhaseTimes {
  std::array<double, static_cast<int>(DevicePhase::Count)> seconds{};
  std::array<std::int64_t, static_cast<int>(DevicePhase::Count)> calls{};
  double total() const {
    double t = 0;
    for (double s : seconds) t += s;
    return t;
  }
};

/// Times one phase for as long as it lives, when `times` is not null (profiling on).
template <class Exec>
class PhaseTimer {
 public:
  PhaseTimer(DevicePhaseTimes* times, DevicePhase phase) : times_(times), phase_(phase) {
    if (!times_) return;
    Exec::synchronize();
    t0_ = std::chrono::steady_clock::now();
  }
  ~PhaseTimer() {
    if (!times_) return;
    Exec::synchronize();
    const auto k = static_cast<int>(phase_);
    times_->seconds[k] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    ++times_->calls[k];
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  DevicePhaseTimes* times_;
  DevicePhase phase_;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace netsph
