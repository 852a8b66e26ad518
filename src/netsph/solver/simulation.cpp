#include "netsph/solver/simulation.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <fmt/format.h>

#include "netsph/backend/cpu/probe_pass.hpp"
#include "netsph/boundary/mdbc.hpp"
#include "netsph/solver/body_motion.hpp"
#include "netsph/solver/step_settings.hpp"
#include "netsph/sph/fluid_point_loads.hpp"
#include "netsph/sph/fluid_sampler.hpp"

namespace netsph {

Simulation::Simulation(const CaseSpec& spec, StepBackend backend)
    : Simulation(spec, backend, build_scene) {}

Simulation::Simulation(const CaseSpec& spec, StepBackend backend,
                       const std::function<Scene(const CaseSpec&)>& build)
    : spec_(spec_with_net_knots(spec)),
      nets_(coupled_nets(spec_)),
      scene_(build(spec_)),
      p_(scene_.particles),
      backend_(backend) {
  const FluidModel& m = scene_.model;
  grid_.configure(scene_.domain_min, scene_.domain_max, m.support, kGridSkin, m.dims,
                  spec.domain.periodic);
  walls_.resize(spec_.walls.size());
  for (std::size_t w = 0; w < spec.walls.size(); ++w) {
    walls_[w].shows_own_velocity =
        spec.walls[w].model == WallModel::Dbc || spec.walls[w].slip == WallSlip::WallVelocity;
  }
  shift_on_ = spec.fluid.shifting == ShiftingModel::Fickian;
  shift_params_ = shifting_params(spec, m);
  contact_model_ = ContactModel::make(spec.simulation.dp, scene_.sound_speed);
  initial_fluid_ = p_.count(ParticleKind::Fluid);
  buoy_resolved_knots_by_their_particles(nets_, scene_.bodies, spec_);
  // Knots carry their weight and buoyancy in the knot-spring solver (constant forces), not as
  // body forces.
  for (const CoupledNet& net : nets_) {
    for (std::size_t k = 0; k < net.model.knots.size(); ++k)
      scene_.bodies[net.first_body + k].external_force = {};
  }
  setup_absorber();  // before the device: its wall velocities take the correction
  if (backend_ != StepBackend::Cpu) start_device();
}

Simulation::~Simulation() = default;

void Simulation::build_view(bool half_step) {
  view_.build(p_, scene_.model, grid_.origin());
  set_view_continuity_velocity(half_step);
}

void Simulation::set_view_continuity_velocity(bool half_step) {
  // Solids under a mirror slip condition show the fluid the mirrored velocity in the viscous
  // terms (p_.vel) but their own velocity in continuity.
  bool mirrors = false;
  for (const auto& w : walls_) mirrors |= !w.shows_own_velocity;
  for (const auto& b : scene_.bodies) mirrors |= !b.shows_own_velocity();
  if (!mirrors) return;
  view_.with_continuity_velocity();
  const auto n = static_cast<std::int64_t>(p_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p_.kind[i] == ParticleKind::Wall) {
      const WallKinematics& w = walls_[p_.group[i]];
      if (!w.shows_own_velocity) view_.set_continuity_velocity(i, half_step ? w.half : w.start);
    } else if (p_.kind[i] == ParticleKind::Body) {
      if (!scene_.bodies[p_.group[i]].shows_own_velocity())
        view_.set_continuity_velocity(i, body_point_velocity(i));
    }
  }
}

Vec3f Simulation::body_point_velocity(std::size_t i) const {
  const RigidBody& b = scene_.bodies[p_.group[i]];
  return Vec3f(rigid_point_velocity(b.state, rigid_lever_arm(b.state, p_.pos[i], grid_.period())));
}

