#include "netsph/solver/body_motion.hpp"

#include <algorithm>
#include <cmath>

namespace netsph {

void advance_bodies(const CaseSpec& spec, std::vector<RigidBody>& bodies,
                    std::vector<CoupledNet>& nets, double time, bool corrector, double dt,
                    const FluidSampler& sample, std::vector<FluidPointLoad>& water_loads) {
  const Vec3d g = spec.fluid.gravity;
  water_loads.clear();
  // Where the stage has the bodies, before they move.
  if (!nets.empty()) sample_sinker_flows(nets, bodies, sample);
  for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
    RigidBody& b = bodies[bi];
    if (!corrector) b.start = b.state;
    switch (b.motion) {
      case BodyMotion::Fixed:
        break;
      case BodyMotion::Prescribed: {
        // As the fluid: half step with the start velocity, full step by the trapezoid rule
        // (exact for a velocity linear in time over the step).
        const VelocityHistory& v = spec.bodies[bi].velocity;
        const Vec3d v0 = v.at(time), v1 = v.at(time + (corrector ? dt : 0.5 * dt));
        b.state.com =
            corrector ? b.start.com + (v0 + v1) * (0.5 * dt) : b.start.com + v0 * (0.5 * dt);
        b.state.vel = v1;
        break;
      }
      case BodyMotion::Floating: {
        const Vec3d force = b.fluid_force + b.contact_force + b.external_force;
        const Vec3d torque = b.fluid_torque + b.contact_torque + b.external_torque;
        const RigidAcceleration a = rigid_acceleration(b.inertia, b.state, force, torque, g);
        b.state = corrector ? rigid_correct(b.start, a, dt) : rigid_predict(b.start, a, dt);
        break;
      }
    }
  }
  // Net knots: translation by the twines and the fluid, sub-cycled over the stage.
  if (!nets.empty()) {
    advance_coupled_nets(nets, bodies, corrector ? dt : 0.5 * dt);
    add_sinker_reactions(nets, water_loads);
  }
}

}  // namespace netsph
