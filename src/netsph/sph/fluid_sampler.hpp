#pragma once
// A hook that samples the SPH fluid at points, Shepard-corrected (sph/shepard.hpp), from the
// particles as a step's stage has them: what models of parts too small to resolve (a net's
// sinker bar, solver/net_coupling.hpp) take their flow from. The CPU step and the device step
// each provide one (Simulation::sample_fluid_at_stage, DeviceStepper::sample_fluid); a
// distributed run sums each process's sums over the processes (sum_over_processes).
#include <functional>
#include <span>
#include <vector>

#include "netsph/sph/shepard.hpp"

namespace netsph {

using FluidSampler =
    std::function<void(std::span<const Vec3d> points, std::span<ShepardValue> values)>;

/// Replaces each point's sums over one process's particles by their sums over all processes
/// of a distributed run; `sum_all` sums a vector of numbers element by element over them.
template <class SumAll>
void sum_over_processes(std::span<ShepardSums> sums, SumAll&& sum_all) {
  constexpr std::size_t per = 6;
  std::vector<double> packed;
  packed.reserve(per * sums.size());
  for (const ShepardSums& s : sums)
    packed.insert(packed.end(), {s.volume_weight, s.velocity.x, s.velocity.y, s.velocity.z,
                                 s.pressure, s.density});
  sum_all(std::span<double>(packed));
  for (std::size_t k = 0; k < sums.size(); ++k) {
    const double* v = &packed[per * k];
    sums[k] = ShepardSums{v[0], {v[1], v[2], v[3]}, v[4], v[5]};
  }
}

}  // namespace netsph