double Simulation::place_body_particles(bool from_step_start) {
  auto& bodies = scene_.bodies;
  if (bodies.empty()) return 0;
  const auto n = static_cast<std::int64_t>(p_.size());
  const int dims = scene_.model.dims;
  const Vec3d period = grid_.period();
  double max_d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : max_d2)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p_.kind[i] != ParticleKind::Body) continue;
    const RigidBody& b = bodies[p_.group[i]];
    const std::uint32_t k = p_.id[i] - b.first_id;
    // Called once per stage, so the previous position is the step start's when
    // `from_step_start` (body particles do not move in the predictor).
    const double d2 =
        place_rigid_particle(b.state, b.offsets[k], b.ghosts[k], dims, b.shows_own_velocity(),
                             period, p_.pos[i], p_.vel[i], p_.ghost[i]);
    if (from_step_start) max_d2 = std::max(max_d2, d2);
  }
  return std::sqrt(max_d2);
}

void Simulation::reduce_body_forces() {
  auto& bodies = scene_.bodies;
  if (bodies.empty()) return;
  for (auto& b : bodies) {
    b.fluid_force = b.fluid_torque = b.contact_force = b.contact_torque = {};
  }
  const double m = scene_.model.mass;
  // Serial over particles in sorted order: the sums do not depend on the thread count.
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.kind[i] != ParticleKind::Body) continue;
    // Body particles sit where the bodies' states put them, the same on every process, so
    // exactly one process counts each.
    if (partition_ && !partition_->owns(p_.pos[i])) continue;
    RigidBody& b = bodies[p_.group[i]];
    const Vec3d r = rigid_lever_arm(b.state, p_.pos[i], grid_.period());
    const Vec3d f = Vec3d(acc_[i]) * m, fc = Vec3d(contact_[i]) * m;
    b.fluid_force += f;
    b.fluid_torque += cross(r, f);
    b.contact_force += fc;
    b.contact_torque += cross(r, fc);
  }
  if (partition_) {
    std::vector<double> loads;
    loads.reserve(12 * bodies.size());
    for (const auto& b : bodies)
      for (const Vec3d* v : {&b.fluid_force, &b.fluid_torque, &b.contact_force, &b.contact_torque})
        loads.insert(loads.end(), {v->x, v->y, v->z});
    partition_->global_sum(loads);
    std::size_t k = 0;
    for (auto& b : bodies)
      for (Vec3d* v : {&b.fluid_force, &b.fluid_torque, &b.contact_force, &b.contact_torque})
        *v = {loads[k], loads[k + 1], loads[k + 2]}, k += 3;
  }
}

void Simulation::advance_bodies(bool corrector, double dt) {
  netsph::advance_bodies(
      spec_, scene_.bodies, nets_, time_, corrector, dt,
      [this](std::span<const Vec3d> points, std::span<ShepardValue> values) {
        sample_fluid_at_stage(points, values);
      },
      water_loads_);
  add_water_loads();
}

void Simulation::add_water_loads() {
  if (water_loads_.empty()) return;
  const FluidModel& m = scene_.model;
  const FluidPointLoadSet set = point_load_set(
      water_loads_.data(), static_cast<std::uint32_t>(water_loads_.size()), m.support);
  const Vec3d period = grid_.period();
  const auto n = static_cast<std::int64_t>(p_.size());
  // Every particle here, a distributed run's halo copies included: a copy takes what its owner
  // takes (the same formula at the same position), as it must, since its half-step velocity
  // feeds the owned particles' corrector rates; the mass weights the loads carry were summed
  // over owned particles only, so the run's fluid takes each load once.
  with_kernel(m.kernel_type, [&](auto kernel) {
    using K = decltype(kernel);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      if (p_.kind[i] != ParticleKind::Fluid) continue;
      acc_[i] += point_loads_acceleration<K>(set, m.kernel, m.support2, period, p_.pos[i]);
    }
    return 0;
  });
}

void Simulation::sample_fluid_at_stage(std::span<const Vec3d> points,
                                       std::span<ShepardValue> values) {
  std::vector<ShepardSums> sums(points.size());
  if (!partition_) {
    point_sums(scene_.model, grid_, p_, points, sums);
  } else {
    // Each process sums the particles it owns (by position, as the body loads are counted),
    // so the sums over the processes count every particle once.
    mark_owned();
    point_sums(scene_.model, grid_, p_, points, sums, owned_);
    sum_over_processes(sums, [&](std::span<double> v) { partition_->global_sum(v); });
  }
  for (std::size_t k = 0; k < sums.size(); ++k) values[k] = shepard_value(sums[k]);
}

