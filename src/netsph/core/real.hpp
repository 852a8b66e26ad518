#pragma once
// Floating-point types. Fields (velocity, density, pressure, forces per particle) use `Real`
// (float: GPU throughput and half the memory traffic); positions and everything integrated
// over many steps use double so that round-off stays far below dp over 1e6 steps
// (docs/ARCHITECTURE.md, "Precision"). Reductions (mass, energy, body forces) use double.
#include "netsph/core/host_device.hpp"

namespace netsph {

using Real = float;

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace netsph
