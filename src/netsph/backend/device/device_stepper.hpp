#pragma once
// The time step with every particle array resident on one executor: the CUDA device
// (backend/cuda/cuda_exec.cuh) or, for tests without a GPU, the host (host_exec.hpp). The
// sequence is Simulation::step's (solver/simulation.hpp) for the cases this version supports:
//
//   open-boundary transitions and new inlet particles; wrap periodic axes; sort by cell key (radix
//   sort of keys, gather of every array); cell ranges; body particles placed; buffer state; mDBC
//   state of walls and bodies; view -> rates
//   (+ contacts) -> dt (max reductions); save the start; body loads -> bodies' predictor (on
//   the host) -> predictor, body particles placed [re-sort if a particle moved past the grid
//   skin]; view -> rates (+ shifting, contacts) -> body loads -> bodies' corrector ->
//   corrector, body particles placed; non-finite check.
//
// Supported: fluid particles, walls (DBC or mDBC, any slip, moving), open boundaries (buffer
// transitions, inlet particles created by a scan of flags, imposed or extrapolated buffer
// state), rigid bodies (fixed, floating, prescribed; nets' knots through the host's
// knot-spring solver), contacts, periodic axes, shifting, both kernels, both viscosity models,
// every density diffusion. Not yet: outputs (probes, series): the caller downloads particles.
//
// Bodies and nets stay on the host: after each rates pass the step reduces every body's force
// and torque on the device (one pass over particles, atomics per body), copies those 12
// numbers per body back, lets the host advance the bodies (hooks.advance_bodies, the CPU
// solver's code) and copies their new states in; the particles then follow on the device.
//
// Exec provides: Buffer<T> (resize, size, data, swap), for_each(n, f), sort_pairs(keys_in,
// keys_out, vals_in, vals_out, n, key_bits), max_of(const T*, n), count_below(const uint32*,
// n, bound), exclusive_scan(const uint32* in, uint32* out, n) -> total, upload(Buffer<T>&,
// const T*, n), download(T*, const Buffer<T>&, n), and
// atomic_add(double*, double) callable inside f. f must be a NETSPH_LAMBDA: on CUDA it runs on
// the device.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "netsph/backend/device/device_kernels.hpp"
#include "netsph/neighbors/grid_index.hpp"
#include "netsph/sph/time_step.hpp"

#if defined(__CUDACC__)
#define NETSPH_LAMBDA __device__
#else
#define NETSPH_LAMBDA
#endif

