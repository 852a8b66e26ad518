#include "netsph/backend/cpu/integrate.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/sph/symplectic.hpp"

namespace netsph {

void StepStart::save(const ParticleSet& p) {
  pos.resize(p.size()), vel.resize(p.size()), rho.resize(p.size());
  const auto n = static_cast<std::int64_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) pos[i] = p.pos[i], vel[i] = p.vel[i], rho[i] = p.rho[i];
}

double symplectic_predictor(ParticleSet& p, const StepStart& s, const StageInputs& in,
                            const FluidModel& m) {
  const auto n = static_cast<std::int64_t>(p.size());
  const double dt = in.dt;
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2)
  for (std::int64_t i = 0; i < n; ++i) {
    switch (p.kind[i]) {
      case ParticleKind::Fluid:
        symplectic_predict(s.pos[i], s.vel[i], s.rho[i], in.acc[i], in.drho[i], dt, p.pos[i],
                           p.vel[i], p.rho[i]);
        break;
      case ParticleKind::Wall: {
        const WallKinematics& w = in.walls[p.group[i]];
        p.pos[i] = s.pos[i] + Vec3d(w.start) * (0.5 * dt);
        if (w.shows_own_velocity) p.vel[i] = w.half;
        p.rho[i] =
            clamp_boundary_density(symplectic_density_half(s.rho[i], in.drho[i], dt), m.eos.rho0);
        break;
      }
      case ParticleKind::Buffer:
        p.pos[i] = s.pos[i] + Vec3d(s.vel[i]) * (0.5 * dt);
        break;
      case ParticleKind::Body:
        // Position and velocity follow the rigid body (Simulation::place_body_particles).
        p.rho[i] =
            clamp_boundary_density(symplectic_density_half(s.rho[i], in.drho[i], dt), m.eos.rho0);
        break;
    }
    max_d2 = std::max(max_d2, norm2(p.pos[i] - s.pos[i]));
  }
  return std::sqrt(max_d2);
}

std::int64_t symplectic_corrector(ParticleSet& p, const StepStart& s, const StageInputs& in,
                                  const FluidModel& m, const ShiftingSums* shifting,
                                  const ShiftingParams* shift_params) {
  const auto n = static_cast<std::int64_t>(p.size());
  const double dt = in.dt;
  std::int64_t bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (std::int64_t i = 0; i < n; ++i) {
    switch (p.kind[i]) {
      case ParticleKind::Fluid: {
        const Real rho_half = p.rho[i];
        symplectic_correct(s.pos[i], s.vel[i], s.rho[i], in.acc[i], in.drho[i], rho_half, dt,
                           p.pos[i], p.vel[i], p.rho[i]);
        if (shifting) {
          p.pos[i] +=
              Vec3d(shifting_displacement(*shift_params, shifting->grad_c[i], shifting->div_r[i],
                                          norm(p.vel[i]), static_cast<Real>(dt)));
        }
        break;
      }
      case ParticleKind::Wall: {
        const WallKinematics& w = in.walls[p.group[i]];
        // Exact for a velocity linear in time over the step (trapezoid rule).
        p.pos[i] = s.pos[i] + (Vec3d(w.start) + Vec3d(w.end)) * (0.5 * dt);
        if (w.shows_own_velocity) p.vel[i] = w.end;
        const Real rho_new = symplectic_density_full(s.rho[i], in.drho[i], p.rho[i], dt);
        p.rho[i] = clamp_boundary_density(rho_new, m.eos.rho0);
        break;
      }
      case ParticleKind::Buffer:
        p.pos[i] = s.pos[i] + Vec3d(s.vel[i]) * dt;
        break;
      case ParticleKind::Body: {
        const Real rho_new = symplectic_density_full(s.rho[i], in.drho[i], p.rho[i], dt);
        p.rho[i] = clamp_boundary_density(rho_new, m.eos.rho0);
        break;
      }
    }
    const bool finite = finite_state(p.pos[i], p.vel[i], p.rho[i]);
    if (!finite) bad = std::min(bad, i);
  }
  return bad == n ? -1 : bad;
}

}  // namespace netsph
