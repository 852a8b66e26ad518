#include "netsph/solver/device_setup.hpp"

#include <string>

#include "netsph/core/error.hpp"
#include "netsph/neighbors/cell_grid.hpp"
#include "netsph/solver/body_motion.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "netsph/solver/step_settings.hpp"

namespace netsph {

namespace {

/// A device run of a case with the bodies and nets kept on the host: the step's
/// advance_bodies hook runs the CPU solver's body and net stages (body_motion.hpp) on them.
class CaseDeviceRun final : public DeviceRun {
 public:
  CaseDeviceRun(const CaseSpec& spec, DeviceExecutor exec)
      : spec_(spec_with_net_knots(spec)), nets_(coupled_nets(spec_)) {
    const Scene scene = build_scene(spec_);
    bodies_ = scene.bodies;
    // Knots carry their weight and buoyancy in the knot-spring solver (as Simulation).
    for (const CoupledNet& net : nets_) {
      for (std::size_t k = 0; k < net.model.knots.size(); ++k)
        bodies_[net.first_body + k].external_force = {};
    }
    DeviceSetup setup = device_setup(spec_, scene);
    setup.advance_bodies = [this](bool corrector, double time, double dt,
                                  const std::vector<DeviceBodyLoads>& loads,
                                  std::vector<RigidState>& states) {
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const double* f = loads[b].f;
        RigidBody& body = bodies_[b];
        body.fluid_force = {f[0], f[1], f[2]}, body.fluid_torque = {f[3], f[4], f[5]};
        body.contact_force = {f[6], f[7], f[8]}, body.contact_torque = {f[9], f[10], f[11]};
      }
      advance_bodies(spec_, bodies_, nets_, time, corrector, dt);
      for (std::size_t b = 0; b < bodies_.size(); ++b) states[b] = bodies_[b].state;
    };
    bool moving = false;
    for (const WallSpec& w : spec_.walls) moving |= w.motion.moving();
    if (moving) {
      setup.wall_velocity = [this](std::size_t w, double t) {
        return Vec3f(spec_.walls[w].motion.at(t));
      };
    }
    if (exec == DeviceExecutor::Host) {
      inner_ = make_host_device_run(std::move(setup), scene.particles);
    } else {
#if defined(NETSPH_HAVE_CUDA)
      inner_ = make_cuda_device_run(std::move(setup), scene.particles);
#else
      throw Error("--backend cuda",
                  "this netsph was built without CUDA (no nvcc found at configure time); use "
                  "--backend cpu");
#endif
    }
  }

  DeviceStepReport step() override {
    return inner_->step();
  }
  void download(ParticleSet& p) const override {
    inner_->download(p);
  }
  double time() const override {
    return inner_->time();
  }
  std::int64_t steps() const override {
    return inner_->steps();
  }
  std::size_t size() const override {
    return inner_->size();
  }
  double bytes_per_particle() const override {
    return inner_->bytes_per_particle();
  }
  const std::vector<RigidState>& body_states() const override {
    return inner_->body_states();
  }
  const std::vector<DeviceBodyLoads>& body_loads() const override {
    return inner_->body_loads();
  }

 private:
  CaseSpec spec_;
  std::vector<CoupledNet> nets_;
  std::vector<RigidBody> bodies_;
  std::unique_ptr<DeviceRun> inner_;
};

}  // namespace

DeviceSetup device_setup(const CaseSpec& spec, const Scene& scene) {
  // Probes are outputs, and a device run writes none yet (the caller downloads the particles).
  DeviceSetup s;
  s.model = scene.model;
  CellGrid grid;
  grid.configure(scene.domain_min, scene.domain_max, s.model.support, kGridSkin, s.model.dims,
                 spec.domain.periodic);
  s.max_displacement = grid.max_displacement();
  s.grid = grid.index();
  s.cfl = spec.simulation.cfl;
  s.dt_max = spec.simulation.dt_max;
  s.dt_min = spec.simulation.dt_min;
  s.shifting = spec.fluid.shifting == ShiftingModel::Fickian;
  s.shift_params = shifting_params(spec, s.model);
  for (const WallSpec& w : spec.walls) {
    DeviceWall d;
    d.mdbc = w.model == WallModel::Mdbc;
    d.slip = w.slip;
    d.shows_own_velocity = w.model == WallModel::Dbc || w.slip == WallSlip::WallVelocity;
    s.walls.push_back(d);
  }
  for (const OpenBoundaryZone& z : scene.zones) {
    DeviceZone d;
    d.geo = z.geometry();
    d.velocity_imposed = z.velocity_imposed;
    d.speed = z.speed;
    d.profile_begin = static_cast<std::uint32_t>(s.profile_z.size());
    d.profile_count = static_cast<std::uint32_t>(z.profile_z.size());
    d.density = z.density;
    s.zones.push_back(d);
    s.profile_z.insert(s.profile_z.end(), z.profile_z.begin(), z.profile_z.end());
    s.profile_u.insert(s.profile_u.end(), z.profile_u.begin(), z.profile_u.end());
  }
  s.gz = spec.fluid.gravity.z;
  for (const RigidBody& b : scene.bodies) {
    DeviceBody d;
    d.state = b.state;
    d.first_id = b.first_id;
    d.offset_base = static_cast<std::uint32_t>(s.body_offsets.size());
    d.mdbc = b.model == WallModel::Mdbc;
    d.slip = b.slip;
    d.shows_own_velocity = b.shows_own_velocity();
    s.bodies.push_back(d);
    s.body_offsets.insert(s.body_offsets.end(), b.offsets.begin(), b.offsets.end());
    s.body_ghosts.insert(s.body_ghosts.end(), b.ghosts.begin(), b.ghosts.end());
  }
  s.contact = ContactModel::make(spec.simulation.dp, scene.sound_speed);
  return s;
}

std::unique_ptr<DeviceRun> make_device_run(const CaseSpec& spec, DeviceExecutor exec) {
  return std::make_unique<CaseDeviceRun>(spec, exec);
}

}  // namespace netsph
