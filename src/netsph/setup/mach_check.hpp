#pragma once
// Whether the case's speed of sound is fast enough for the flow it sets up. Weakly
// compressible SPH replaces the incompressible fluid by one whose density varies as
// (U/c0)^2 (Monaghan 1994, "Simulating free surface flows with SPH", section 3), and its
// free surfaces compress by about g H / c0^2; DualSPHysics' rule is c0 >= 10 U. A case whose
// c0 is far below that runs, but its water squeezes, its pressures are wrong, and it often
// ends with particles through a wall, where the run's diagnosis cannot name c0.
#include <optional>
#include <string>

#include "netsph/case/case_spec.hpp"

namespace netsph {

/// The fastest flow the case sets up (m/s) and what sets it: the fills', moving walls',
/// inlets', imposed outlets' and bodies' speeds, and the free-fall speed sqrt(2 |g| H) over the
/// deepest fill, H = `depth`.
struct ExpectedFlow {
  double speed = 0;
  std::string source;
};
ExpectedFlow expected_flow_speed(const CaseSpec& spec, double depth);

/// A warning when c0 is less than kMinSoundSpeedRatio times the expected flow speed.
inline constexpr double kMinSoundSpeedRatio = 5.0;
std::optional<std::string> sound_speed_warning(const CaseSpec& spec, double depth, double c0);

}  // namespace netsph
