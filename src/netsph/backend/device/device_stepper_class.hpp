#pragma once
// The class of the device step: its state, its memory and step(); the phases' definitions are
// in the device_stepper_*.hpp parts, and device_stepper.hpp includes them all.
//
// The time step with every particle array resident on one executor: the CUDA device
// (backend/cuda/cuda_exec.cuh) or, for tests without a GPU, the host (host_exec.hpp). The
// sequence is Simulation::step's (solver/simulation.hpp) for the cases this version supports:
//
//   open-boundary transitions and new inlet particles; wrap periodic axes; sort by cell key (radix
//   sort of keys, gather of every array); cell ranges; body particles placed; buffer state; mDBC
//   state of walls and bodies; view -> rates
//   (+ contacts) -> dt (max reductions); save the start; body loads -> bodies' predictor (on
//   the host) -> water loads -> predictor, body particles placed [re-sort if a particle moved
//   past the grid skin]; view -> rates (+ shifting, contacts) -> body loads -> bodies'
//   corrector -> water loads -> corrector, body particles placed; non-finite check.
//
// Supported: fluid particles, walls (DBC or mDBC, any slip, moving), open boundaries (buffer
// transitions, inlet particles created by a scan of flags, imposed or extrapolated buffer
// state), rigid bodies (fixed, floating, prescribed; nets' knots through the host's
// knot-spring solver), contacts, periodic axes, shifting, both kernels, both viscosity models,
// every density diffusion. Outputs: the probes and the series rows' measures are computed on
// the device (sample_fluid, tally); snapshots and checkpoints download the particles.
//
// Bodies and nets stay on the host: after each rates pass the step reduces every body's force
// and torque on the device (one pass over particles, atomics per body), copies those 12
// numbers per body back, lets the host advance the bodies (hooks.advance_bodies, the CPU
// solver's code) and copies their new states in, and adds the few point loads the host's
// modelled parts put on the water (sinker bars) to the fluid's accelerations; the particles
// then follow on the device.
//
// Memory: the state (positions, velocities, densities, kinds, ids, groups; the solids' ghost
// vectors are tables of the solids, DeviceGhosts), the
// step start's velocities and densities, the sorted cell keys and the cell table persist; every
// other per-particle array lives in one work area (work_area.hpp) that the phases of a step
// share: the view and the rates, the sort's buffers, the open boundaries' flags.
//
// Exec provides: Buffer<T> (resize, size, capacity, data), for_each(n, f), sort_pairs(keys,
// keys_alt, vals, vals_alt, n, key_bits) -> whether the sorted pairs are in the _alt buffers
// (CUB's double-buffer sort, which needs no O(n) temporary storage), max_of(const T*, n),
// count_below(const uint32*, n, bound), exclusive_scan(const uint32* in, uint32* out, n) ->
// total, upload(Buffer<T>&, const T*, n), download(T*, const Buffer<T>&, n),
// for_each_occupying<MinBlocks>(n, f) (for_each with registers capped for MinBlocks blocks of
// 256 threads a multiprocessor; a plain for_each on the host), and
// atomic_add(double*, double) callable inside f, reduce(n, identity, map, combine) -> the
// combine of map(0..n) (map runs on the device, combine on both), and synchronize() (waits for the
// device; for the phase profile). f must be a NETSPH_LAMBDA: on CUDA it runs on the device.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "netsph/backend/device/device_kernels.hpp"
#include "netsph/backend/device/device_step_setup.hpp"
#include "netsph/backend/device/phase_profile.hpp"
#include "netsph/backend/device/work_area.hpp"
#include "netsph/neighbours/grid_index.hpp"
#include "netsph/sph/particle_tally.hpp"
#include "netsph/sph/time_step.hpp"

#if defined(__CUDACC__)
#define NETSPH_LAMBDA __device__
#else
#define NETSPH_LAMBDA
#endif

namespace netsph {

template <class Exec>
class DeviceStepper {
 public:
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;

