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
  std::vector<Real> vx, vy, vz;  ///< velocity in the viscous terms
  /// Velocity in continuity where it differs from vx (a solid under a mirror slip condition
  /// shows its own velocity there). Empty unless with_continuity_velocity() was called: most
  /// cases have no mirrored solid, and 12 bytes per particle are saved (docs/PERFORMANCE.md).
  std::vector<Real> cvx, cvy, cvz;
  std::vector<Real> rho, press;
  std::vector<Real> fluid;  ///< 1 for fluid and buffer particles, 0 for wall and body particles
  /// Which solid a particle belongs to: kNotSolid (fluid, buffer), kWallSolid, or the body
  /// index; body particles make contact with particles of other solids.
  std::vector<std::int32_t> solid;
  static constexpr std::int32_t kNotSolid = -1, kWallSolid = -2;
  /// Which particles enter the rates pass's reductions (max |a|, the viscous dt criterion):
  /// null for all. A process of a distributed run (distributed/) passes the particles it
  /// owns, so that its halo copies, whose sums miss neighbours, never limit dt.
  const std::uint8_t* reduce_mask = nullptr;

  /// Copies the particles. The continuity velocity is the velocity (no separate arrays)
  /// until with_continuity_velocity().
  void build(const ParticleSet& p, const FluidModel& m, const Vec3d& origin);
  /// Copies particle i's density, pressure and velocity again after the boundary state has
  /// set them in `p` (positions, flags and continuity velocity untouched).
  void refresh_state(std::size_t i, const ParticleSet& p, const FluidModel& m) {
    rho[i] = p.rho[i];
    press[i] = m.eos.pressure(p.rho[i]);
    vx[i] = p.vel[i].x, vy[i] = p.vel[i].y, vz[i] = p.vel[i].z;
  }
  /// Gives the continuity velocity its own arrays, equal to the velocity; the caller then sets
  /// solids' own velocities where they differ (set_continuity_velocity).
  void with_continuity_velocity();
  void set_continuity_velocity(std::size_t i, const Vec3f& v) {
    cvx[i] = v.x, cvy[i] = v.y, cvz[i] = v.z;
  }
  bool has_continuity_velocity() const { return !cvx.empty(); }
  /// The arrays continuity reads: its own, or the viscous velocity when there are none.
  const Real* continuity_vx() const { return has_continuity_velocity() ? cvx.data() : vx.data(); }
  const Real* continuity_vy() const { return has_continuity_velocity() ? cvy.data() : vy.data(); }
  const Real* continuity_vz() const { return has_continuity_velocity() ? cvz.data() : vz.data(); }
  std::size_t bytes() const {
    return 9 * x.capacity() * sizeof(Real) +
           (cvx.capacity() + cvy.capacity() + cvz.capacity()) * sizeof(Real) +
           solid.capacity() * sizeof(std::int32_t);
  }
};

}  // namespace netsph
