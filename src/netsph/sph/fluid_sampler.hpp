#pragma once
// A hook that samples the SPH fluid at points, Shepard-corrected (sph/shepard.hpp), from the
// particles as a step's stage has them: what models of parts too small to resolve (a net's
// sinker bar, solver/net_coupling.hpp) take their flow from. The CPU step and the device step
// each provide one (Simulation::sample_fluid, DeviceStepper::sample_fluid).
#include <functional>
#include <span>

#include "netsph/sph/shepard.hpp"

namespace netsph {

using FluidSampler =
    std::function<void(std::span<const Vec3d> points, std::span<ShepardValue> values)>;

}  // namespace netsph