void Simulation::sort_particles(bool mid_step) {
  const std::size_t before = p_.size();
  // Mid-step too: the corrector advances positions from the half step (sph/symplectic.hpp),
  // so no step-start copy needs the same wrap. But not the buffer particles mid-step: one the
  // half step carried across the face of a periodic axis has left through its outlet, and the
  // next step start removes it (open_boundary.hpp), before any wrap; wrapped, it would land
  // in the inlet's buffer on the far side and come back as fluid. Until then the grid keeps it
  // in the end cell (GridIndex::key_of clamps on periodic axes).
  if (!mid_step || scene_.zones.empty()) {
    grid_.wrap(p_.pos);
  } else {
    const auto n = static_cast<std::int64_t>(p_.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i)
      if (p_.kind[i] != ParticleKind::Buffer) p_.pos[i] = grid_.wrapped(p_.pos[i]);
  }
  grid_.sort(p_.pos, order_);
  if (order_.size() < before) {
    // Dropped: outlet removals (NaN positions) and particles outside the domain (lost). Keep
    // the last few lost ones for the report of a run stopped for losing fluid.
    kept_.assign(before, 0);
    for (const std::uint32_t i : order_) kept_[i] = 1;
    for (std::size_t i = 0; i < before; ++i) {
      if (kept_[i] || !std::isfinite(p_.pos[i].x)) continue;
      remember_lost(diag_.last_lost, {p_.id[i], p_.pos[i], p_.vel[i]});
    }
  }
  gather_into(p_.kind, order_, scratch_kind_);
  gather_into(p_.id, order_, scratch_u32_);
  gather_into(p_.group, order_, scratch_u32_);
  gather_into(p_.pos, order_, scratch_d3_);
  if (!mid_step) {
    // At the start of a step the step-start arrays hold nothing live: use them as scratch.
    gather_into(p_.ghost, order_, start_.vel);
    gather_into(p_.vel, order_, start_.vel);
    gather_into(p_.rho, order_, start_.rho);
  } else {
    // Rare (a half step beyond the grid skin): these scratch arrays grow only then.
    gather_into(p_.ghost, order_, scratch_f3_);
    gather_into(p_.vel, order_, scratch_f3_);
    gather_into(p_.rho, order_, scratch_f_);
    gather_into(start_.vel, order_, scratch_f3_);
    gather_into(start_.rho, order_, scratch_f_);
  }
  diag_.lost_total += before - p_.size();
}

double Simulation::compute_dt(const RateReductions& local) {
  RateReductions r = local;
  if (partition_) {
    // Each process reduced over the particles it owns (the view's reduce_mask).
    r.max_acc = partition_->global_max(r.max_acc);
    r.max_visc_dt = partition_->global_max(r.max_visc_dt);
  }
  diag_.dt_limits =
      compute_time_step(scene_.model, spec_.simulation.cfl, {r.max_acc, r.max_visc_dt});
  double dt = diag_.dt_limits.dt;
  if (spec_.simulation.dt_max > 0) dt = std::min(dt, spec_.simulation.dt_max);
  if (steps_ == 0) {
    dt_floor_ = spec_.simulation.dt_min > 0 ? spec_.simulation.dt_min : 1e-4 * dt;
  }
  if (!(dt >= dt_floor_)) {
    check_dt_min_reachable(dt);
    // As many digits as it takes to tell dt from the floor (a dt_min just above the step).
    int digits = 3;
    while (digits < 9 &&
           fmt::format("{:.{}g}", dt, digits) == fmt::format("{:.{}g}", dt_floor_, digits))
      ++digits;
    throw SimulationUnstable(
        "solver",
        fmt::format("time step collapsed at t = {:.6g} s (step {}): dt = {:.{}g} s is below "
                    "the floor {:.{}g} s (force limit {:.3g} s, acoustic-viscous limit "
                    "{:.3g} s); particles are colliding or the flow is too fast for c0 = "
                    "{:.4g} m/s; the strongest acceleration: {}",
                    time_, steps_, dt, digits, dt_floor_, digits, diag_.dt_limits.force,
                    diag_.dt_limits.acoustic, scene_.sound_speed, fastest_accelerating()));
  }
  diag_.dt_limits.dt = dt;
  return dt;
}

