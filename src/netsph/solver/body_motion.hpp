#pragma once
// One symplectic stage of every rigid body, from the loads of that stage's rates pass: shared
// by the CPU solver (simulation.cpp) and the device-shaped step's host side
// (device_setup.cpp), which keeps bodies and nets on the host and their particles on the
// device.
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "netsph/sph/fluid_sampler.hpp"

namespace netsph {

/// A prescribed rotation's state at the half step (predictor) or full step (corrector) from
/// the step's `start`: the body turned about the axis through `body.hinge` by its
/// angular_velocity history, its centre carried round the hinge (a flap paddle).
RigidState prescribed_rotation(const RigidState& start, const BodySpec& body, double time,
                               bool corrector, double dt);

/// Advances every body to the half step (predictor, `corrector` false) or the full step from
/// its step-start state (saved here in the predictor): fixed bodies stay, prescribed ones
/// follow their velocity history (or turn about their hinge), floating ones move under fluid,
/// contact and external loads and gravity; net knots are then advanced by the knot-spring solver,
/// their sinker bars' drag from the fluid `sample` gives at the bars. `time` is the step's start.
/// `water_loads` receives what the stage's modelled parts put on the water (the sinker bars'
/// reaction), for the step to add to the fluid's accelerations before it moves the fluid.
void advance_bodies(const CaseSpec& spec, std::vector<RigidBody>& bodies,
                    std::vector<CoupledNet>& nets, double time, bool corrector, double dt,
                    const FluidSampler& sample, std::vector<FluidPointLoad>& water_loads);

}  // namespace netsph
