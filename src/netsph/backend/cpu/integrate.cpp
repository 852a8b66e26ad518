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

double symplectic_predictor(ParticleSet& p, const StepStart& s, std::span<const Vec3f> acc,
                            std::span<const Real> drho, double dt, const FluidModel& m) {
  const auto n = static_cast<std::int64_t>(p.size());
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2)
  for (std::int64_t i = 0; i < n; ++i) {
    if (is_fluid(p.kind[i])) {
      symplectic_predict(s.pos[i], s.vel[i], s.rho[i], acc[i], drho[i], dt, p.pos[i], p.vel[i],
                         p.rho[i]);
      max_d2 = std::max(max_d2, norm2(p.pos[i] - s.pos[i]));
    } else {
      p.rho[i] = clamp_boundary_density(symplectic_density_half(s.rho[i], drho[i], dt), m.eos.rho0);
    }
  }
  return std::sqrt(max_d2);
}

std::int64_t symplectic_corrector(ParticleSet& p, const StepStart& s, std::span<const Vec3f> acc,
                                  std::span<const Real> drho, double dt, const FluidModel& m) {
  const auto n = static_cast<std::int64_t>(p.size());
  std::int64_t bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (std::int64_t i = 0; i < n; ++i) {
    if (is_fluid(p.kind[i])) {
      const Real rho_half = p.rho[i];
      symplectic_correct(s.pos[i], s.vel[i], s.rho[i], acc[i], drho[i], rho_half, dt, p.pos[i],
                         p.vel[i], p.rho[i]);
      const bool finite = std::isfinite(p.pos[i].x) && std::isfinite(p.pos[i].y) &&
                          std::isfinite(p.pos[i].z) && std::isfinite(p.vel[i].x) &&
                          std::isfinite(p.vel[i].y) && std::isfinite(p.vel[i].z) &&
                          std::isfinite(p.rho[i]) && p.rho[i] > 0;
      if (!finite) bad = std::min(bad, i);
    } else {
      const Real rho_new = symplectic_density_full(s.rho[i], drho[i], p.rho[i], dt);
      p.rho[i] = clamp_boundary_density(rho_new, m.eos.rho0);
      if (!std::isfinite(p.rho[i])) bad = std::min(bad, i);
    }
  }
  return bad == n ? -1 : bad;
}

}  // namespace netsph