void Simulation::check_dt_min_reachable(double first_dt) const {
  if (steps_ != 0 || !(spec_.simulation.dt_min > 0) || !(first_dt < spec_.simulation.dt_min))
    return;
  throw Error(spec_.source,
              fmt::format("simulation.dt_min = {:.4g} s is larger than the first time step, "
                          "{:.4g} s (force limit {:.3g} s, acoustic-viscous limit {:.3g} s, cfl "
                          "{:.3g}): set dt_min below {:.3g} s, or leave it out (the floor is then "
                          "1e-4 of the first step)",
                          spec_.simulation.dt_min, first_dt, diag_.dt_limits.force,
                          diag_.dt_limits.acoustic, spec_.simulation.cfl, first_dt));
}

void Simulation::update_wall_kinematics(double dt) {
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const VelocityHistory& m = spec_.walls[w].motion;
    const Vec3f correction = paddle_correction(w);  // constant over the step
    walls_[w].start = Vec3f(m.at(time_)) + correction;
    walls_[w].half = Vec3f(m.at(time_ + 0.5 * dt)) + correction;
    walls_[w].end = Vec3f(m.at(time_ + dt)) + correction;
  }
}

void Simulation::apply_open_boundary_state() {
  const auto& zones = scene_.zones;
  if (zones.empty()) return;
  const TaitEos& eos = scene_.model.eos;
  const double gz = spec_.fluid.gravity.z;
  ghost_targets_.clear();
  ghost_points_.clear();
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    if (p_.kind[i] != ParticleKind::Buffer) continue;
    // Buffer particles take their state from the fluid only (Tafuni et al. 2018): out of the
    // view's sources while their ghost nodes sum, back in below.
    view_.fluid[i] = 0;
    const OpenBoundaryZone& z = zones[p_.group[i]];
    if (z.velocity_imposed) p_.vel[i] = z.imposed_velocity(p_.pos[i]);
    if (z.density == BufferDensity::Reference) p_.rho[i] = eos.rho0;
    if (z.density == BufferDensity::Hydrostatic)
      p_.rho[i] = hydrostatic_buffer_density(eos, gz, z.surface_z, p_.pos[i].z);
    if (!z.velocity_imposed || z.density == BufferDensity::Extrapolated) {
      ghost_targets_.push_back(i);
      ghost_points_.push_back(z.ghost_of(p_.pos[i]));
    }
  }
  for_each_ghost_value(
      scene_.model, grid_, view_, ghost_points_, [&](std::size_t k, const GhostValue& g) {
        if (!g.any) return;  // no fluid in reach: keep the previous state
        const std::uint32_t i = ghost_targets_[k];
        const OpenBoundaryZone& z = zones[p_.group[i]];
        // First-order extrapolation from the ghost node back to the buffer particle.
        const Vec3d to_b = p_.pos[i] - ghost_points_[k];
        if (z.density == BufferDensity::Extrapolated) {
          p_.rho[i] = static_cast<Real>(g.first_order ? g.rho + dot(g.grad_rho, to_b) : g.rho);
        }
        if (!z.velocity_imposed) {
          // The velocity is the corrected value at the ghost node, not extrapolated further along
          // its gradient: at an outlet the flow accelerates towards the buffer, and extrapolating
          // that gradient feeds back (faster buffer -> faster fluid -> steeper gradient) and
          // drains the channel (14% too fast in a 3D channel at 5 layers; docs/VALIDATION.md).
          p_.vel[i] = Vec3f(g.vel);
        }
      });
  const auto n = static_cast<std::int64_t>(p_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    if (p_.kind[i] != ParticleKind::Buffer) continue;
    view_.fluid[i] = 1;
    view_.refresh_state(static_cast<std::size_t>(i), p_, scene_.model);
  }
}