namespace netsph {

/// What a device step needs from the case (solver/device_setup.cpp builds it).
struct DeviceSetup {
  FluidModel model;
  GridIndex grid;
  double max_displacement = 0;  ///< CellGrid::max_displacement()
  double cfl = 0.2;
  double dt_max = 0;  ///< 0: none
  double dt_min = 0;  ///< 0: 1e-4 of the first dt
  bool shifting = false;
  ShiftingParams shift_params;
  std::vector<DeviceWall> walls;  ///< by wall index
  /// Velocity of wall w at time t (null: every wall is at rest).
  std::function<Vec3f(std::size_t w, double t)> wall_velocity;
  std::vector<DeviceZone> zones;             ///< open boundaries: inlets, then outlets
  std::vector<double> profile_z, profile_u;  ///< the zones' inflow profiles, concatenated
  double gz = 0;                             ///< gravity's z component, m/s^2 (hydrostatic buffers)
  std::vector<DeviceBody> bodies;            ///< by body index, with their initial states
  std::vector<Vec3f> body_offsets, body_ghosts;  ///< body frame, by DeviceBody::offset_base + k
  ContactModel contact;
  /// Advances the bodies one stage (body_motion.hpp) from the loads of that stage: `states`
  /// holds the bodies' states on entry and receives the new ones. `time` is the step's start.
  std::function<void(bool corrector, double time, double dt,
                     const std::vector<DeviceBodyLoads>& loads, std::vector<RigidState>& states)>
      advance_bodies;
};

/// Why a step stopped early.
enum class DeviceStepStatus { Ok, DtCollapsed, NonFinite };

struct DeviceStepReport {
  DeviceStepStatus status = DeviceStepStatus::Ok;
  TimeStepLimits dt_limits;
  double dt_floor = 0;
  std::size_t lost = 0;     ///< particles dropped this step for leaving the grid
  std::size_t created = 0;  ///< inlet buffer particles created this step
  std::size_t removed = 0;  ///< buffer particles that left through a face this step
  bool resorted = false;
  double max_speed = 0;  ///< largest fluid speed at the end of the step, m/s
};

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
    Exec::upload(ghost_, p.ghost.data(), n_);
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
    motion_host_.resize(s_.walls.size());
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
    sort(false);
    rep.lost = before - n_ - rep.removed;
    wall_motion(0.0);  // velocities at t for the boundary state
    place_bodies(false);
    if (!s_.zones.empty()) buffer_state();
    mdbc();
    view(false);
    rates(false);
    if (has_bodies_) contacts();
    const TimeStepInputs in{std::sqrt(static_cast<double>(Exec::max_of(acc2_.data(), n_))),
                            static_cast<double>(Exec::max_of(visc_.data(), n_))};
    rep.dt_limits = compute_time_step(s_.model, s_.cfl, in);
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
      sort(true);
      rep.resorted = true;
    }
    view(true);
    rates(s_.shifting);
    if (has_bodies_) {
      contacts();
      advance_bodies(true, dt);
    }
    if (!correct(dt)) rep.status = DeviceStepStatus::NonFinite;
    place_bodies(false);
    rep.max_speed = max_fluid_speed();
    time_ += dt;
    ++steps_;
    return rep;
  }

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
    p.group.resize(n_), p.ghost.resize(n_);
    Exec::download(p.pos.data(), pos_, n_);
    Exec::download(p.vel.data(), vel_, n_);
    Exec::download(p.rho.data(), rho_, n_);
    Exec::download(p.kind.data(), kind_, n_);
    Exec::download(p.id.data(), id_, n_);
    Exec::download(p.group.data(), group_, n_);
    Exec::download(p.ghost.data(), ghost_, n_);
    p.next_id = next_id_;
  }

  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  std::size_t size() const { return n_; }
  /// Bytes the executor holds per particle (all buffers, capacity, and the cell table).
  double bytes_per_particle() const {
    // pos, vel, rho, kind, id and one gather scratch of each type; group and ghost share
    // the scratch of id and vel.
    const std::size_t state = 2 * (sizeof(Vec3d) + sizeof(Vec3f) + sizeof(Real) +
                                   sizeof(ParticleKind) + sizeof(std::uint32_t)) +
                              sizeof(std::uint32_t) + sizeof(Vec3f);
    const std::size_t start = sizeof(Vec3d) + sizeof(Vec3f) + sizeof(Real);
    const std::size_t view = (mirrors_ ? 12 : 9) * sizeof(Real);
    const std::size_t rates =
        sizeof(Vec3f) + 3 * sizeof(Real) + (s_.shifting ? sizeof(Vec3f) + sizeof(Real) : 0);
    const std::size_t sort = 4 * sizeof(std::uint32_t) + sizeof(double);  // keys, order, moved
    const std::size_t per = state + start + view + rates + sort;
    return static_cast<double>(per) +
           static_cast<double>(cell_begin_.size() * sizeof(std::uint32_t)) /
               static_cast<double>(n_ > 0 ? n_ : 1);
  }

  // The phases of a step, public only because CUDA's device lambdas cannot live in private
  // member functions.

  void alloc(std::size_t n) {
    pos_.resize(n), vel_.resize(n), rho_.resize(n), kind_.resize(n), id_.resize(n);
    group_.resize(n), ghost_.resize(n);
    pos2_.resize(n), vel2_.resize(n), rho2_.resize(n), kind2_.resize(n), id2_.resize(n);
    spos_.resize(n), svel_.resize(n), srho_.resize(n);
    for (auto* b : {&vx_, &vy_, &vz_, &x_, &y_, &z_, &vrho_, &press_, &fluid_}) b->resize(n);
    if (mirrors_) cvx_.resize(n), cvy_.resize(n), cvz_.resize(n);
    acc_.resize(n), drho_.resize(n), acc2_.resize(n), visc_.resize(n);
    if (s_.shifting) grad_c_.resize(n), div_r_.resize(n);
    keys_.resize(n), keys2_.resize(n), order_.resize(n), order2_.resize(n), moved_.resize(n);
    if (has_bodies_) contact_.resize(n), solid_.resize(n);
    cell_begin_.resize(static_cast<std::size_t>(s_.grid.cells()) + 2);
  }

  DeviceState state() {
    return {pos_.data(), vel_.data(),   rho_.data(),  kind_.data(),
            id_.data(),  group_.data(), ghost_.data()};
  }
  DeviceStart start() { return {spos_.data(), svel_.data(), srho_.data()}; }
  DeviceView view_arrays() {
    DeviceView v{x_.data(),     y_.data(),     z_.data(),  vx_.data(), vy_.data(),
                 vz_.data(),    vx_.data(),    vy_.data(), vz_.data(), vrho_.data(),
                 press_.data(), fluid_.data(), nullptr};
    if (mirrors_) v.cvx = cvx_.data(), v.cvy = cvy_.data(), v.cvz = cvz_.data();
    v.solid = has_bodies_ ? solid_.data() : nullptr;
    return v;
  }
  DeviceRates rate_arrays() {
    return {acc_.data(),
            drho_.data(),
            acc2_.data(),
            visc_.data(),
            s_.shifting ? grad_c_.data() : nullptr,
            s_.shifting ? div_r_.data() : nullptr};
  }

  /// Wraps periodic axes, sorts every array by cell and rebuilds the cell table; drops the
  /// particles outside the grid. Mid-step (after the predictor) the step-start arrays move too.
  void sort(bool mid_step) {
    const GridIndex g = s_.grid;
    const DeviceState st = state();
    const DeviceStart ss = start();
    std::uint32_t* keys = keys_.data();
    std::uint32_t* order = order_.data();
    const bool periodic = g.periodic[0] || g.periodic[1] || g.periodic[2];
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      if (periodic) {
        const Vec3d q = g.wrapped(st.pos[i]);
        if (mid_step) ss.pos[i] += q - st.pos[i];
        st.pos[i] = q;
      }
      keys[i] = g.key_of(st.pos[i]);
      order[i] = i;
    });
    int bits = 1;
    while ((std::uint64_t{1} << bits) <= g.sentinel()) ++bits;
    Exec::sort_pairs(keys_.data(), keys2_.data(), order_.data(), order2_.data(), n_, bits);
    keys_.swap(keys2_);  // the sorted keys and order are now in keys_ and order2_
    const std::size_t kept = Exec::count_below(keys_.data(), n_, g.sentinel());
    gather(pos_, pos2_, kept), gather(vel_, vel2_, kept), gather(rho_, rho2_, kept);
    // One scratch array per element type: a gather swaps it with the array it sorted, so the
    // same scratch serves the next array of that type (ids and groups, velocities and ghosts).
    gather(kind_, kind2_, kept), gather(id_, id2_, kept), gather(group_, id2_, kept);
    gather(ghost_, vel2_, kept);
    if (mid_step)
      gather(spos_, pos2_, kept), gather(svel_, vel2_, kept), gather(srho_, rho2_, kept);
    n_ = kept;
    // cell_begin[c] = first sorted index with key >= c, for c in [0, cells + 1].
    std::uint32_t* begin = cell_begin_.data();
    const std::uint32_t* k = keys_.data();
    const std::uint32_t n = static_cast<std::uint32_t>(n_);
    const std::uint32_t last = g.sentinel() + 1;
    Exec::for_each(n_ + 1, [=] NETSPH_LAMBDA(std::uint32_t i) {
      const std::uint32_t lo = i == 0 ? 0 : k[i - 1] + 1;
      const std::uint32_t hi = i == n ? last : k[i];
      for (std::uint32_t c = lo; c <= hi; ++c) begin[c] = i;
    });
  }

  /// v = v[order] for the first `kept` sorted slots, through `scratch`.
  template <class T>
  void gather(Buffer<T>& v, Buffer<T>& scratch, std::size_t kept) {
    const T* src = v.data();
    T* dst = scratch.data();
    const std::uint32_t* order = order2_.data();
    Exec::for_each(kept, [=] NETSPH_LAMBDA(std::uint32_t i) { dst[i] = src[order[i]]; });
    v.swap(scratch);
  }

  // Kernel types are dispatched by hand, not with with_kernel: CUDA's device lambdas cannot be
  // defined inside a generic lambda.
  void mdbc() {
    if (s_.model.kernel_type == KernelType::Wendland) return mdbc_for<WendlandC2>();
    mdbc_for<CubicSpline>();
  }

  template <class K>
  void mdbc_for() {
    const GridIndex g = s_.grid;
    const std::uint32_t* begin = cell_begin_.data();
    const DeviceState st = state();
    const DeviceWall* walls = walls_.data();
    const DeviceWallMotion* motion = motion_.data();
    const DeviceBody* bodies = bodies_.data();
    const FluidModel m = s_.model;
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      device_mdbc_particle<K>(g, begin, st, walls, motion, bodies, m, i);
    });
  }

  void view(bool half_step) {
    const DeviceState st = state();
    const DeviceView v = view_arrays();
    const FluidModel m = s_.model;
    const DeviceWall* walls = walls_.data();
    const DeviceWallMotion* motion = motion_.data();
    const DeviceBody* bodies = bodies_.data();
    const Vec3d origin = s_.grid.origin;
    const bool mirrors = mirrors_;
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      device_view_particle(st, v, m, walls, motion, bodies, origin, i, mirrors, half_step);
    });
  }

  /// The walls' velocities at t, t + dt/2 and t + dt, copied to the executor.
  void wall_motion(double dt) {
    if (!s_.wall_velocity) return;
    for (std::size_t w = 0; w < motion_host_.size(); ++w) {
      motion_host_[w] = {s_.wall_velocity(w, time_), s_.wall_velocity(w, time_ + 0.5 * dt),
                         s_.wall_velocity(w, time_ + dt)};
    }
    Exec::upload(motion_, motion_host_.data(), motion_host_.size());
  }

  /// Body particles on their bodies' states; returns the largest displacement from the step
  /// start when `from_start`.
  double place_bodies(bool from_start) {
    if (!has_bodies_) return 0;
    const DeviceState st = state();
    const DeviceBody* bodies = bodies_.data();
    const Vec3f* offsets = offsets_.data();
    const Vec3f* ghosts = body_ghosts_.data();
    const int dims = s_.model.dims;
    const Vec3d* start_pos = from_start ? spos_.data() : nullptr;
    double* moved = moved_.data();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      moved[i] = device_place_body_particle(st, bodies, offsets, ghosts, dims, start_pos, i);
    });
    return from_start ? std::sqrt(Exec::max_of(moved_.data(), n_)) : 0.0;
  }

  /// Buffer transitions, then the inlets' new buffer particles appended in index order with
  /// consecutive ids (as update_open_boundary_particles appends them).
  void open_boundaries(DeviceStepReport& rep) {
    const DeviceState st = state();
    const ZoneGeometry* geo = zone_geo_.data();
    const std::size_t nz = s_.zones.size();
    std::uint32_t* create = keys_.data();  // free until the sort
    std::uint32_t* removed = keys2_.data();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      device_transition_particle(st, geo, nz, create, removed, i);
    });
    rep.removed = Exec::exclusive_scan(keys2_.data(), order2_.data(), n_);
    const std::size_t created = Exec::exclusive_scan(keys_.data(), order_.data(), n_);
    rep.created = created;
    if (created == 0) return;
    const std::size_t n = n_;
    alloc(n + created);
    const DeviceState grown = state();
    const std::uint32_t* flag = keys_.data();
    const std::uint32_t* offset = order_.data();
    const std::uint32_t first_id = next_id_;
    const auto base = static_cast<std::uint32_t>(n);
    Exec::for_each(n, [=] NETSPH_LAMBDA(std::uint32_t i) {
      if (flag[i])
        device_create_buffer_particle(grown, geo, i, base + offset[i], first_id + offset[i]);
    });
    n_ = n + created;
    next_id_ += static_cast<std::uint32_t>(created);
  }

  void buffer_state() {
    if (s_.model.kernel_type == KernelType::Wendland) return buffer_state_for<WendlandC2>();
    buffer_state_for<CubicSpline>();
  }

  template <class K>
  void buffer_state_for() {
    const GridIndex g = s_.grid;
    const std::uint32_t* begin = cell_begin_.data();
    const DeviceState st = state();
    const DeviceZone* zones = zones_.data();
    const double* pz = profile_z_.data();
    const double* pu = profile_u_.data();
    const double gz = s_.gz;
    const FluidModel m = s_.model;
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      device_buffer_state_particle<K>(g, begin, st, zones, pz, pu, gz, m, i);
    });
  }

  void contacts() {
    const GridIndex g = s_.grid;
    const std::uint32_t* begin = cell_begin_.data();
    const std::uint32_t* keys = keys_.data();
    const ParticleKind* kind = kind_.data();
    const DeviceView v = view_arrays();
    const ContactModel c = s_.contact;
    Vec3f* contact = contact_.data();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t a) {
      device_contact_particle(g, begin, keys, kind, v, c, contact, a);
    });
  }

  /// Reduces the bodies' loads on the executor, advances the bodies on the host and copies
  /// their states back.
  void advance_bodies(bool corrector, double dt) {
    const std::size_t nb = s_.bodies.size();
    double* loads = reinterpret_cast<double*>(loads_.data());
    Exec::for_each(nb * 12, [=] NETSPH_LAMBDA(std::uint32_t k) { loads[k] = 0; });
    const DeviceState st = state();
    const DeviceBody* bodies = bodies_.data();
    const Vec3f* acc = acc_.data();
    const Vec3f* contact = contact_.data();
    const double mass = s_.model.mass;
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      if (st.kind[i] != ParticleKind::Body) return;
      const std::uint32_t b = st.group[i];
      const Vec3d r = st.pos[i] - bodies[b].state.com;
      const Vec3d f = Vec3d(acc[i]) * mass, fc = Vec3d(contact[i]) * mass;
      const Vec3d t = cross(r, f), tc = cross(r, fc);
      double* out = loads + 12 * b;
      const double v[12] = {f.x, f.y, f.z, t.x, t.y, t.z, fc.x, fc.y, fc.z, tc.x, tc.y, tc.z};
      for (int k = 0; k < 12; ++k) {
        if (v[k] != 0) Exec::atomic_add(out + k, v[k]);
      }
    });
    Exec::download(loads_host_.data(), loads_, nb);
    s_.advance_bodies(corrector, time_, dt, loads_host_, states_);
    for (std::size_t b = 0; b < nb; ++b) s_.bodies[b].state = states_[b];
    Exec::upload(bodies_, s_.bodies.data(), nb);
  }

  void rates(bool shift) {
    if (s_.model.kernel_type == KernelType::Wendland) return rates_kernel<WendlandC2>(shift);
    rates_kernel<CubicSpline>(shift);
  }

  template <class K>
  void rates_kernel(bool shift) {
    if (s_.model.viscosity == ViscosityModel::Laminar)
      return rates_for<K, ViscosityModel::Laminar>(shift);
    rates_for<K, ViscosityModel::Artificial>(shift);
  }

  template <class K, ViscosityModel Visc>
  void rates_for(bool shift) {
    switch (s_.model.diffusion) {
      case DensityDiffusion::None:
        return shift ? rates_launch<K, Visc, DensityDiffusion::None, true>()
                     : rates_launch<K, Visc, DensityDiffusion::None, false>();
      case DensityDiffusion::Molteni:
        return shift ? rates_launch<K, Visc, DensityDiffusion::Molteni, true>()
                     : rates_launch<K, Visc, DensityDiffusion::Molteni, false>();
      case DensityDiffusion::Fourtakas:
        return shift ? rates_launch<K, Visc, DensityDiffusion::Fourtakas, true>()
                     : rates_launch<K, Visc, DensityDiffusion::Fourtakas, false>();
    }
  }

  template <class K, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
  void rates_launch() {
    const GridIndex g = s_.grid;
    const std::uint32_t* begin = cell_begin_.data();
    const std::uint32_t* keys = keys_.data();
    const ParticleKind* kind = kind_.data();
    const DeviceView v = view_arrays();
    const FluidModel m = s_.model;
    const DeviceRates out = rate_arrays();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t a) {
      device_rates_particle<K, Visc, Diff, Shift>(g, begin, keys, kind, v, m, out, a);
    });
  }

  void save_start() {
    const DeviceState st = state();
    const DeviceStart ss = start();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      ss.pos[i] = st.pos[i], ss.vel[i] = st.vel[i], ss.rho[i] = st.rho[i];
    });
  }

  /// Predictor; returns the largest displacement, m.
  double predict(double dt) {
    const DeviceState st = state();
    const DeviceStart ss = start();
    const DeviceRates r = rate_arrays();
    const DeviceWall* walls = walls_.data();
    const DeviceWallMotion* motion = motion_.data();
    const FluidModel m = s_.model;
    double* moved = moved_.data();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      moved[i] = device_predict_particle(st, ss, r, walls, motion, m, dt, i);
    });
    return std::sqrt(Exec::max_of(moved_.data(), n_));
  }

  double max_fluid_speed() {
    const DeviceState st = state();
    double* speed2 = moved_.data();
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      const Vec3f v = st.vel[i];
      speed2[i] = st.kind[i] == ParticleKind::Fluid
                      ? static_cast<double>(v.x * v.x + v.y * v.y + v.z * v.z)
                      : 0.0;
    });
    return std::sqrt(Exec::max_of(moved_.data(), n_));
  }

  /// Corrector; returns false when a particle's state is not finite.
  bool correct(double dt) {
    const DeviceState st = state();
    const DeviceStart ss = start();
    const DeviceRates r = rate_arrays();
    const DeviceWall* walls = walls_.data();
    const DeviceWallMotion* motion = motion_.data();
    const FluidModel m = s_.model;
    const bool shift = s_.shifting;
    const ShiftingParams sp = s_.shift_params;
    double* bad = moved_.data();  // reused: 1 where the state is not finite
    Exec::for_each(n_, [=] NETSPH_LAMBDA(std::uint32_t i) {
      bad[i] = device_correct_particle(st, ss, r, walls, motion, m, shift ? &sp : nullptr, dt, i)
                   ? 0.0
                   : 1.0;
    });
    return !(Exec::max_of(moved_.data(), n_) > 0);
  }

 private:
  DeviceSetup s_;
  std::size_t n_ = 0;
  std::uint32_t next_id_ = 0;
  bool mirrors_ = false;
  bool has_bodies_ = false;
  double time_ = 0;
  std::int64_t steps_ = 0;
  double dt_floor_ = 0;
  Buffer<Vec3d> pos_, pos2_, spos_;
  Buffer<Vec3f> vel_, vel2_, svel_, ghost_, acc_, grad_c_;
  Buffer<Real> rho_, rho2_, srho_, x_, y_, z_, vx_, vy_, vz_, cvx_, cvy_, cvz_, vrho_, press_,
      fluid_, drho_, acc2_, visc_, div_r_;
  Buffer<ParticleKind> kind_, kind2_;
  Buffer<std::uint32_t> id_, id2_, group_, keys_, keys2_, order_, order2_, cell_begin_;
  Buffer<double> moved_;
  Buffer<DeviceWall> walls_;
  Buffer<DeviceWallMotion> motion_;
  std::vector<DeviceWallMotion> motion_host_;
  Buffer<DeviceZone> zones_;
  Buffer<ZoneGeometry> zone_geo_;
  Buffer<double> profile_z_, profile_u_;
  Buffer<DeviceBody> bodies_;
  Buffer<Vec3f> offsets_, body_ghosts_, contact_;
  Buffer<std::int32_t> solid_;
  Buffer<DeviceBodyLoads> loads_;
  std::vector<DeviceBodyLoads> loads_host_;
  std::vector<RigidState> states_;
};

}  // namespace netsph
