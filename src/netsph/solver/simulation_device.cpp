// Simulation on the device backends: the step runs in the device-shaped stepper
// (backend/device/, on the CUDA device or the host executor); the bodies and the nets stay
// here and the stepper calls back into the same stage code as the CPU step
// (solver/body_motion.cpp); particles and the cell table come back only when something reads
// them (outputs, checkpoints, diagnostics).
#include <fmt/format.h>

#include "netsph/solver/body_motion.hpp"
#include "netsph/solver/device_setup.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/sph/symplectic.hpp"

namespace netsph {

void Simulation::start_device() {
  // A restart replaces a running device step: its buffers go first, or the device would hold
  // two copies of the case at once (40 GB for the paper's full net).
  device_.reset();
  DeviceSetup setup = device_setup(spec_, scene_);
  setup.advance_bodies = [this](bool corrector, double time, double dt,
                                const std::vector<DeviceBodyLoads>& loads,
                                std::vector<RigidState>& states, const FluidSampler& sample,
                                std::vector<FluidPointLoad>& water_loads) {
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
      const double* f = loads[b].f;
      RigidBody& body = scene_.bodies[b];
      body.fluid_force = {f[0], f[1], f[2]}, body.fluid_torque = {f[3], f[4], f[5]};
      body.contact_force = {f[6], f[7], f[8]}, body.contact_torque = {f[9], f[10], f[11]};
    }
    netsph::advance_bodies(spec_, scene_.bodies, nets_, time, corrector, dt, sample, water_loads);
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b) states[b] = scene_.bodies[b].state;
  };
  bool moving = false;
  for (const WallSpec& w : spec_.walls) moving |= w.motion.moving();
  if (moving) {
    setup.wall_velocity = [this](std::size_t w, double t) {
      return Vec3f(spec_.walls[w].motion.at(t)) + paddle_correction(w);
    };
  }
  if (backend_ == StepBackend::HostDevice) {
    device_ = make_host_device_run(std::move(setup), p_);
  } else {
#if defined(NETSPH_HAVE_CUDA)
    device_ = make_cuda_device_run(std::move(setup), p_);
#else
    throw Error("--backend cuda",
                "this netsph was built without CUDA (no nvcc found at configure time); use "
                "--backend cpu");
#endif
  }
  device_->set_clock(time_, steps_, dt_floor_);
  device_ahead_ = false;
  device_stepped_ = false;
}

void Simulation::device_step() {
  const DeviceStepReport r = device_->step();
  device_ahead_ = true;
  device_stepped_ = true;
  diag_.dt_limits = r.dt_limits;
  if (steps_ == 0) dt_floor_ = r.dt_floor;
  if (r.status == DeviceStepStatus::DtCollapsed) {
    check_dt_min_reachable(r.dt_limits.dt);
    throw SimulationUnstable(
        "solver",
        fmt::format("time step collapsed at t = {:.6g} s (step {}): dt = {:.3g} s is below "
                    "the floor {:.3g} s (force limit {:.3g} s, acoustic-viscous limit "
                    "{:.3g} s); particles are colliding or the flow is too fast for c0 = "
                    "{:.4g} m/s",
                    time_, steps_, r.dt_limits.dt, r.dt_floor, r.dt_limits.force,
                    r.dt_limits.acoustic, scene_.sound_speed));
  }
  diag_.open.created += r.created;
  diag_.open.removed += r.removed;
  diag_.open.entered_fluid += r.entered_fluid;
  diag_.open.absorbed += r.absorbed;
  diag_.lost_total += r.lost;
  for (const LostParticle& l : r.last_lost) remember_lost(diag_.last_lost, l);
  if (r.resorted) ++diag_.resorts;
  diag_.max_speed = r.max_speed;
  check_lost(r.lost);
  time_ = device_->time();
  ++steps_;
  if (r.status == DeviceStepStatus::NonFinite) {
    sync_from_device();
    for (std::size_t i = 0; i < p_.size(); ++i) {
      if (!finite_state(p_.pos[i], p_.vel[i], p_.rho[i]))
        fail_non_finite(static_cast<std::int64_t>(i));
    }
  }
}

void Simulation::set_device_profiling(bool on) {
  if (!device_)
    throw Error("--profile",
                "the phase profile is of the device step (--backend cuda or "
                "host-device); profile the CPU step with perf");
  device_->set_profiling(on);
}

std::optional<DevicePhaseTimes> Simulation::device_phase_times() const {
  if (!device_) return std::nullopt;
  return device_->phase_times();
}

// The device's particles are always the newest (as of the last step, or equal to the host's
// copy after a download): the outputs read them there whether or not a copy came back, so a
// probe gives the same value on a snapshot's step as on any other.
std::optional<ParticleTally> Simulation::tally_on_device() const {
  if (!device_) return std::nullopt;
  return device_->tally();
}

bool Simulation::sample_on_device(std::span<const Vec3d> points,
                                  std::span<ShepardValue> values) const {
  // Before its first step (a new run, a restart) the device has no cell table yet; its
  // particles are the host's, which the host's path samples (a resumed run writes nothing
  // before it steps).
  if (!device_ || !device_stepped_) return false;
  device_->sample_fluid(points, values);
  return true;
}

void Simulation::sync_from_device() const {
  if (!device_ || !device_ahead_) return;
  device_ahead_ = false;
  ++device_downloads_;
  // p_ is a reference member: const here is the Simulation's, not the particles'.
  device_->download(p_);
  device_->download_cell_begin(device_cells_);
  grid_.adopt_ranges(device_cells_);
}

}  // namespace netsph
