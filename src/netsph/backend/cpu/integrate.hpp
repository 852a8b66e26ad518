#pragma once
// The two symplectic stages applied to every particle on the CPU: each particle goes through
// sph/symplectic.hpp's per-particle stage (as on the device), plus shifting of fluid particles
// in the corrector when enabled.
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/backend/cpu/rates.hpp"
#include "netsph/sph/damping_zone.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"
#include "netsph/sph/shifting.hpp"
#include "netsph/sph/symplectic.hpp"

namespace netsph {

/// The velocity and density at the start of a step, which the corrector starts from (the
/// position advances from the half step: sph/symplectic.hpp).
struct StepStart {
  std::vector<Vec3f> vel;
  std::vector<Real> rho;

  void save(const ParticleSet& p);
  std::size_t bytes() const {
    return vel.capacity() * sizeof(Vec3f) + rho.capacity() * sizeof(Real);
  }
};

struct StageInputs {
  std::span<const Vec3f> acc;
  std::span<const Real> drho;
  double dt = 0;
  std::span<const WallKinematics> walls;  ///< by wall group
};

/// Half-step state from the state at the step start (in p). Returns the largest
/// displacement, m, over the particles with counted[i] != 0 (all when null: a process of a
/// distributed run counts those it owns, whose displacements are the one-process run's).
double symplectic_predictor(ParticleSet& p, const StageInputs& in, const FluidModel& m,
                            const std::uint8_t* counted = nullptr);

/// Full step; with `shifting`, fluid particles are shifted (sph/shifting.hpp). Returns the
/// index of a particle whose new state is not finite, or -1.
std::int64_t symplectic_corrector(ParticleSet& p, const StepStart& s, const StageInputs& in,
                                  const FluidModel& m, const ShiftingSums* shifting = nullptr,
                                  const ShiftingParams* shift_params = nullptr);

/// The damping zones' relaxation of the fluid particles' velocities over a step of dt ending
/// at time t (sph/damping_zone.hpp: a relaxation wavemaker's target moves), after the
/// corrector.
void apply_damping(ParticleSet& p, std::span<const DampingZone> zones, double t, double dt);

}  // namespace netsph
