#pragma once
// Symplectic position-Verlet time integration as in DualSPHysics (Leimkuhler & Matthews
// 2015; Crespo et al. 2015), second order, per particle:
//
//   predictor (rates at step n):        r* = r^n + dt/2 v^n
//                                       v* = v^n + dt/2 a^n
//                                       rho* = rho^n + dt/2 drho^n
//   corrector (rates at the half step): v^{n+1} = v^n + dt a*
//                                       r^{n+1} = r^n + dt/2 (v^n + v^{n+1})
//                                                = r* + dt/2 v^{n+1}
//                                       rho^{n+1} = rho^n (2 - eps) / (2 + eps),
//                                       eps = -(drho*/rho*) dt
// The density update is the exact solution of d(rho)/dt = -rho div(v) over the step with a
// frozen divergence, which keeps rho positive. The corrector advances the position from the
// half step (the second form of r^{n+1}): the same update, so no step-start copy of the
// positions is kept (24 B per particle of device memory), and a mid-step periodic
// wrap needs no correction of a start copy.
//
// Both backends advance every particle through symplectic_predict_particle and
// symplectic_correct_particle, so the CPU and the device step share one definition of the
// update of fluid, wall, buffer and body particles.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// Density at the half step.
NETSPH_HD Real symplectic_density_half(Real rho0, Real drho, double dt) {
  return rho0 + drho * static_cast<Real>(0.5 * dt);
}

/// Density at the end of the step from the half-step rate.
NETSPH_HD Real symplectic_density_full(Real rho0, Real drho_half, Real rho_half, double dt) {
  const Real eps = -(drho_half / rho_half) * static_cast<Real>(dt);
  return rho0 * (Real(2) - eps) / (Real(2) + eps);
}

/// A wall's prescribed velocity at the start, middle and end of the step.
struct WallKinematics {
  Vec3f start{}, half{}, end{};
  bool shows_own_velocity = true;  ///< DBC, or mDBC with WallSlip::WallVelocity
};

/// DBC boundary particles keep at least the reference density so that they never attract
/// fluid (DualSPHysics does the same).
NETSPH_HD Real clamp_boundary_density(Real rho, Real rho_ref) {
  return rho < rho_ref ? rho_ref : rho;
}

/// Predictor of one particle, in place: r, v and rho hold the step-start state on entry and
/// the half-step state on return; returns the displacement squared, m^2.
///   fluid:  the predictor above;
///   wall:   moves with its start velocity; shows its half-step velocity when it shows its
///           own; density integrates continuity, clamped at rho_ref;
///   buffer: moves with its (imposed or extrapolated) velocity, state kept;
///   body:   density only (position and velocity follow the rigid body).
/// `wall` is the particle's wall (read for walls only).
NETSPH_HD double symplectic_predict_particle(ParticleKind kind, const WallKinematics* wall,
                                             const Vec3f& acc, Real drho, double dt, Real rho_ref,
                                             Vec3d& r, Vec3f& v, Real& rho) {
  const double half = 0.5 * dt;
  Vec3d d{};
  switch (kind) {
    case ParticleKind::Fluid:
      d = Vec3d(v) * half;
      v = v + acc * static_cast<Real>(half);
      rho = symplectic_density_half(rho, drho, dt);
      break;
    case ParticleKind::Wall:
      d = Vec3d(wall->start) * half;
      if (wall->shows_own_velocity) v = wall->half;
      rho = clamp_boundary_density(symplectic_density_half(rho, drho, dt), rho_ref);
      break;
    case ParticleKind::Buffer:
      d = Vec3d(v) * half;
      break;
    case ParticleKind::Body:
      rho = clamp_boundary_density(symplectic_density_half(rho, drho, dt), rho_ref);
      break;
  }
  r += d;
  return d.x * d.x + d.y * d.y + d.z * d.z;
}

/// Corrector of one particle, in place: r, v and rho hold the half-step state on entry and
/// the end-of-step state on return; v0 and rho0 are the step start's. Walls end at
/// r^n + dt/2 (v_start + v_end), exact for a velocity linear in time over the step (trapezoid
/// rule). Shifting, where enabled, is the caller's (it needs the new velocity).
NETSPH_HD void symplectic_correct_particle(ParticleKind kind, const WallKinematics* wall,
                                           const Vec3f& v0, Real rho0, const Vec3f& acc, Real drho,
                                           double dt, Real rho_ref, Vec3d& r, Vec3f& v, Real& rho) {
  const double half = 0.5 * dt;
  switch (kind) {
    case ParticleKind::Fluid:
      v = v0 + acc * static_cast<Real>(dt);
      r += Vec3d(v) * half;
      rho = symplectic_density_full(rho0, drho, rho, dt);
      break;
    case ParticleKind::Wall:
      r += Vec3d(wall->end) * half;
      if (wall->shows_own_velocity) v = wall->end;
      rho = clamp_boundary_density(symplectic_density_full(rho0, drho, rho, dt), rho_ref);
      break;
    case ParticleKind::Buffer:
      r += Vec3d(v0) * half;
      break;
    case ParticleKind::Body:
      rho = clamp_boundary_density(symplectic_density_full(rho0, drho, rho, dt), rho_ref);
      break;
  }
}

/// Whether a particle's state is usable: finite position, velocity and density, density > 0
/// (the solvers' instability check after each corrector).
NETSPH_HD bool finite_state(const Vec3d& r, const Vec3f& v, Real rho) {
  return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) && std::isfinite(v.x) &&
         std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(rho) && rho > 0;
}

}  // namespace netsph