  DeviceStepper(DeviceSetup setup, const ParticleSet& p) : s_(std::move(setup)) {
    n_ = p.size();
    next_id_ = p.next_id;
    for (const DeviceWall& w : s_.walls) mirrors_ |= !w.shows_own_velocity;
    for (const DeviceBody& b : s_.bodies) mirrors_ |= !b.shows_own_velocity;
    has_bodies_ = !s_.bodies.empty();
    alloc(n_);
    Exec::upload(pos_, p.pos.data(), n_);
    Exec::upload(vel_, p.vel.data(), n_);
    Exec::upload(rho_, p.rho.data(), n_);
    Exec::upload(kind_, p.kind.data(), n_);
    Exec::upload(id_, p.id.data(), n_);
    Exec::upload(group_, p.group.data(), n_);
    upload_wall_ghosts(p);
    Exec::upload(walls_, s_.walls.data(), s_.walls.size());
    if (!s_.zones.empty()) {
      std::vector<ZoneGeometry> geo;
      for (const DeviceZone& z : s_.zones) geo.push_back(z.geo);
      Exec::upload(zones_, s_.zones.data(), s_.zones.size());
      Exec::upload(zone_geo_, geo.data(), geo.size());
      const double none = 0;  // a one-entry table keeps the pointers valid without profiles
      const bool profiles = !s_.profile_z.empty();
      Exec::upload(profile_z_, profiles ? s_.profile_z.data() : &none,
                   profiles ? s_.profile_z.size() : 1);
      Exec::upload(profile_u_, profiles ? s_.profile_u.data() : &none,
                   profiles ? s_.profile_u.size() : 1);
    }
    if (!s_.damping.empty()) Exec::upload(damping_, s_.damping.data(), s_.damping.size());
    motion_host_.resize(s_.walls.size());
    for (std::size_t w = 0; w < s_.walls.size(); ++w)
      motion_host_[w].shows_own_velocity = s_.walls[w].shows_own_velocity;
    Exec::upload(motion_, motion_host_.data(), motion_host_.size());
    if (has_bodies_) {
      Exec::upload(bodies_, s_.bodies.data(), s_.bodies.size());
      Exec::upload(offsets_, s_.body_offsets.data(), s_.body_offsets.size());
      Exec::upload(body_ghosts_, s_.body_ghosts.data(), s_.body_ghosts.size());
      loads_.resize(s_.bodies.size());
      loads_host_.resize(s_.bodies.size());
      for (const DeviceBody& b : s_.bodies) states_.push_back(b.state);
    }
  }

  /// Advances one symplectic step; the report says whether it completed.
  DeviceStepReport step() {
    DeviceStepReport rep;
    // Open boundaries first: conversions use positions only, and the sort then places the
    // created particles and drops the removed ones.
    if (!s_.zones.empty()) open_boundaries(rep);
    const std::size_t before = n_;
    sort(false, rep.removed, rep.last_lost);
    rep.lost = before - n_ - rep.removed;
    wall_motion(0.0);  // velocities at t for the boundary state
    place_bodies(false);
    if (!s_.zones.empty()) buffer_state();
    mdbc();
    view(false);
    rates(false);
    if (has_bodies_) contacts();
    {
      const PhaseTimer<Exec> timer(profile(), DevicePhase::TimeStep);
      const TimeStepInputs in{max_fluid_acceleration(),
                              static_cast<double>(Exec::max_of(step_arrays().rates.visc_dt, n_))};
      rep.dt_limits = compute_time_step(s_.model, s_.cfl, in);
    }
    double dt = rep.dt_limits.dt;
    if (s_.dt_max > 0) dt = dt < s_.dt_max ? dt : s_.dt_max;
    if (steps_ == 0) dt_floor_ = s_.dt_min > 0 ? s_.dt_min : 1e-4 * dt;
    rep.dt_floor = dt_floor_;
    rep.dt_limits.dt = dt;
    if (!(dt >= dt_floor_)) {
      rep.status = DeviceStepStatus::DtCollapsed;
      return rep;
    }
    wall_motion(dt);
    save_start();
    if (has_bodies_) advance_bodies(false, dt);
    double moved = predict(dt);
    if (has_bodies_) moved = std::max(moved, place_bodies(true));
    if (moved > s_.max_displacement) {
      const std::size_t before_resort = n_;
      sort(true, 0, rep.last_lost);
      rep.lost += before_resort - n_;  // left the grid in the half step
      rep.resorted = true;
    }
    view(true);
    rates(s_.shifting);
    if (has_bodies_) {
      contacts();
      advance_bodies(true, dt);
    }
    if (!correct(dt)) rep.status = DeviceStepStatus::NonFinite;
    if (!s_.damping.empty()) damp(dt);
    place_bodies(false);
    rep.max_speed = max_fluid_speed();
    time_ += dt;
    ++steps_;
    return rep;
  }

