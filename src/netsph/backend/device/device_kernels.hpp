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
#include <limits>

#include "netsph/backend/device/device_types.hpp"
#include "netsph/bodies/rigid_body.hpp"
#include "netsph/boundary/mdbc.hpp"
#include "netsph/boundary/open_boundary.hpp"
#include "netsph/core/host_device.hpp"
#include "netsph/neighbours/grid_index.hpp"
#include "netsph/sph/contact.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/pair_interaction.hpp"
#include "netsph/sph/particle_set.hpp"
#include "netsph/sph/shepard.hpp"
#include "netsph/sph/shifting.hpp"
#include "netsph/sph/symplectic.hpp"

namespace netsph {

/// The particle arrays of the state being advanced (sorted by cell). The mDBC ghost vectors
/// are not among them: only solids have one, so they live in tables of the solids
/// (DeviceGhosts), 12 B a particle less for every particle and one array less to sort.
struct DeviceState {
  Vec3d* pos;
  Vec3f* vel;
  Real* rho;
  ParticleKind* kind;
  std::uint32_t* id;
  std::uint32_t* group;
};

/// The solids' mDBC ghost vectors: a wall particle's is fixed (walls translate), in a table by
/// particle id (the walls are built first, so their ids are 0, 1, ...); a body particle's
/// turns with its body, from the body-frame table (DeviceBody::offset_base).
struct DeviceGhosts {
  const Vec3f* wall;  ///< by particle id, wall_count entries
  std::uint32_t wall_count;
  const Vec3f* body;
  int dims;
};

/// The ghost vector of particle i (zero for fluid and buffer particles, and for solids
/// without one), the one ParticleSet::ghost holds on the CPU.
NETSPH_HD Vec3f device_solid_ghost(const DeviceState& s, const DeviceBody* bodies,
                                   const DeviceGhosts& gh, std::uint32_t i) {
  const ParticleKind k = s.kind[i];
  if (k == ParticleKind::Wall) return s.id[i] < gh.wall_count ? gh.wall[s.id[i]] : Vec3f{};
  if (k != ParticleKind::Body) return {};
  const DeviceBody& b = bodies[s.group[i]];
  return rigid_ghost(b.state, gh.body[b.offset_base + (s.id[i] - b.first_id)], gh.dims);
}

/// A particle's float position relative to the grid origin and its pressure in one 16-byte
/// element: the candidate test, the hottest loop of the step, reads a neighbour's position
/// with one load (a 128-bit load on the GPU, as DualSPHysics' pospress) instead of three, and
/// its pressure comes with it. Same bytes as four separate arrays.
struct alignas(16) PosPress {
  Real x, y, z, p;
};

/// A particle's velocity and density in one 16-byte element, as DualSPHysics' velrhop: a
/// neighbour's pair terms then read it with one load (a 128-bit load on the GPU) instead of
/// four scattered ones, and the pair's loads are this, its PosPress and its kind.
struct alignas(16) VelRho {
  Real vx, vy, vz, rho;
};

/// What the interaction reads: positions and pressures (from the equation of state once per
/// particle), velocities and densities. Positions are relative to the grid origin, as the CPU
/// view (backend/cpu/interaction_view.hpp). cv is the velocity continuity sees (the solid's own
/// velocity under a mirror slip condition; its rho is not used), read only when `mirrors`;
/// otherwise it is vr. Whether a neighbour is fluid comes from the kind array (1 B a particle
/// instead of a float).
struct DeviceView {
  PosPress* pp;
  VelRho* vr;
  VelRho* cv;
  bool mirrors;
};

/// The rates of one pass.
struct DeviceRates {
  Vec3f* acc;  ///< fluid: total acceleration (with gravity); body: fluid force per unit mass
  Real* drho;
  Real* visc_dt;  ///< max |h v_ab.r_ab/(r^2+eta^2)| of the particle's pairs
  Vec3f* grad_c;  ///< shifting sums, or null
  Real* div_r;
};

/// The view of particle i (InteractionView::build).
NETSPH_HD void device_view_particle(const DeviceState& s, const DeviceView& v, const FluidModel& m,
                                    const DeviceWall* walls, const WallKinematics* motion,
                                    const DeviceBody* bodies, const Vec3d& origin,
                                    const Vec3d& period, std::uint32_t i, bool mirrors,
                                    bool half_step) {
  const Vec3d p = s.pos[i];
  v.pp[i] = {static_cast<Real>(p.x - origin.x), static_cast<Real>(p.y - origin.y),
             static_cast<Real>(p.z - origin.z), m.eos.pressure(s.rho[i])};
  const Vec3f u = s.vel[i];
  v.vr[i] = {u.x, u.y, u.z, s.rho[i]};
  const ParticleKind k = s.kind[i];
  if (mirrors) {
    // A solid under a mirror slip condition shows continuity its own velocity (Simulation::
    // build_view): the wall's, or the body's at this point.
    Vec3f c = u;
    if (k == ParticleKind::Wall && !walls[s.group[i]].shows_own_velocity) {
      const WallKinematics& w = motion[s.group[i]];
      c = half_step ? w.half : w.start;
    } else if (k == ParticleKind::Body && !bodies[s.group[i]].shows_own_velocity) {
      const RigidState& b = bodies[s.group[i]].state;
      c = Vec3f(rigid_point_velocity(b, rigid_lever_arm(b, s.pos[i], period)));
    }
    v.cv[i] = {c.x, c.y, c.z, Real(0)};
  }
}

/// The periodic shift that brings a neighbour at offset d (along one axis) within reach: the
/// nearest image. A neighbour is within the support (< period / 2.5, CellGrid) through exactly
/// one shift, the one GridIndex::next_range gave its range. period 0: not periodic.
NETSPH_HD Real nearest_image_shift(Real d, Real period) {
  if (!(period > 0)) return 0;
  return d > Real(0.5) * period ? period : (d < Real(-0.5) * period ? -period : Real(0));
}

/// The offset from candidate b to particle a (its position shifted across periodic
/// boundaries) and its square.
struct PairOffset {
  Real dx, dy, dz, r2;
};
NETSPH_HD PairOffset pair_offset(Real xa, Real ya, Real za, Vec3f shift, const PosPress& pb) {
  const Real dx = (xa - shift.x) - pb.x, dy = (ya - shift.y) - pb.y, dz = (za - shift.z) - pb.z;
  return {dx, dy, dz, dx * dx + dy * dy + dz * dz};
}

/// Rates of particle a: fluid particles sum every neighbour (fluid_pair_rates), wall particles
/// the fluid ones (boundary_pair_rates), as backend/cpu/rates.cpp.
///
/// The scan gathers the neighbours it finds (at most kRatesBatchMax) and sums them when, at the
/// end of a range (a row of cells), any thread of the warp holds `batch` or more (any_lane): then
/// every thread of the warp sums what it holds, together (batch 0: each pair is summed where
/// it is found). Why: the 32 threads of a GPU warp execute together, and about a quarter of the
/// candidates in the cells of size h around a particle are neighbours. Summing each pair where
/// the scan finds it (DualSPHysics' loop) runs the pair terms whenever any thread of the warp
/// has just found one, with most threads idle, so the warp pays the pair terms for nearly every
/// candidate. Gathered and summed warp by warp, most threads of the warp have pairs to sum each
/// time the warp pays for the terms. (A first version let each thread sum its own full batch,
/// scanning on where it stopped: the threads went out of step across the rows, and on an H200
/// it was 24% slower than no batch at all, docs/PERFORMANCE.md.) The neighbours, their order
/// and the sums are those of a single loop, whatever the batch size (bit for bit on the host;
/// nvcc may fuse the recomputed r^2 into other FMAs than the scan's: a last-bit difference).
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
NETSPH_HD void device_rates_particle(const GridIndex& g, const std::uint32_t* cell_begin,
                                     const std::uint32_t* keys, const ParticleKind* kind,
                                     const DeviceView& v, const FluidModel& m,
                                     const DeviceRates& out, std::uint32_t a, std::uint32_t batch) {
  const ParticleKind ka = kind[a];
  const PosPress pa = v.pp[a];
  const Real xa = pa.x, ya = pa.y, za = pa.z, press_a = pa.p;
  const VelRho ua = v.vr[a];
  const Real vxa = ua.vx, vya = ua.vy, vza = ua.vz, rho_a = ua.rho;
  const VelRho ca = v.mirrors ? v.cv[a] : ua;
  const Real cxa = ca.vx, cya = ca.vy, cza = ca.vz;
  const bool fluid_a = ka == ParticleKind::Fluid, body_a = ka == ParticleKind::Body;
  // A body sees gauge pressures (backend/cpu/rates.cpp, body_sums, says why).
  const Real p_bg = m.eos.p_background;
  const PairCentre centre = pair_centre(rho_a, body_a ? press_a - p_bg : press_a);
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0, gx = 0, gy = 0, gz = 0, div = 0;
  const Real px = static_cast<Real>(g.period[0]), py = static_cast<Real>(g.period[1]),
             pz = static_cast<Real>(g.period[2]);
  // Neighbour b at offset o, pressure press_b.
  const auto add_pair = [&](std::uint32_t b, const PairOffset& o,
                            Real press_b) NETSPH_INLINE_LAMBDA {
    const Real dx = o.dx, dy = o.dy, dz = o.dz, r2 = o.r2;
    const Real fluid_b = carries_fluid(kind[b]) ? Real(1) : Real(0);
    const VelRho ub = v.vr[b];
    if (fluid_a) {
      const VelRho cb = v.mirrors ? v.cv[b] : ub;
      const Neighbour nb{{dx, dy, dz},
                         r2,
                         {vxa - ub.vx, vya - ub.vy, vza - ub.vz},
                         {vxa - cb.vx, vya - cb.vy, vza - cb.vz},
                         ub.rho,
                         press_b,
                         m.mass,
                         fluid_b};
      const PairRates s = fluid_pair_rates<Kernel, Visc, Diff>(m, centre, nb);
      ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
      vdt = vdt > s.visc_dt ? vdt : s.visc_dt;
      if constexpr (Shift) {
        const Real vf = s.vol_grad;
        gx += vf * dx, gy += vf * dy, gz += vf * dz;
        div -= vf * r2;
      }
    } else if (fluid_b > Real(0)) {
      // A solid sees its fluid neighbours with its own velocity in continuity; a body
      // also takes their force, with gauge pressures.
      const Real p_off = body_a ? p_bg : Real(0);
      const Neighbour nb{{dx, dy, dz},
                         r2,
                         {vxa - ub.vx, vya - ub.vy, vza - ub.vz},
                         {cxa - ub.vx, cya - ub.vy, cza - ub.vz},
                         ub.rho,
                         press_b - p_off,
                         m.mass,
                         fluid_b};
      const PairRates s =
          body_a ? fluid_pair_rates<Kernel, Visc, DensityDiffusion::None>(m, centre, nb)
                 : boundary_pair_rates<Kernel>(m, nb);
      ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
      vdt = vdt > s.visc_dt ? vdt : s.visc_dt;
    }
  };
  // Every candidate cell is scanned: a scan of only the cells within reach of a was slower on
  // an H200 (its threads skip different cells and their warp waits for them), and the cursor
  // that trimmed it kept six floats and a flag live through the loop (docs/PERFORMANCE.md, "CUDA").
  if (ka == ParticleKind::Buffer) {
    // Buffers have no rates.
  } else if (batch == 0) {
    // Each pair summed where the scan finds it: kept to measure the batches against.
    g.for_each_range(cell_begin, keys[a], [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      for (std::uint32_t b = b0; b < b1; ++b) {
        const PosPress pb = v.pp[b];
        const PairOffset o = pair_offset(xa, ya, za, shift, pb);
        if (o.r2 < m.support2 && b != a) add_pair(b, o, pb.p);
      }
    });
  } else {
    std::uint32_t hits[kRatesBatchMax];
    std::uint32_t found = 0;
    const auto sum_hits = [&]() NETSPH_INLINE_LAMBDA {
      for (std::uint32_t k = 0; k < found; ++k) {
        const std::uint32_t nb = hits[k];
        const PosPress pb = v.pp[nb];
        const Vec3f image(nearest_image_shift(xa - pb.x, px), nearest_image_shift(ya - pb.y, py),
                          nearest_image_shift(za - pb.z, pz));
        add_pair(nb, pair_offset(xa, ya, za, image, pb), pb.p);
      }
      found = 0;
    };
    g.for_each_range(cell_begin, keys[a], [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
      for (std::uint32_t b = b0; b < b1; ++b) {
        if (pair_offset(xa, ya, za, shift, v.pp[b]).r2 < m.support2 && b != a) {
          hits[found++] = b;
          if (found == kRatesBatchMax) sum_hits();  // full inside a row: this thread alone
        }
      }
      if (any_lane(found >= batch)) sum_hits();
    });
    sum_hits();
  }
  if (fluid_a) {
    const Vec3f total{ax + m.gravity.x, ay + m.gravity.y, az + m.gravity.z};
    out.acc[a] = total;
  } else {
    // Body particles: the fluid's force per unit mass, without gravity (the body's weight acts
    // on its centre of mass); walls and buffers: none.
    out.acc[a] = body_a ? Vec3f{ax, ay, az} : Vec3f{};
  }
  out.drho[a] = dr;
  out.visc_dt[a] = vdt;
  if constexpr (Shift) {
    out.grad_c[a] = Vec3f{gx, gy, gz};
    out.div_r[a] = div;
  }
}

/// Calls f(j, d, r2) for every particle j within the support of `at` (wrapped into periodic
/// axes first) whose kind keep() accepts, d = x_j - at, r2 = |d|^2; none outside the grid.
template <class Keep, class F>
NETSPH_HD void device_visit_point(const GridIndex& g, const std::uint32_t* cell_begin,
                                  const DeviceState& s, Real support2, const Vec3d& at, Keep keep,
                                  F f) {
  const Vec3d point = g.wrapped(at);
  const std::uint32_t c = g.key_of(point);
  if (c == g.sentinel()) return;
  g.for_each_range(cell_begin, c, [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
    const Vec3d sh(shift);
    for (std::uint32_t j = b0; j < b1; ++j) {
      if (!keep(s.kind[j])) continue;
      const Vec3f d(s.pos[j] + sh - point);
      const Real r2 = d.x * d.x + d.y * d.y + d.z * d.z;
      if (r2 < support2) f(j, d, r2);
    }
  });
}

/// The ghost-node sums at `point` over the fluid and, unless `fluid_only`, buffer particles
/// within the support (backend/cpu/ghost_pass.hpp's ghost_sums_at); empty outside the grid.
template <class Kernel>
NETSPH_HD GhostSums device_ghost_sums(const GridIndex& g, const std::uint32_t* cell_begin,
                                      const DeviceState& s, const FluidModel& m, const Vec3d& at,
                                      bool fluid_only) {
  GhostSums sums;
  const auto keep = [&](ParticleKind k) {
    return fluid_only ? k == ParticleKind::Fluid
                      : k != ParticleKind::Wall && k != ParticleKind::Body;
  };
  device_visit_point(
      g, cell_begin, s, m.support2, at, keep, [&](std::uint32_t j, const Vec3f& d, Real r2) {
        const Real r = std::sqrt(r2);
        ghost_accumulate(sums, d, kernel_value<Kernel>(m.kernel, r),
                         kernel_grad_factor<Kernel>(m.kernel, r), m.mass, s.rho[j], s.vel[j]);
      });
  return sums;
}

/// Shepard sums at point `at` over the fluid particles (not buffers, walls or bodies) within
/// the support (backend/cpu/probe_pass.hpp's point_sums); empty outside the grid.
template <class Kernel>
NETSPH_HD ShepardSums device_point_sums(const GridIndex& g, const std::uint32_t* cell_begin,
                                        const DeviceState& s, const FluidModel& m,
                                        const Vec3d& at) {
  ShepardSums sums;
  device_visit_point(
      g, cell_begin, s, m.support2, at, [](ParticleKind k) { return k == ParticleKind::Fluid; },
      [&](std::uint32_t j, const Vec3f&, Real r2) {
        shepard_accumulate_fluid(sums, kernel_value<Kernel>(m.kernel, std::sqrt(r2)), m.mass,
                                 s.rho[j], s.vel[j], m.eos);
      });
  return sums;
}

/// mDBC state of wall or body particle i (Simulation::apply_mdbc): the ghost node's
/// first-order value over the fluid (and buffer) particles in reach, extrapolated back. Walls
/// without a ghost (DBC) show their own velocity.
template <class Kernel>
NETSPH_HD void device_mdbc_particle(const GridIndex& g, const std::uint32_t* cell_begin,
                                    const DeviceState& s, const DeviceWall* walls,
                                    const WallKinematics* motion, const DeviceBody* bodies,
                                    const DeviceGhosts& ghosts, const FluidModel& m,
                                    std::uint32_t i) {
  const ParticleKind k = s.kind[i];
  if (k != ParticleKind::Wall && k != ParticleKind::Body) return;
  const Vec3f off = device_solid_ghost(s, bodies, ghosts, i);
  const bool has_ghost = off.x != 0 || off.y != 0 || off.z != 0;
  WallSlip slip;
  Vec3f v_solid;
  if (k == ParticleKind::Wall) {
    const DeviceWall w = walls[s.group[i]];
    v_solid = motion[s.group[i]].start;
    if (!w.mdbc || !has_ghost) {
      if (w.shows_own_velocity) s.vel[i] = v_solid;
      return;
    }
    slip = w.slip;
  } else {
    if (!has_ghost) return;  // body ghosts are zero unless the body uses mDBC
    const DeviceBody& b = bodies[s.group[i]];
    slip = b.slip;
    v_solid = Vec3f(rigid_point_velocity(b.state, rigid_lever_arm(b.state, s.pos[i], g.period)));
  }
  const GhostSums sums = device_ghost_sums<Kernel>(g, cell_begin, s, m, s.pos[i] + Vec3d(off),
                                                   /*fluid_only=*/false);
  const GhostValue gv = ghost_solve(sums, m.dims);
  const WallState st = mdbc_wall_state(gv, off, m.eos.rho0, slip, v_solid);
  s.rho[i] = st.rho;
  s.vel[i] = st.vel;
}

/// What an open-boundary transition did to a particle, for the step's counts.
enum DeviceOpenEvent : std::uint32_t {
  kNoOpenEvent = 0,
  kRemovedEvent = 1,   ///< left through a face
  kEnteredEvent = 2,   ///< a buffer particle became fluid
  kAbsorbedEvent = 3,  ///< a fluid particle became an outlet's (or inlet's) buffer particle
};

/// The open-boundary transition of particle i (boundary/open_boundary.cpp's rules, applied in
/// place); create[i] = 1 when an inlet must create a buffer particle behind it; event[i] says
/// what happened (DeviceOpenEvent). A removed particle's position becomes NaN, so the sort
/// drops it.
NETSPH_HD void device_transition_particle(const DeviceState& s, const ZoneGeometry* zones,
                                          std::size_t nzones, std::uint32_t* create,
                                          std::uint32_t* event, std::uint32_t i) {
  std::uint32_t entered = 0;
  create[i] = 0, event[i] = kNoOpenEvent;
  switch (buffer_transition(zones, nzones, s.kind[i], s.group[i], s.pos[i], entered)) {
    case BufferTransition::None:
      break;
    case BufferTransition::ToFluidAndCreate:
      create[i] = 1;
      s.kind[i] = ParticleKind::Fluid;  // the group (its zone) is cleared by the creation
      event[i] = kEnteredEvent;
      break;
    case BufferTransition::ToFluid:
      s.kind[i] = ParticleKind::Fluid;
      s.group[i] = 0;
      event[i] = kEnteredEvent;
      break;
    case BufferTransition::Remove: {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      s.pos[i] = Vec3d(nan, nan, nan);
      event[i] = kRemovedEvent;
      break;
    }
    case BufferTransition::ToBuffer:
      s.kind[i] = ParticleKind::Buffer;
      s.group[i] = entered;
      event[i] = kAbsorbedEvent;
      break;
  }
}

/// The buffer particle an inlet creates behind particle i (which entered the fluid), in slot
/// `slot` with id `id`; then clears i's group.
NETSPH_HD void device_create_buffer_particle(const DeviceState& s, const ZoneGeometry* zones,
                                             std::uint32_t i, std::uint32_t slot,
                                             std::uint32_t id) {
  const std::uint32_t zone = s.group[i];
  s.pos[slot] = created_buffer_position(zones[zone], s.pos[i]);
  s.vel[slot] = s.vel[i];
  s.rho[slot] = s.rho[i];
  s.kind[slot] = ParticleKind::Buffer;
  s.id[slot] = id;
  s.group[slot] = zone;
  s.group[i] = 0;
}

/// State of buffer particle i (Simulation::apply_open_boundary_state): imposed velocity,
/// reference or hydrostatic density, and where the zone extrapolates, the ghost node's value
/// over the fluid particles mirrored across the interface.
template <class Kernel>
NETSPH_HD void device_buffer_state_particle(const GridIndex& g, const std::uint32_t* cell_begin,
                                            const DeviceState& s, const DeviceZone* zones,
                                            const double* profile_z, const double* profile_u,
                                            double gz, const FluidModel& m, std::uint32_t i) {
  if (s.kind[i] != ParticleKind::Buffer) return;
  const DeviceZone z = zones[s.group[i]];
  const Vec3d p = s.pos[i];
  if (z.velocity_imposed) {
    const double u = inflow_speed(z.speed, profile_z + z.profile_begin, profile_u + z.profile_begin,
                                  z.profile_count, p.z);
    s.vel[i] = buffer_velocity(z.geo.axis, z.geo.inward, z.geo.inlet, u);
  }
  if (z.density == BufferDensity::Reference) s.rho[i] = m.eos.rho0;
  if (z.density == BufferDensity::Hydrostatic)
    s.rho[i] = hydrostatic_buffer_density(m.eos, gz, z.geo.surface_z, p.z);
  if (z.velocity_imposed && z.density != BufferDensity::Extrapolated) return;
  // The ghost node: p mirrored across the interface (OpenBoundaryZone::ghost_of).
  const double depth = buffer_depth(z.geo.axis, z.geo.inward, z.geo.plane, p);
  Vec3d ghost = p;
  ghost[z.geo.axis] += z.geo.inward * (2 * depth);
  const GhostSums sums = device_ghost_sums<Kernel>(g, cell_begin, s, m, ghost, /*fluid_only=*/true);
  const GhostValue gv = ghost_solve(sums, m.dims);
  if (!gv.any) return;  // no fluid in reach: keep the previous state
  if (z.density == BufferDensity::Extrapolated) {
    // First-order extrapolation from the ghost node back to the buffer particle.
    const Vec3d to_b = p - ghost;
    s.rho[i] = static_cast<Real>(gv.first_order ? gv.rho + dot(gv.grad_rho, to_b) : gv.rho);
  }
  if (!z.velocity_imposed) s.vel[i] = Vec3f(gv.vel);
}

/// Which solid particle i belongs to (as InteractionView::solid): -1 fluid or buffer, -2 wall,
/// else its body's index. Read from the kind and group arrays rather than stored: 4 B a
/// particle less on the device.
NETSPH_HD std::int32_t device_solid_of(const ParticleKind* kind, const std::uint32_t* group,
                                       std::uint32_t i) {
  const ParticleKind k = kind[i];
  if (k == ParticleKind::Wall) return -2;
  return k == ParticleKind::Body ? static_cast<std::int32_t>(group[i]) : -1;
}

/// Contact acceleration of body particle a from the particles of other solids
/// (backend/cpu/contact.cpp); zero for other particles.
NETSPH_HD Vec3f device_contact_particle(const GridIndex& g, const std::uint32_t* cell_begin,
                                        const std::uint32_t* keys, const ParticleKind* kind,
                                        const std::uint32_t* group, const DeviceView& v,
                                        const ContactModel& model, std::uint32_t a) {
  if (kind[a] != ParticleKind::Body) return {};
  const std::int32_t self = static_cast<std::int32_t>(group[a]);
  Vec3f acc{};
  g.for_each_range(cell_begin, keys[a], [&](std::uint32_t b0, std::uint32_t b1, Vec3f shift) {
    const PosPress q = v.pp[a];
    const Vec3f pa(q.x - shift.x, q.y - shift.y, q.z - shift.z);
    for (std::uint32_t b = b0; b < b1; ++b) {
      const std::int32_t other = device_solid_of(kind, group, b);
      if (other == -1 || other == self) continue;
      const PosPress pb = v.pp[b];
      // The solids' own velocities (the continuity velocity; CPU: contact.cpp).
      const VelRho ua = v.mirrors ? v.cv[a] : v.vr[a], ub = v.mirrors ? v.cv[b] : v.vr[b];
      acc += contact_acceleration(model, pa - Vec3f(pb.x, pb.y, pb.z),
                                  Vec3f(ua.vx - ub.vx, ua.vy - ub.vy, ua.vz - ub.vz));
    }
  });
  return acc;
}

/// Places body particle i rigidly on its body's state (Simulation::place_body_particles);
/// returns its displacement squared from where it was (0 unless `measure`).
NETSPH_HD double device_place_body_particle(const DeviceState& s, const DeviceBody* bodies,
                                            const Vec3f* offsets, const Vec3f* ghosts, int dims,
                                            const Vec3d& period, bool measure, std::uint32_t i) {
  if (s.kind[i] != ParticleKind::Body) return 0;
  const DeviceBody& b = bodies[s.group[i]];
  const std::uint32_t k = b.offset_base + (s.id[i] - b.first_id);
  Vec3f ghost;  // not kept: device_solid_ghost turns it when mDBC needs it
  const double d2 = place_rigid_particle(b.state, offsets[k], ghosts[k], dims, b.shows_own_velocity,
                                         period, s.pos[i], s.vel[i], ghost);
  return measure ? d2 : 0.0;
}

/// The step start's velocity and density, which the corrector starts from.
struct DeviceStart {
  Vec3f* vel;
  Real* rho;
};

/// Predictor (half step) of particle i, from the step-start state it holds; returns its
/// displacement squared (sph/symplectic.hpp, as the CPU backend).
NETSPH_HD double device_predict_particle(const DeviceState& p, const DeviceRates& r,
                                         const WallKinematics* motion, const FluidModel& m,
                                         double dt, std::uint32_t i) {
  const ParticleKind k = p.kind[i];
  const WallKinematics* wall = k == ParticleKind::Wall ? &motion[p.group[i]] : nullptr;
  return symplectic_predict_particle(k, wall, r.acc[i], r.drho[i], dt, m.eos.rho0, p.pos[i],
                                     p.vel[i], p.rho[i]);
}

/// Corrector of particle i, shifted when `shift` is set; returns false when the state is not
/// finite. The shifting parameters come by reference: a pointer to the kernel's copy put the
/// closure in local memory (a 264 B stack frame per thread, nvcc -Xptxas -v).
NETSPH_HD bool device_correct_particle(const DeviceState& p, const DeviceStart& s,
                                       const DeviceRates& r, const WallKinematics* motion,
                                       const FluidModel& m, bool shift,
                                       const ShiftingParams& shift_params, double dt,
                                       std::uint32_t i) {
  const ParticleKind k = p.kind[i];
  const WallKinematics* wall = k == ParticleKind::Wall ? &motion[p.group[i]] : nullptr;
  symplectic_correct_particle(k, wall, s.vel[i], s.rho[i], r.acc[i], r.drho[i], dt, m.eos.rho0,
                              p.pos[i], p.vel[i], p.rho[i]);
  if (shift && k == ParticleKind::Fluid)
    shift_position(shift_params, r.grad_c[i], r.div_r[i], p.vel[i], dt, p.pos[i]);
  return finite_state(p.pos[i], p.vel[i], p.rho[i]);
}

/// The loads one body particle adds to its body: force m a and its torque about the centre of
/// mass, r x m a (world frame; Simulation::reduce_body_forces).
NETSPH_HD void device_particle_load(const Vec3d& r, const Vec3f& acc, double mass, double out[6]) {
  const Vec3d f = Vec3d(acc) * mass;
  const Vec3d t = cross(r, f);
  out[0] = f.x, out[1] = f.y, out[2] = f.z, out[3] = t.x, out[4] = t.y, out[5] = t.z;
}

/// The dt force criterion of particle i: |a|^2 of fluid particles, 0 for the others.
NETSPH_HD Real device_fluid_acc2(const ParticleKind* kind, const Vec3f* acc, std::uint32_t i) {
  if (kind[i] != ParticleKind::Fluid) return 0;
  const Vec3f a = acc[i];
  return a.x * a.x + a.y * a.y + a.z * a.z;
}

}  // namespace netsph