void Simulation::apply_mdbc() {
  ghost_targets_.clear();
  ghost_points_.clear();
  for (std::uint32_t i = 0; i < p_.size(); ++i) {
    const Vec3f& g = p_.ghost[i];
    const bool has_ghost = g.x != 0 || g.y != 0 || g.z != 0;
    if (p_.kind[i] == ParticleKind::Wall) {
      const std::uint32_t w = p_.group[i];
      if (spec_.walls[w].model == WallModel::Mdbc && has_ghost) {
        ghost_targets_.push_back(i);
        ghost_points_.push_back(p_.pos[i] + Vec3d(g));
      } else if (walls_[w].shows_own_velocity) {
        p_.vel[i] = walls_[w].start;
        view_.refresh_state(i, p_, scene_.model);
      }
    } else if (p_.kind[i] == ParticleKind::Body && has_ghost) {
      ghost_targets_.push_back(i);  // body ghosts are zero unless the body uses mDBC
      ghost_points_.push_back(p_.pos[i] + Vec3d(g));
    }
  }
  if (ghost_targets_.empty()) return;
  std::atomic<std::size_t> fallbacks{0};
  // The view holds the fluid and buffer state the ghost nodes sum (English et al. 2022 include
  // buffer particles); the solids' entries set here are refreshed in it.
  for_each_ghost_value(
      scene_.model, grid_, view_, ghost_points_, [&](std::size_t k, const GhostValue& g) {
        const std::uint32_t i = ghost_targets_[k];
        const bool wall = p_.kind[i] == ParticleKind::Wall;
        const WallSlip slip =
            wall ? spec_.walls[p_.group[i]].slip : scene_.bodies[p_.group[i]].slip;
        const Vec3f v_solid = wall ? walls_[p_.group[i]].start : body_point_velocity(i);
        if (g.any && !g.first_order) fallbacks.fetch_add(1, std::memory_order_relaxed);
        const WallState s = mdbc_wall_state(g, p_.ghost[i], scene_.model.eos.rho0, slip, v_solid);
        p_.rho[i] = s.rho;
        p_.vel[i] = s.vel;
        view_.refresh_state(i, p_, scene_.model);
      });
  diag_.mdbc_fallbacks = fallbacks.load();
}

std::int64_t Simulation::first_owned_non_finite() const {
  // Halo copies are dropped after the step: only the particles this process owns count.
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const bool finite = std::isfinite(p_.pos[i].x) && std::isfinite(p_.pos[i].y) &&
                        std::isfinite(p_.pos[i].z) && std::isfinite(p_.vel[i].x) &&
                        std::isfinite(p_.vel[i].y) && std::isfinite(p_.vel[i].z) &&
                        std::isfinite(p_.rho[i]);
    if (finite) continue;
    if (!std::isfinite(p_.pos[i].x + p_.pos[i].y + p_.pos[i].z) || partition_->owns(p_.pos[i]))
      return static_cast<std::int64_t>(i);
  }
  return -1;
}

void Simulation::fail_non_finite(std::int64_t i) const {
  sync_from_device();
  const Vec3d x = p_.pos[i];
  const Vec3f v = p_.vel[i];
  throw SimulationUnstable(
      "solver",
      fmt::format("non-finite state at t = {:.6g} s (step {}): particle id {} ({}) at ({:.4g}, "
                  "{:.4g}, {:.4g}) m, velocity ({:.3g}, {:.3g}, {:.3g}) m/s, density {:.4g} kg/m^3",
                  time_, steps_, p_.id[i], name_of(p_.kind[i]), x.x, x.y, x.z, v.x, v.y, v.z,
                  p_.rho[i]));
}

