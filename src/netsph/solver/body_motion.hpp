#pragma once
// One symplectic stage of every rigid body, from the loads of that stage's rates pass: shared
// by the CPU solver (simulation.cpp) and the device-shaped step's host side
// (device_setup.cpp), which keeps bodies and nets on the host and their particles on the
// device.
#include <string>
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/solver/net_coupling.hpp"
#include "netsph/sph/fluid_sampler.hpp"

namespace netsph {

/// Advances every body to the half step (predictor, `corrector` false) or the full step from
/// its step-start state (saved here in the predictor): fixed bodies stay, prescribed ones
/// follow their velocity history, floating ones move under fluid, contact and external loads
/// and gravity; net knots are then advanced by the knot-spring solver, their sinker bars'
/// drag from the fluid `sample` gives at the bars. `time` is the step's start. `water_loads`
/// receives what the stage's modelled parts put on the water (the sinker bars' reaction),
/// for the step to add to the fluid's accelerations before it moves the fluid.
void advance_bodies(const CaseSpec& spec, std::vector<RigidBody>& bodies,
                    std::vector<CoupledNet>& nets, double time, bool corrector, double dt,
                    const FluidSampler& sample, std::vector<FluidPointLoad>& water_loads);

/// What is wrong, in words, if body `b` is as wide as half a periodic axis's period or wider
/// (judged by its particle farthest from the centre of mass, so whatever its rotation); empty
/// if not. A body may cross a periodic end (place_rigid_particle puts each particle at the image
/// nearest the cell it was sorted into), but its lever arms are taken at the nearest image of
/// each particle (rigid_lever_arm), which is its own only while the body spans less than half
/// a period.
std::string body_wider_than_half_period(const CaseSpec& spec, const RigidBody& b);

}  // namespace netsph
