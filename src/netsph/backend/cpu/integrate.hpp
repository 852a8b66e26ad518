#pragma once
// The two symplectic stages (sph/symplectic.hpp) applied to every particle on the CPU.
// Fluid particles move; wall particles (DBC) keep position and velocity and update only their
// density, clamped at rho0.
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// The state at the start of a step, which both stages start from.
struct StepStart {
  std::vector<Vec3d> pos;
  std::vector<Vec3f> vel;
  std::vector<Real> rho;

  void save(const ParticleSet& p);
  std::size_t bytes() const {
    return pos.capacity() * sizeof(Vec3d) + vel.capacity() * sizeof(Vec3f) +
           rho.capacity() * sizeof(Real);
  }
};

/// Half-step state. Returns the largest fluid displacement from the step start, m.
double symplectic_predictor(ParticleSet& p, const StepStart& s, std::span<const Vec3f> acc,
                            std::span<const Real> drho, double dt, const FluidModel& m);

/// Full step. Returns the index of a particle whose new state is not finite, or -1.
std::int64_t symplectic_corrector(ParticleSet& p, const StepStart& s, std::span<const Vec3f> acc,
                                  std::span<const Real> drho, double dt, const FluidModel& m);

}  // namespace netsph
