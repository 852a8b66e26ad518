#pragma once
// Two-way coupling of nets with the SPH fluid (Shi et al. 2024, section 2.3, done better):
// every knot of a [[net]] becomes a floating rigid body resolved by boundary particles
// (mDBC), so the fluid force on it is the sum over its particles, with no drag coefficient.
// At both symplectic stages the knots' translation is integrated by the knot-spring solver
// (net/knot_spring_solver.hpp), sub-cycled from the step-start state over the stage (dt/2 in
// the predictor, dt in the corrector) with the fluid and contact forces of that stage's rates
// pass held constant, so the twines act in both stages (DualSPHysics + MoorDyn couple only in
// the corrector) and their stiffness never shortens the fluid dt. The knots' rotation follows
// the fluid torque through the rigid-body stages (twines act at the knot centres). Anchored
// knots are fixed bodies.
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/net/net_model.hpp"

namespace netsph {

struct CoupledNet {
  NetModel model;
  std::size_t first_body = 0;  ///< body index of knot 0; knot k is body first_body + k
  std::vector<Vec3d> initial;  ///< undeformed knot positions
};

/// The case with one [[body]] appended per knot of every [[net]] (after the case's own
/// bodies, in net and knot order), named "<net>.knot<row>_<column>", grouped by net.
CaseSpec spec_with_net_knots(const CaseSpec& spec);

/// The nets of a case expanded by spec_with_net_knots, with their knot-body indices.
std::vector<CoupledNet> coupled_nets(const CaseSpec& expanded);

/// One stage for every net: knot positions and velocities from the bodies' step-start state,
/// advanced by `stage_dt` under each knot body's fluid and contact force, written back to the
/// bodies' state.
void advance_coupled_nets(std::vector<CoupledNet>& nets, std::vector<RigidBody>& bodies,
                          double stage_dt);

}  // namespace netsph