  /// Switches the phase profile on (its sums restart) or off.
  void set_profiling(bool on) {
    profiling_ = on;
    times_ = DevicePhaseTimes{};
  }
  /// Seconds per phase since profiling was switched on.
  const DevicePhaseTimes& phase_times() const { return times_; }

  /// Sets the clock (time, step count, dt floor) of a run continued from a checkpoint.
  void set_clock(double time, std::int64_t steps, double dt_floor) {
    time_ = time, steps_ = steps, dt_floor_ = dt_floor;
  }

  /// The cell table of the last sort: first sorted index of every cell, cells + 1 entries.
  void download_cell_begin(std::vector<std::uint32_t>& begin) const {
    begin.resize(static_cast<std::size_t>(s_.grid.cells()) + 1);
    Exec::download(begin.data(), cell_begin_, begin.size());
  }

  /// Copies the particles back (sorted by cell as of the last step).
  void download(ParticleSet& p) const {
    p.pos.resize(n_), p.vel.resize(n_), p.rho.resize(n_), p.kind.resize(n_), p.id.resize(n_);
    p.group.resize(n_);
    Exec::download(p.pos.data(), pos_, n_);
    Exec::download(p.vel.data(), vel_, n_);
    Exec::download(p.rho.data(), rho_, n_);
    Exec::download(p.kind.data(), kind_, n_);
    Exec::download(p.id.data(), id_, n_);
    Exec::download(p.group.data(), group_, n_);
    p.next_id = next_id_;
    // The ghost vectors from the host's copies of the solids' tables, by the device's function.
    p.ghost.resize(n_);
    const DeviceState host{p.pos.data(),  p.vel.data(), p.rho.data(),
                           p.kind.data(), p.id.data(),  p.group.data()};
    const DeviceGhosts tables{wall_ghosts_host_.data(),
                              static_cast<std::uint32_t>(wall_ghosts_host_.size()),
                              s_.body_ghosts.data(), s_.model.dims};
    for (std::size_t i = 0; i < n_; ++i)
      p.ghost[i] =
          device_solid_ghost(host, s_.bodies.data(), tables, static_cast<std::uint32_t>(i));
  }

  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  std::size_t size() const { return n_; }
  /// Bytes the executor holds per particle: every per-particle buffer at its capacity, the
  /// work area and the cell table, over the particle count. (CUB's double-buffer sort and
  /// reductions add a temporary of a few hundred kB, independent of the count.)
  double bytes_per_particle() const {
    std::size_t bytes = 0;
    const auto add = [&bytes](const auto& b) { bytes += b.capacity() * sizeof(*b.data()); };
    add(pos_), add(vel_), add(rho_), add(kind_), add(id_), add(group_);
    add(svel_), add(srho_), add(keys_), add(cell_begin_), add(work_);
    add(wall_ghosts_), add(offsets_), add(body_ghosts_);  // the solids' tables
    return static_cast<double>(bytes) / static_cast<double>(n_ > 0 ? n_ : 1);
  }

  // The phases of a step, public only because CUDA's device lambdas cannot live in private
  // member functions.

  /// The persistent arrays hold n particles (their contents kept); then the work area.
  void alloc(std::size_t n) {
    alloc_state(n);
    alloc_work(n);
  }
  void alloc_state(std::size_t n) {
    pos_.resize(n), vel_.resize(n), rho_.resize(n), kind_.resize(n), id_.resize(n);
    group_.resize(n), svel_.resize(n), srho_.resize(n), keys_.resize(n);
    cell_begin_.resize(static_cast<std::size_t>(s_.grid.cells()) + 2);
  }
  /// The work area for n particles: the largest of its phases' layouts (contents not kept).
  void alloc_work(std::size_t n) {
    WorkCarver step(nullptr, n), sorting(nullptr, n), open(nullptr, n);
    step_layout(step), sort_layout(sorting), open_layout(open);
    // Nothing in it outlives a phase: no copy of the old contents, no old and new at once.
    Exec::resize_discarding(
        work_, std::max({step.bytes(), sorting.bytes(), open.bytes(), std::size_t{1}}));
  }

