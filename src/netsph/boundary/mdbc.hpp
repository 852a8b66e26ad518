#pragma once
// Modified dynamic boundary conditions (mDBC, English et al. 2022): each wall particle takes
// its density from a ghost node mirrored into the fluid across the wall surface, by
// first-order extrapolation rho_b = rho_g + grad(rho)_g . (r_b - r_g). The ghost sums see
// fluid and buffer particles only. Fallbacks, as DualSPHysics: Shepard density without the
// gradient when the ghost's matrix is singular, rho0 when the ghost sees no fluid at all.
// The density is set once per step, before the first interaction; within the step the wall
// particle integrates continuity as under DBC (clamped at rho0).
//
// Velocity the fluid sees (continuity and viscosity):
//   WallVelocity: v_b = v_wall                      (DualSPHysics SlipMode 1, DBC-like)
//   NoSlip:       v_b = 2 v_wall - v_g              (the mirror image: v = v_wall on the wall)
//   FreeSlip:     v_b = v_g - 2 ((v_g - v_wall).n) n (normal component mirrored only)
#include "netsph/core/physics_options.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/ghost_interpolation.hpp"

namespace netsph {

struct WallState {
  Real rho;
  Vec3f vel;
};

/// `ghost_offset` = r_g - r_b; `rho0` the reference density.
NETSPH_HD WallState mdbc_wall_state(const GhostValue& g, const Vec3f& ghost_offset, Real rho0,
                                    WallSlip slip, const Vec3f& v_wall) {
  WallState w{rho0, v_wall};
  if (!g.any) return w;
  const Vec3d off(ghost_offset);
  w.rho = static_cast<Real>(g.first_order ? g.rho - dot(g.grad_rho, off) : g.rho);
  const Vec3f vg(g.vel);
  switch (slip) {
    case WallSlip::WallVelocity:
      break;
    case WallSlip::NoSlip:
      w.vel = v_wall * Real(2) - vg;
      break;
    case WallSlip::FreeSlip: {
      const Real len = norm(ghost_offset);
      if (len > Real(0)) {
        const Vec3f n = ghost_offset / len;
        w.vel = vg - n * (Real(2) * dot(vg - v_wall, n));
      }
      break;
    }
  }
  return w;
}

}  // namespace netsph