void Simulation::step() {
  if (device_) {
    update_absorber();
    return device_step();
  }
  const FluidModel& m = scene_.model;

  // Open boundaries first: conversions use positions only, and the sort then places the
  // created particles and drops the removed ones.
  // A process of a distributed run counts the events of its own particles only, and numbers
  // the created ones with the others.
  const bool numbered = partition_ && !scene_.zones.empty();
  OpenBoundaryEvents events;
  const std::size_t before_update = p_.size();
  if (numbered) {
    mark_owned();
    events.counted = owned_.data();
  }
  const OpenBoundaryCounts ob =
      update_open_boundary_particles(p_, scene_.zones, numbered ? &events : nullptr);
  if (numbered) partition_->number_created(p_, before_update, events);
  diag_.open.entered_fluid += ob.entered_fluid;
  diag_.open.created += ob.created;
  diag_.open.removed += ob.removed;
  diag_.open.absorbed += ob.absorbed;
  const std::size_t lost_before = diag_.lost_total;
  sort_particles(false);
  update_absorber();
  diag_.lost_total -= ob.removed;  // left through an outlet: not lost
  // A distributed run checks its processes' losses together, between steps.
  if (!partition_) check_lost(diag_.lost_total - lost_before);

  update_wall_kinematics(0.0);  // velocities at t for the boundary state
  place_body_particles(false);
  // The view first: the ghost nodes of the buffer and of mDBC read the fluid's state from it,
  // and the particles they set are refreshed in it.
  view_.build(p_, m, grid_.origin());
  apply_open_boundary_state();
  apply_mdbc();
  set_view_continuity_velocity(false);

  const bool bodies = !scene_.bodies.empty();
  if (partition_) {
    mark_owned();
    view_.reduce_mask = owned_.data();
  }
  const RateReductions r0 = compute_rates(m, grid_, view_, p_.kind, acc_, drho_);
  view_.reduce_mask = nullptr;
  if (bodies) compute_contacts(contact_model_, grid_, view_, p_.kind, contact_);
  const double dt = compute_dt(r0);
  update_wall_kinematics(dt);
  const StageInputs in{acc_, drho_, dt, walls_};

  start_.save(p_);
  reduce_body_forces();
  advance_bodies(false, dt);
  // Split over processes, the largest displacement of the particles each owns (a halo copy
  // of a buffer particle near the halo's edge moves by one-sided ghost-node sums), and over
  // the processes: the one-process run's. So all sort again when it would, and a particle's
  // candidates come from its cells, its pair sums in its order (neighbours/cell_grid.cpp).
  double moved = symplectic_predictor(p_, in, m, partition_ ? owned_.data() : nullptr);
  moved = std::max(moved, place_body_particles(true));
  if (partition_) moved = partition_->global_max(moved);
  if (moved > grid_.max_displacement()) {
    sort_particles(true);
    ++diag_.resorts;
  }

  build_view(true);
  compute_rates(m, grid_, view_, p_.kind, acc_, drho_, shift_on_ ? &shift_sums_ : nullptr);
  if (bodies) {
    compute_contacts(contact_model_, grid_, view_, p_.kind, contact_);
    reduce_body_forces();
    advance_bodies(true, dt);
  }
  std::int64_t bad =
      symplectic_corrector(p_, start_, in, m, shift_on_ ? &shift_sums_ : nullptr, &shift_params_);
  if (!scene_.damping.empty()) apply_damping(p_, scene_.damping, time_ + dt, dt);
  place_body_particles(false);
  time_ += dt;
  ++steps_;

  // Before the check below: a process that stops there must not skip this collective step.
  double vmax2 = 0;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (!is_fluid(p_.kind[i]) || (partition_ && !partition_->owns(p_.pos[i]))) continue;
    vmax2 = std::max(vmax2, static_cast<double>(norm2(p_.vel[i])));
  }
  diag_.max_speed = std::sqrt(partition_ ? partition_->global_max(vmax2) : vmax2);
  if (bad >= 0 && partition_) bad = first_owned_non_finite();
  if (bad >= 0) fail_non_finite(bad);
}

void Simulation::check_lost(std::size_t lost_this_step) const {
  check_lost_fluid(spec_, time_, steps_, lost_this_step, diag_.lost_total, initial_fluid_,
                   diag_.last_lost);
}