  DeviceState state() {
    return {pos_.data(), vel_.data(), rho_.data(), kind_.data(), id_.data(), group_.data()};
  }
  DeviceGhosts ghosts() {
    return {wall_ghosts_.data(), static_cast<std::uint32_t>(wall_ghosts_host_.size()),
            body_ghosts_.data(), s_.model.dims};
  }
  /// The walls' ghost vectors by particle id (DeviceGhosts), from the particles' own.
  void upload_wall_ghosts(const ParticleSet& p) {
    std::size_t count = 0;  // DBC walls have no ghost: no table
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3f g = p.ghost[i];
      if (p.kind[i] == ParticleKind::Wall && (g.x != 0 || g.y != 0 || g.z != 0))
        count = std::max<std::size_t>(count, p.id[i] + 1);
    }
    wall_ghosts_host_.assign(count, Vec3f{});
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.kind[i] == ParticleKind::Wall && p.id[i] < count)
        wall_ghosts_host_[p.id[i]] = p.ghost[i];
    if (count > 0) Exec::upload(wall_ghosts_, wall_ghosts_host_.data(), count);
  }
  DeviceStart start() { return {svel_.data(), srho_.data()}; }

  /// The work area during the interaction: the view, then the rates.
  struct StepArrays {
    DeviceView view;
    DeviceRates rates;
  };
  StepArrays step_layout(WorkCarver& c) {
    StepArrays a{};
    DeviceView& v = a.view;
    v.pp = c.take<PosPress>();
    v.vr = c.take<VelRho>();
    v.mirrors = mirrors_;
    v.cv = mirrors_ ? c.take<VelRho>() : v.vr;
    DeviceRates& r = a.rates;
    r.acc = c.take<Vec3f>(), r.drho = c.take<Real>(), r.visc_dt = c.take<Real>();
    r.grad_c = s_.shifting ? c.take<Vec3f>() : nullptr;
    r.div_r = s_.shifting ? c.take<Real>() : nullptr;
    return a;
  }
  StepArrays step_arrays() {
    WorkCarver carve(work_.data(), n_);
    return step_layout(carve);
  }
  /// One float per particle for the reductions of a step (displacements, the dt force
  /// criterion, non-finite flags): the start of the view's positions, which those phases never
  /// overlap (they run before the view is built or after the rates and contacts have read it).
  Real* scalars() { return reinterpret_cast<Real*>(step_arrays().view.pp); }

  /// Where the phases add their times: null while profiling is off.
  DevicePhaseTimes* profile() { return profiling_ ? &times_ : nullptr; }

  /// The work area during the sort.
  struct SortArrays {
    std::uint32_t *keys_alt, *order, *order_alt;
    unsigned char* scratch;  ///< one array of the largest element type (the positions)
  };
  SortArrays sort_layout(WorkCarver& c) {
    SortArrays a{};
    a.keys_alt = c.take<std::uint32_t>();
    a.order = c.take<std::uint32_t>(), a.order_alt = c.take<std::uint32_t>();
    a.scratch = c.take<unsigned char>(sizeof(Vec3d));
    return a;
  }

  /// The work area during the open boundaries' transitions and creations.
  struct OpenArrays {
    std::uint32_t *create, *event, *create_at, *flag;
  };
  OpenArrays open_layout(WorkCarver& c) {
    OpenArrays a{};
    a.create = c.take<std::uint32_t>(), a.event = c.take<std::uint32_t>();
    a.create_at = c.take<std::uint32_t>(), a.flag = c.take<std::uint32_t>();
    return a;
  }

  // ---- device_stepper_sort.hpp ----
  /// Wraps periodic axes, sorts every array by cell and rebuilds the cell table; drops the
  /// particles outside the grid. Mid-step (after the predictor) the step start's velocities
  /// and densities move too.
  /// `removed`: the outlets' removals among the particles it drops (their positions are NaN);
  /// any more left the grid, and the last few of those are added to `last_lost`.
  void sort(bool mid_step, std::size_t removed, std::vector<LostParticle>& last_lost);

  /// Copies the `count` dropped particles at `dropped` back (rare: only in a step that lost
  /// some) and adds to `last_lost` the last of those that left the grid, not through an outlet.
  void note_lost(const std::uint32_t* dropped, std::size_t count,
                 std::vector<LostParticle>& last_lost);

  /// v = v[order] for the first `kept` sorted slots: gathered into the scratch, copied back
  /// (a streaming copy; the scratch is shared by every array, whatever its type).
  template <class T>
  void gather(Buffer<T>& v, const std::uint32_t* order, unsigned char* scratch, std::size_t kept);

  // ---- device_stepper_open.hpp ----
  /// Buffer transitions, then the inlets' new buffer particles appended in index order with
  /// consecutive ids (as update_open_boundary_particles appends them).
  void open_boundaries(DeviceStepReport& rep);

  /// How many particles had open-boundary event `kind`: a scan of its flags (in `flag`, the
  /// scan into `scan`), not atomics on one counter from a whole inflowing column.
  std::size_t count_events(const std::uint32_t* event, std::uint32_t kind, std::uint32_t* flag,
                           std::uint32_t* scan);

  void buffer_state();

  template <class K>
  void buffer_state_for();

  // ---- device_stepper_bodies.hpp ----
  /// Body particles on their bodies' states; returns the largest displacement when
  /// `from_start` (after the predictor, which leaves body particles where the step started).
  double place_bodies(bool from_start);

  /// Zeroes the bodies' loads, then adds their contact forces and torques (loads 6-11) where
  /// they arise: each body particle's contact acceleration goes straight into its body's sums,
  /// so no per-particle array holds it. The stage's fluid loads follow in advance_bodies.
  void contacts();

  /// Adds the bodies' fluid loads (0-5) to the contact loads of this stage, advances the
  /// bodies on the host and copies their states back.
  void advance_bodies(bool corrector, double dt);

  /// The fluid's accelerations += the stage's water loads (Simulation::add_water_loads).
  template <class K>
  void add_water_loads();

  // ---- device_stepper_rates.hpp ----
  // Kernel types are dispatched by hand, not with with_kernel: CUDA's device lambdas cannot be
  // defined inside a generic lambda.
  void mdbc();

  template <class K>
  void mdbc_for();

  void view(bool half_step);

  void rates(bool shift);

  template <class K>
  void rates_kernel(bool shift);

  template <class K, ViscosityModel Visc>
  void rates_for(bool shift);

  template <class K, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
  void rates_launch();

  // ---- device_stepper_sampling.hpp ----
  /// The fluid at `points` as the stage has it (its positions and cell table): a few points
  /// (the nets' sinker bars), one thread each, their sums copied back.
  void sample_fluid(std::span<const Vec3d> points, std::span<ShepardValue> values);

  /// The series rows' measures of the particles as of the last step, reduced where they are.
  ParticleTally tally();

  template <class K>
  void sample_for(std::size_t n);

  // ---- device_stepper_integration.hpp ----
  /// The walls' velocities at t, t + dt/2 and t + dt, copied to the executor.
  void wall_motion(double dt);

  void save_start();

  /// Largest acceleration of a fluid particle in the last rates pass, m/s^2 (dt's force
  /// criterion).
  double max_fluid_acceleration();

  /// Predictor; returns the largest displacement, m.
  double predict(double dt);

  double max_fluid_speed();

  /// Corrector; returns false when a particle's state is not finite.
  bool correct(double dt);

  /// The damping zones' relaxation of the fluid's velocities over the step.
  void damp(double dt);

 private:
  DeviceSetup s_;
  std::size_t n_ = 0;
  std::uint32_t next_id_ = 0;
  bool mirrors_ = false;
  bool has_bodies_ = false;
  double time_ = 0;
  std::int64_t steps_ = 0;
  double dt_floor_ = 0;
  bool profiling_ = false;
  DevicePhaseTimes times_;
  Buffer<Vec3d> pos_;
  Buffer<Vec3f> vel_, svel_;
  Buffer<Real> rho_, srho_;
  Buffer<ParticleKind> kind_;
  Buffer<std::uint32_t> id_, group_, keys_, cell_begin_;
  Buffer<unsigned char> work_;  ///< the phases' short-lived arrays (work_area.hpp)
  Buffer<DeviceWall> walls_;
  Buffer<WallKinematics> motion_;
  std::vector<WallKinematics> motion_host_;
  Buffer<DeviceZone> zones_;
  Buffer<DampingZone> damping_;
  Buffer<ZoneGeometry> zone_geo_;
  Buffer<double> profile_z_, profile_u_;
  Buffer<DeviceBody> bodies_;
  Buffer<Vec3f> offsets_, body_ghosts_, wall_ghosts_;
  std::vector<Vec3f> wall_ghosts_host_;  ///< by particle id (DeviceGhosts::wall)
  Buffer<DeviceBodyLoads> loads_;
  std::vector<DeviceBodyLoads> loads_host_;
  std::vector<RigidState> states_;
  Buffer<Vec3d> sample_points_;  ///< sample_fluid's points and sums
  Buffer<ShepardSums> sample_sums_;
  std::vector<ShepardSums> sample_sums_host_;
  std::vector<FluidPointLoad> water_loads_host_;  ///< the stage's loads on the water
  Buffer<FluidPointLoad> water_loads_;
};

}  // namespace netsph
