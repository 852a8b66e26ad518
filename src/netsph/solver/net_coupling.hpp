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
//
// A sinker bar is too thin to resolve (the paper's is 6 mm, dp there 1.2 mm and here 12.5 mm),
// so its drag is modelled: at every stage the fluid is sampled along each bottom knot's share
// of the bar, at its ends midway to the neighbours and below the knot (net/current_loads.hpp,
// sinker_sample_points), and the bar takes cylinder drag on the mean of the water's velocity
// there relative to the knot (sinker_drag), in every sub-step of the knot-spring solver. Its
// reaction goes back to the water (sph/fluid_point_loads.hpp): the stage's drag as the
// sub-steps applied it, spread by kernel weight over the fluid along the share at points at
// most h apart (a line sink, as the bar is, not a few spots, which at fine resolution would
// stop the water crossing them), moved one kernel support (2h) downstream along the drag, so
// the water loses the momentum the net gains. Not at the bar itself: there it would slow the very
// water the drag is taken from (the self-induced velocity of two-way coupled point forces, Horwitz
// & Mani 2016), and the tethered knot's bar took 0.062 N instead of 0.075 N; one support downstream
// its kernel no longer reaches the sample point (only the edge of the water the sample averages)
// and the bar takes 0.075 N, as without the reaction. The knot bodies report the drag apart from
// the resolved fluid force (RigidBody::modelled_force), and the net's force group adds it: a load
// cell on the net's frame reads both.
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/net/current_loads.hpp"
#include "netsph/net/net_model.hpp"
#include "netsph/sph/fluid_point_loads.hpp"
#include "netsph/sph/fluid_sampler.hpp"

namespace netsph {

struct CoupledNet {
  NetModel model;
  std::size_t first_body = 0;   ///< body index of knot 0; knot k is body first_body + k
  std::vector<Vec3d> initial;   ///< undeformed knot positions
  double water_density = 1000;  ///< kg/m^3, for the sinker's drag
  /// How far downstream of the bar, along its drag, its reaction goes into the water, m
  /// (kSinkerReactionOffsetSupports kernel supports), and the largest spacing of the points
  /// along the bar it is spread over (h); 0 in tests without a fluid.
  double reaction_offset = 0;
  double reaction_spacing = 0;
  /// The water's velocity along each knot's share of the sinker bar at the stage being
  /// advanced, m/s: the weighted mean over its sample points in the water (Shepard coverage
  /// at least 1/2); wet: whether any is (a bar above a free surface takes no drag). Knots
  /// without a share: zero, false.
  std::vector<Vec3d> sinker_flow;
  std::vector<char> sinker_wet;
  /// A point where a knot's share of the bar gives the water its reaction at this stage.
  struct ReactionPoint {
    std::size_t knot = 0;
    Vec3d point{};  ///< m
    /// The point's part of the share's reaction (its length along the share over the wet
    /// parts') over the fluid's mass weight there, sum_j m_j W (kg/m^3): m^3/kg.
    double part_per_mass_weight = 0;
  };
  /// The stage's reaction points of every share: along the bar at most h apart, each moved
  /// reaction_offset downstream along its share's drag, where the water is.
  std::vector<ReactionPoint> sinker_reach;
  /// Each knot's sinker drag over the stage as the knot-spring sub-steps applied it (their
  /// trapezoidal mean), N: what the water takes back.
  std::vector<Vec3d> sinker_stage_drag;
  /// How many times (shares x stages over the run; a restart continues it) a share of the bar
  /// found no water reaction_offset downstream and gave its reaction at the bar, where it
  /// slows the water the drag is taken from, and the knot of the first such share (the run
  /// warns once; summary.json reports the count).
  std::size_t reactions_at_bar = 0;
  std::size_t first_knot_reacting_at_bar = 0;
};

/// The case with one [[body]] appended per knot of every [[net]] (after the case's own
/// bodies, in net and knot order), named "<net>.knot<row>_<column>", grouped by net.
CaseSpec spec_with_net_knots(const CaseSpec& spec);

/// The nets of a case expanded by spec_with_net_knots, with their knot-body indices.
std::vector<CoupledNet> coupled_nets(const CaseSpec& expanded);

/// Resolved knots in a fluid with gravity: the fluid's pressure buoys each knot body by the
/// water of about the lattice cells its particles stand for, rho_w g N dp^3 (measured on the
/// Bi 2014 net in still water at dp 20 mm, cases/waves/net_bi2014_waves3d.toml: 12-14 N up
/// on 9 knots of 18 particles, against 12.7 N from N dp^3 and the 5 N of the knots'
/// resolvable shapes), not by the shapes' volume the generator assumed
/// (net/net_generator.hpp, resolved_knot_volume). Corrects each knot's constant force
/// by the difference, from the bodies' particle counts, so that water and constant force
/// together give the netting's buoyancy. Nothing to do without gravity in the fluid.
void buoy_resolved_knots_by_their_particles(std::vector<CoupledNet>& nets,
                                            const std::vector<RigidBody>& bodies,
                                            const CaseSpec& expanded);

/// Samples the fluid along every net's sinker bar, where the knot bodies' present states put it,
/// into CoupledNet::sinker_flow and sinker_wet, and downstream of it for sinker_reach. A
/// stage calls it before the bodies move.
void sample_sinker_flows(std::vector<CoupledNet>& nets, const std::vector<RigidBody>& bodies,
                         const FluidSampler& sample);

/// How far downstream of its sample points a sinker bar's reaction goes into the water, in
/// kernel supports (2h).
inline constexpr double kSinkerReactionOffsetSupports = 1.0;

/// The Shepard coverage from which a sinker bar counts as in the water.
inline constexpr double kSinkerWetCoverage = 0.5;

/// One stage for every net: knot positions and velocities from the bodies' step-start state,
/// advanced by `stage_dt` under each knot body's fluid and contact force and its sinker's
/// drag (at the sampled flow), written back to the bodies' state; the sinker's drag as the
/// sub-steps applied it (their trapezoidal mean over the stage) goes to
/// CoupledNet::sinker_stage_drag and the knot bodies' modelled_force (its moment about the
/// knot's centre at the stage's end to modelled_torque).
void advance_coupled_nets(std::vector<CoupledNet>& nets, std::vector<RigidBody>& bodies,
                          double stage_dt);

/// Appends the reaction of every sinker's stage drag on the water, at the stage's reaction
/// points (CoupledNet::sinker_reach; after advance_coupled_nets).
void add_sinker_reactions(const std::vector<CoupledNet>& nets, std::vector<FluidPointLoad>& loads);

}  // namespace netsph
