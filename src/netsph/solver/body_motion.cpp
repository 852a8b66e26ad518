#include "netsph/solver/body_motion.hpp"

#include <algorithm>
#include <cmath>

namespace netsph {

RigidState prescribed_rotation(const RigidState& start, const BodySpec& body, double time,
                               bool corrector, double dt) {
  // As a prescribed translation: the predictor turns by the start's rate over half a step, the
  // corrector by the trapezoid rule over the whole step. Turns about one fixed axis compose
  // exactly, so the body turns by the integral of its rate (exact for a rate linear over the
  // step) and the hinge does not move.
  const VelocityHistory& w = body.angular_velocity;
  const Vec3d w0 = w.at(time), w1 = w.at(time + (corrector ? dt : 0.5 * dt));
  const Vec3d turn = corrector ? (w0 + w1) * (0.5 * dt) : w0 * (0.5 * dt);
  const Quat dq = Quat::from_rotation_vector(turn);
  RigidState s;
  s.q = normalized(dq * start.q);
  s.com = body.hinge + rotate(dq, start.com - body.hinge);
  s.omega = w1;
  s.vel = cross(w1, s.com - body.hinge);
  return s;
}

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
        if (spec.bodies[bi].angular_velocity.moving()) {
          b.state = prescribed_rotation(b.start, spec.bodies[bi], time, corrector, dt);
          break;
        }
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