void check_lost_fluid(const CaseSpec& spec, double time, std::int64_t steps,
                      std::size_t lost_this_step, std::size_t lost_total, std::size_t initial_fluid,
                      std::span<const StepDiagnostics::Lost> last_lost) {
  if (lost_total == 0) return;
  const double fluid = static_cast<double>(std::max<std::size_t>(initial_fluid, 1));
  const bool burst = static_cast<double>(lost_this_step) > std::max(10.0, 0.01 * fluid);
  const bool total = static_cast<double>(lost_total) > spec.simulation.max_lost_fraction * fluid;
  if (!burst && !total) return;
  const std::string where = describe_lost(last_lost);
  throw SimulationUnstable(
      "solver",
      fmt::format("fluid is leaving the domain at t = {:.6g} s (step {}): {} particles in this "
                  "step, {} in all ({:.2g}% of the initial fluid; the limit is {} in one step or "
                  "simulation.max_lost_fraction = {} in all); the last to leave{}",
                  time, steps, lost_this_step, lost_total,
                  100 * static_cast<double>(lost_total) / fluid,
                  static_cast<std::size_t>(std::max(10.0, 0.01 * fluid)),
                  spec.simulation.max_lost_fraction, where.empty() ? "" : ": " + where));
}

std::string describe_lost(std::span<const StepDiagnostics::Lost> lost) {
  std::string where;
  for (const auto& l : lost) {
    where += fmt::format(
        "{}id {} at ({:.4g}, {:.4g}, {:.4g}) m moving ({:.3g}, {:.3g}, {:.3g}) m/s",
        where.empty() ? "" : "; ", l.id, l.pos.x, l.pos.y, l.pos.z, l.vel.x, l.vel.y, l.vel.z);
  }
  return where;
}

std::string Simulation::fastest_accelerating() const {
  std::size_t best = p_.size();
  double a2 = -1;
  for (std::size_t i = 0; i < p_.size() && i < acc_.size(); ++i) {
    if (!is_fluid(p_.kind[i])) continue;
    const double v = norm2(Vec3d(acc_[i]));
    if (v > a2) a2 = v, best = i;
  }
  if (best == p_.size()) return "no fluid particle";
  const Vec3d x = p_.pos[best];
  const Vec3f v = p_.vel[best];
  return fmt::format(
      "fluid particle id {} at ({:.4g}, {:.4g}, {:.4g}) m, velocity ({:.3g}, "
      "{:.3g}, {:.3g}) m/s, acceleration {:.3g} m/s^2",
      p_.id[best], x.x, x.y, x.z, v.x, v.y, v.z, std::sqrt(a2));
}

std::vector<float> Simulation::pressures() const {
  sync_from_device();
  std::vector<float> p(p_.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = scene_.model.eos.pressure(p_.rho[i]);
  return p;
}

double Simulation::bytes_per_particle() const {
  if (device_) return device_->bytes_per_particle();
  const auto n = static_cast<double>(std::max<std::size_t>(p_.size(), 1));
  const std::size_t bytes =
      p_.bytes() + view_.bytes() + start_.bytes() + acc_.capacity() * sizeof(Vec3f) +
      drho_.capacity() * sizeof(Real) + order_.capacity() * sizeof(std::uint32_t) + grid_.bytes() +
      scratch_d3_.capacity() * sizeof(Vec3d) + scratch_f3_.capacity() * sizeof(Vec3f) +
      scratch_f_.capacity() * sizeof(Real) + scratch_kind_.capacity() +
      scratch_u32_.capacity() * sizeof(std::uint32_t) +
      shift_sums_.grad_c.capacity() * sizeof(Vec3f) + shift_sums_.div_r.capacity() * sizeof(Real) +
      ghost_targets_.capacity() * sizeof(std::uint32_t) + ghost_points_.capacity() * sizeof(Vec3d) +
      contact_.capacity() * sizeof(Vec3f);
  return static_cast<double>(bytes) / n;
}

}  // namespace netsph
