#include "netsph/backend/cpu/integrate.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/growth.hpp"
#include "netsph/sph/symplectic.hpp"

namespace netsph {

void StepStart::save(const ParticleSet& p) {
  resize_for(vel, p.size()), resize_for(rho, p.size());
  const auto n = static_cast<std::int64_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) vel[i] = p.vel[i], rho[i] = p.rho[i];
}

double symplectic_predictor(ParticleSet& p, const StageInputs& in, const FluidModel& m,
                            const std::uint8_t* counted) {
  const auto n = static_cast<std::int64_t>(p.size());
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2)
  for (std::int64_t i = 0; i < n; ++i) {
    const ParticleKind k = p.kind[i];
    const WallKinematics* wall = k == ParticleKind::Wall ? &in.walls[p.group[i]] : nullptr;
    const double d2 = symplectic_predict_particle(k, wall, in.acc[i], in.drho[i], in.dt, m.eos.rho0,
                                                  p.pos[i], p.vel[i], p.rho[i]);
    if (!counted || counted[i]) max_d2 = std::max(max_d2, d2);
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
    const ParticleKind k = p.kind[i];
    const WallKinematics* wall = k == ParticleKind::Wall ? &in.walls[p.group[i]] : nullptr;
    symplectic_correct_particle(k, wall, s.vel[i], s.rho[i], in.acc[i], in.drho[i], dt, m.eos.rho0,
                                p.pos[i], p.vel[i], p.rho[i]);
    if (shifting && k == ParticleKind::Fluid)
      shift_position(*shift_params, shifting->grad_c[i], shifting->div_r[i], p.vel[i], dt,
                     p.pos[i]);
    if (!finite_state(p.pos[i], p.vel[i], p.rho[i])) bad = std::min(bad, i);
  }
  return bad == n ? -1 : bad;
}

void apply_damping(ParticleSet& p, std::span<const DampingZone> zones, double t, double dt) {
  const auto n = static_cast<std::int64_t>(p.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p.kind[i] != ParticleKind::Fluid) continue;
    for (const DampingZone& z : zones) damp_velocity(z, p.pos[i], t, dt, p.vel[i]);
  }
}

}  // namespace netsph
