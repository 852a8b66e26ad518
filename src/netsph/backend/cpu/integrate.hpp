#pragma once
// The two symplectic stages (sph/symplectic.hpp) applied to every particle on the CPU:
//   fluid:  the symplectic update (plus shifting in the corrector when enabled);
//   wall:   positions follow the wall's prescribed velocity (exactly, for a velocity linear
//           in time over the step); density integrates continuity, clamped at rho0; walls
//           that show the fluid their own velocity get it for the stage time;
//   buffer: moves with its (imposed or extrapolated) velocity, keeps its state.
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/backend/cpu/rates.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"
#include "netsph/sph/shifting.hpp"

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

/// A wall's prescribed velocity at the start, middle and end of the step.
struct WallKinematics {
  Vec3f start{}, half{}, end{};
  bool shows_own_velocity = true;  ///< DBC, or mDBC with WallSlip::WallVelocity
};

struct StageInputs {
  std::span<const Vec3f> acc;
  std::span<const Real> drho;
  double dt = 0;
  std::span<const WallKinematics> walls;  ///< by wall group
};

/// Half-step state. Returns the largest displacement from the step start, m.
double symplectic_predictor(ParticleSet& p, const StepStart& s, const StageInputs& in,
                            const FluidModel& m);

/// Full step; with `shifting`, fluid particles are shifted (sph/shifting.hpp). Returns the
/// index of a particle whose new state is not finite, or -1.
std::int64_t symplectic_corrector(ParticleSet& p, const StepStart& s, const StageInputs& in,
                                  const FluidModel& m, const ShiftingSums* shifting = nullptr,
                                  const ShiftingParams* shift_params = nullptr);

}  // namespace netsph
