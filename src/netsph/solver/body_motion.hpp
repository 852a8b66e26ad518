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

namespace netsph {

/// Advances every body to the half step (predictor, `corrector` false) or the full step from
/// its step-start state (saved here in the predictor): fixed bodies stay, prescribed ones
/// follow their velocity history, floating ones move under fluid, contact and external loads
/// and gravity; net knots are then advanced by the knot-spring solver. `time` is the step's
/// start.
void advance_bodies(const CaseSpec& spec, std::vector<RigidBody>& bodies,
                    std::vector<CoupledNet>& nets, double time, bool corrector, double dt);

/// What is wrong, in words, if a particle of body `b` may lie outside the domain along a
/// periodic axis (judged by its particle farthest from the centre of mass); empty if none can.
/// Not supported: the sort wraps particles into the period, but a body's particles are placed
/// again at centre + offset every stage, a period away from the cells they were sorted into,
/// where the neighbour search does not look, so the fluid there would not see them.
std::string body_outside_periodic_extent(const CaseSpec& spec, const RigidBody& b);

}  // namespace netsph
