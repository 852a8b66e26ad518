#pragma once
// The per-particle work of one time step in the shape a GPU runs it: one call per particle,
// reading other particles only through raw arrays, writing only its own slot. The CUDA
// backend launches these functions as kernels (backend/cuda/); the host executor runs the same
// functions in an OpenMP loop, so CI checks their logic against the CPU backend on machines
// without a GPU (tests/physics/device_parity_test.cpp). The physics is not written here: the
// pair terms, the ghost-node solve, the wall state, the integrator and shifting come from
// sph/ and boundary/, as the CPU backend calls them.
#include <cmath>
#include <cstdint>

#include "netsph/backend/device/device_grid.hpp"
#include "netsph/boundary/mdbc.hpp"
#include "netsph/core/host_device.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/pair_interaction.hpp"
#include "netsph/sph/particle_set.hpp"
#include "netsph/sph/shifting.hpp"
#include "netsph/sph/symplectic.hpp"

namespace netsph {

/// Per-wall constants a kernel needs (fixed walls only in this version of the device step).
struct DeviceWall {
  bool mdbc = false;
  WallSlip slip = WallSlip::WallVelocity;
  /// DBC, or mDBC showing the wall's own velocity: the fluid sees v = 0 in both equations.
  bool shows_own_velocity = true;
};

/// The particle arrays of the state being advanced (sorted by cell).
struct DeviceState {
  Vec3d* pos;
  Vec3f* vel;
  Real* rho;
  ParticleKind* kind;
  std::uint32_t* id;
  std::uint32_t* group;
  Vec3f* ghost;
};

/// What the interaction reads: float positions relative to the grid origin (as the CPU view,
/// backend/cpu/interaction_view.hpp), velocities, density, pressure from the equation of state
/// once per particle, and the fluid flag. cvx.. is the velocity continuity sees (the solid's own
/// velocity under a mirror slip condition); it aliases vx.. when no wall mirrors.
struct DeviceView {
  Real *x, *y, *z, *vx, *vy, *vz, *cvx, *cvy, *cvz, *rho, *press, *fluid;
};

/// The rates of one pass.
struct DeviceRates {
  Vec3f* acc;
  Real* drho;
  Real* acc2;     ///< |a|^2 of fluid particles (0 for others): the force criterion of dt
  Real* visc_dt;  ///< max |h v_ab.r_ab/(r^2+eta^2)| of the particle's pairs
  Vec3f* grad_c;  ///< shifting sums, or null
  Real* div_r;
};

/// The view of particle i (InteractionView::build).
NETSPH_HD void device_view_particle(const DeviceState& s, const DeviceView& v, const FluidModel& m,
                                    const DeviceWall* walls, const Vec3d& origin, std::uint32_t i,
                                    bool mirrors) {
  const Vec3d p = s.pos[i];
  v.x[i] = static_cast<Real>(p.x - origin.x);
  v.y[i] = static_cast<Real>(p.y - origin.y);
  v.z[i] = static_cast<Real>(p.z - origin.z);
  const Vec3f u = s.vel[i];
  v.vx[i] = u.x, v.vy[i] = u.y, v.vz[i] = u.z;
  v.rho[i] = s.rho[i];
  v.press[i] = m.eos.pressure(s.rho[i]);
  const ParticleKind k = s.kind[i];
  v.fluid[i] = (k == ParticleKind::Fluid || k == ParticleKind::Buffer) ? Real(1) : Real(0);
  if (mirrors) {
    // A fixed wall under a mirror slip condition shows its own velocity, zero, to continuity.
    const bool mirrored = k == ParticleKind::Wall && !walls[s.group[i]].shows_own_velocity;
    v.cvx[i] = mirrored ? Real(0) : u.x;
    v.cvy[i] = mirrored ? Real(0) : u.y;
    v.cvz[i] = mirrored ? Real(0) : u.z;
  }
}

/// Rates of particle a: fluid particles sum every neighbour (fluid_pair_rates), wall particles
/// the fluid ones (boundary_pair_rates), as backend/cpu/rates.cpp.
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
NETSPH_HD void device_rates_particle(const DeviceGrid& g, const std::uint32_t* cell_begin,
                                     const std::uint32_t* keys, const ParticleKind* kind,
                                     const DeviceView& v, const FluidModel& m,
                                     const DeviceRates& out, std::uint32_t a) {
  const ParticleKind ka = kind[a];
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const Real cxa = v.cvx[a], cya = v.cvy[a], cza = v.cvz[a];
  const Real rho_a = v.rho[a], press_a = v.press[a];
  const bool fluid_a = ka == ParticleKind::Fluid;
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0, gx = 0, gy = 0, gz = 0, div = 0;
  if (fluid_a || ka == ParticleKind::Wall) {
    g.for_each_range(cell_begin, keys[a], [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      const Real xs = xa - shift.x, ys = ya - shift.y, zs = za - shift.z;
      for (std::uint32_t b = b0; b < b1; ++b) {
        const Real dx = xs - v.x[b], dy = ys - v.y[b], dz = zs - v.z[b];
        const Real r2 = dx * dx + dy * dy + dz * dz;
        if (!(r2 < m.support2) || b == a) continue;
        if (fluid_a) {
          const Neighbour nb{{dx, dy, dz},
                             r2,
                             {vxa - v.vx[b], vya - v.vy[b], vza - v.vz[b]},
                             {vxa - v.cvx[b], vya - v.cvy[b], vza - v.cvz[b]},
                             v.rho[b],
                             v.press[b],
                             m.mass,
                             v.fluid[b]};
          const PairRates s = fluid_pair_rates<Kernel, Visc, Diff>(m, rho_a, press_a, nb);
          ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
          vdt = vdt > s.visc_dt ? vdt : s.visc_dt;
          if constexpr (Shift) {
            const Real vf = m.mass / v.rho[b] * kernel_grad_factor<Kernel>(m.kernel, std::sqrt(r2));
            gx += vf * dx, gy += vf * dy, gz += vf * dz;
            div -= vf * r2;
          }
        } else if (v.fluid[b] > Real(0)) {
          const Neighbour nb{{dx, dy, dz},
                             r2,
                             {vxa - v.vx[b], vya - v.vy[b], vza - v.vz[b]},
                             {cxa - v.vx[b], cya - v.vy[b], cza - v.vz[b]},
                             v.rho[b],
                             v.press[b],
                             m.mass,
                             v.fluid[b]};
          const PairRates s = boundary_pair_rates<Kernel>(m, nb);
          dr += s.drho;
          vdt = vdt > s.visc_dt ? vdt : s.visc_dt;
        }
      }
    });
  }
  if (fluid_a) {
    const Vec3f total{ax + m.gravity.x, ay + m.gravity.y, az + m.gravity.z};
    out.acc[a] = total;
    out.acc2[a] = total.x * total.x + total.y * total.y + total.z * total.z;
  } else {
    out.acc[a] = Vec3f{};
    out.acc2[a] = 0;
  }
  out.drho[a] = dr;
  out.visc_dt[a] = vdt;
  if constexpr (Shift) {
    out.grad_c[a] = Vec3f{gx, gy, gz};
    out.div_r[a] = div;
  }
}

/// mDBC state of wall particle i (Simulation::apply_mdbc with a fixed wall): the ghost node's
/// first-order value over the fluid (and buffer) particles in reach, extrapolated back.
template <class Kernel>
NETSPH_HD void device_mdbc_particle(const DeviceGrid& g, const std::uint32_t* cell_begin,
                                    const DeviceState& s, const DeviceWall* walls,
                                    const FluidModel& m, std::uint32_t i) {
  if (s.kind[i] != ParticleKind::Wall) return;
  const DeviceWall w = walls[s.group[i]];
  const Vec3f off = s.ghost[i];
  const bool has_ghost = off.x != 0 || off.y != 0 || off.z != 0;
  if (!w.mdbc || !has_ghost) {
    if (w.shows_own_velocity) s.vel[i] = Vec3f{};
    return;
  }
  const Vec3d point = g.wrapped(s.pos[i] + Vec3d(off));
  GhostSums sums;
  const std::uint32_t c = g.key_of(point);
  if (c != g.sentinel()) {
    g.for_each_range(cell_begin, c, [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      const Vec3d sh(shift);
      for (std::uint32_t j = b0; j < b1; ++j) {
        const ParticleKind kj = s.kind[j];
        if (kj == ParticleKind::Wall || kj == ParticleKind::Body) continue;
        const Vec3f d(s.pos[j] + sh - point);
        const Real r2 = d.x * d.x + d.y * d.y + d.z * d.z;
        if (!(r2 < m.support2)) continue;
        const Real r = std::sqrt(r2);
        ghost_accumulate(sums, d, kernel_value<Kernel>(m.kernel, r),
                         kernel_grad_factor<Kernel>(m.kernel, r), m.mass, s.rho[j], s.vel[j]);
      }
    });
  }
  const GhostValue gv = ghost_solve(sums, m.dims);
  const WallState st = mdbc_wall_state(gv, off, m.eos.rho0, w.slip, Vec3f{});
  s.rho[i] = st.rho;
  s.vel[i] = st.vel;
}

/// The step-start copy of one particle.
struct DeviceStart {
  Vec3d* pos;
  Vec3f* vel;
  Real* rho;
};

/// Predictor (half step) of particle i; returns its displacement squared. Fixed walls stay in
/// place and integrate continuity (backend/cpu/integrate.cpp).
NETSPH_HD double device_predict_particle(const DeviceState& p, const DeviceStart& s,
                                         const DeviceRates& r, const DeviceWall* walls,
                                         const FluidModel& m, double dt, std::uint32_t i) {
  if (p.kind[i] == ParticleKind::Fluid) {
    symplectic_predict(s.pos[i], s.vel[i], s.rho[i], r.acc[i], r.drho[i], dt, p.pos[i], p.vel[i],
                       p.rho[i]);
  } else if (p.kind[i] == ParticleKind::Wall) {
    p.pos[i] = s.pos[i];
    if (walls[p.group[i]].shows_own_velocity) p.vel[i] = Vec3f{};
    p.rho[i] = clamp_boundary_density(symplectic_density_half(s.rho[i], r.drho[i], dt), m.eos.rho0);
  }
  const Vec3d d = p.pos[i] - s.pos[i];
  return d.x * d.x + d.y * d.y + d.z * d.z;
}

/// Corrector of particle i, with shifting when `shift` is given; returns false when the state
/// is not finite.
NETSPH_HD bool device_correct_particle(const DeviceState& p, const DeviceStart& s,
                                       const DeviceRates& r, const DeviceWall* walls,
                                       const FluidModel& m, const ShiftingParams* shift, double dt,
                                       std::uint32_t i) {
  if (p.kind[i] == ParticleKind::Fluid) {
    const Real rho_half = p.rho[i];
    symplectic_correct(s.pos[i], s.vel[i], s.rho[i], r.acc[i], r.drho[i], rho_half, dt, p.pos[i],
                       p.vel[i], p.rho[i]);
    if (shift) {
      const Vec3f u = p.vel[i];
      p.pos[i] += Vec3d(shifting_displacement(*shift, r.grad_c[i], r.div_r[i],
                                              std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z),
                                              static_cast<Real>(dt)));
    }
  } else if (p.kind[i] == ParticleKind::Wall) {
    p.pos[i] = s.pos[i];
    if (walls[p.group[i]].shows_own_velocity) p.vel[i] = Vec3f{};
    const Real rho_new = symplectic_density_full(s.rho[i], r.drho[i], p.rho[i], dt);
    p.rho[i] = clamp_boundary_density(rho_new, m.eos.rho0);
  }
  const Vec3d x = p.pos[i];
  const Vec3f u = p.vel[i];
  return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) && std::isfinite(u.x) &&
         std::isfinite(u.y) && std::isfinite(u.z) && std::isfinite(p.rho[i]) && p.rho[i] > 0;
}

}  // namespace netsph
