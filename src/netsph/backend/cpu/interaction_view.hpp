#pragma once
// The particle data the interaction loop reads, as float arrays (structure of arrays) so the
// inner loop over neighbours loads contiguous floats and vectorises. Positions are stored
// relative to the grid origin: float keeps ~1e-7 of the domain size, far below dp for the
// domain/dp ratios netsph targets (1e3-1e4), while the integration itself stays in double.
// Pressure is evaluated once per particle here instead of once per pair.
#include <cstdint>
#include <vector>

#include "netsph/core/real.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

struct InteractionView {
  std::vector<Real> x, y, z;
  std::vector<Real> vx, vy, vz;     ///< velocity in the viscous terms
  std::vector<Real> cvx, cvy, cvz;  ///< velocity in continuity (a solid's own velocity)
  std::vector<Real> rho, press;
  std::vector<Real> fluid;  ///< 1 for fluid and buffer particles, 0 for wall and body particles
  /// Which solid a particle belongs to: kNotSolid (fluid, buffer), kWallSolid, or the body
  /// index; body particles make contact with particles of other solids.
  std::vector<std::int32_t> solid;
  static constexpr std::int32_t kNotSolid = -1, kWallSolid = -2;

  /// Copies the particles; the continuity velocity starts equal to the velocity (the caller
  /// sets solids' own velocities where they differ: set_continuity_velocity).
  void build(const ParticleSet& p, const FluidModel& m, const Vec3d& origin);
  void set_continuity_velocity(std::size_t i, const Vec3f& v) {
    cvx[i] = v.x, cvy[i] = v.y, cvz[i] = v.z;
  }
  std::size_t bytes() const {
    return 12 * x.capacity() * sizeof(Real) + solid.capacity() * sizeof(std::int32_t);
  }
};

}  // namespace netsph
