#include "netsph/backend/cpu/interaction_view.hpp"

#include "netsph/core/growth.hpp"

namespace netsph {

void InteractionView::build(const ParticleSet& p, const FluidModel& m, const Vec3d& origin) {
  const auto n = static_cast<std::int64_t>(p.size());
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &rho, &press, &fluid}) resize_for(*v, p.size());
  cvx.clear(), cvy.clear(), cvz.clear();
  resize_for(solid, p.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    x[i] = static_cast<Real>(p.pos[i].x - origin.x);
    y[i] = static_cast<Real>(p.pos[i].y - origin.y);
    z[i] = static_cast<Real>(p.pos[i].z - origin.z);
    vx[i] = p.vel[i].x, vy[i] = p.vel[i].y, vz[i] = p.vel[i].z;
    rho[i] = p.rho[i];
    press[i] = m.eos.pressure(p.rho[i]);
    fluid[i] = carries_fluid(p.kind[i]) ? Real(1) : Real(0);
    solid[i] =
        p.kind[i] == ParticleKind::Wall
            ? kWallSolid
            : (p.kind[i] == ParticleKind::Body ? static_cast<std::int32_t>(p.group[i]) : kNotSolid);
  }
}

void InteractionView::with_continuity_velocity() {
  for (auto* v : {&cvx, &cvy, &cvz}) reserve_for(*v, vx.size());
  cvx = vx, cvy = vy, cvz = vz;
}

}  // namespace netsph
