#pragma once
// Symplectic position-Verlet time integration as in DualSPHysics (Leimkuhler & Matthews
// 2015; Crespo et al. 2015), second order, per particle:
//
//   predictor (rates at step n):        r* = r^n + dt/2 v^n
//                                       v* = v^n + dt/2 a^n
//                                       rho* = rho^n + dt/2 drho^n
//   corrector (rates at the half step): v^{n+1} = v^n + dt a*
//                                       r^{n+1} = r^n + dt/2 (v^n + v^{n+1})
//                                       rho^{n+1} = rho^n (2 - eps) / (2 + eps),
//                                       eps = -(drho*/rho*) dt
// The density update is the exact solution of d(rho)/dt = -rho div(v) over the step with a
// frozen divergence, which keeps rho positive.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

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

NETSPH_HD void symplectic_predict(const Vec3d& r0, const Vec3f& v0, Real rho0, const Vec3f& acc,
                                  Real drho, double dt, Vec3d& r, Vec3f& v, Real& rho) {
  const double half = 0.5 * dt;
  r = r0 + Vec3d(v0) * half;
  v = v0 + acc * static_cast<Real>(half);
  rho = symplectic_density_half(rho0, drho, dt);
}

NETSPH_HD void symplectic_correct(const Vec3d& r0, const Vec3f& v0, Real rho0, const Vec3f& acc,
                                  Real drho, Real rho_half, double dt, Vec3d& r, Vec3f& v,
                                  Real& rho) {
  const Real dtr = static_cast<Real>(dt);
  v = v0 + acc * dtr;
  r = r0 + (Vec3d(v0) + Vec3d(v)) * (0.5 * dt);
  rho = symplectic_density_full(rho0, drho, rho_half, dt);
}

/// Whether a particle's state is usable: finite position, velocity and density, density > 0
/// (the solvers' instability check after each corrector).
NETSPH_HD bool finite_state(const Vec3d& r, const Vec3f& v, Real rho) {
  return std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) && std::isfinite(v.x) &&
         std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(rho) && rho > 0;
}

/// DBC boundary particles keep at least the reference density so that they never attract
/// fluid (DualSPHysics does the same).
NETSPH_HD Real clamp_boundary_density(Real rho, Real rho_ref) {
  return rho < rho_ref ? rho_ref : rho;
}

}  // namespace netsph
