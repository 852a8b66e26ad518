#pragma once
// The net generator: turns a [[net]] table (real netting data: outline, twine length and
// diameter, material) into knots and twines, after Shi et al. (2024), sections 2.2-2.3:
//  - mesh grouping: the numerical twine is lambda l0 long and lambda d0 thick, which keeps the
//    solidity 2d/l - (d/l)^2;
//  - equivalent knots: each twine crossing becomes a rigid shape with the cruciform element's
//    volume and projected area (net/equivalent_knot.hpp);
//  - edges: whole elements everywhere (the paper) or solidity-matched edge and corner knots.
// Masses are those of the real netting: a numerical element stands for lambda^2 real ones,
// so knot mass = rho_material V_element(l0, d0) lambda^2 (the numerical volume lambda^3 V
// would make a grouped net lambda times too heavy). docs/NETS.md gives the rules with the
// paper's numbers.
#include "netsph/case/case_spec.hpp"
#include "netsph/net/net_model.hpp"

namespace netsph {

struct NetEnvironment {
  Vec3d gravity{0, 0, -9.81};   ///< m/s^2
  double water_density = 1000;  ///< kg/m^3
  /// Add each knot's buoyancy (rho_w g V of the netting it stands for). False when the knots
  /// are resolved by SPH particles in a fluid with gravity, whose pressure carries a buoyancy
  /// rho_w g V_resolved on the knot as the particles resolve it; the generator then adds
  /// rho_w g (V_netting - V_resolved) so that the total is the netting's buoyancy (with mesh
  /// grouping the numerical knot holds lambda times the volume of the lambda^2 real elements
  /// it stands for). The sinker, never resolved, always gets its buoyancy.
  bool knot_buoyancy = true;
  /// The particle spacing that resolves the knots (with knot_buoyancy false), m. A knot is
  /// resolved at least 2 dp thick (geometry/shapes.hpp, resolvable_shape), and the fluid is
  /// removed from all of that volume; 0 takes the knot's own volume.
  double resolved_dp = 0;
};

/// The volume of a knot resolved by SPH particles at spacing dp, as the net generator counts
/// its buoyancy (resolvable_shape: every dimension at least 2 dp); its own volume when dp is 0.
/// The fluid's pressure acts on the lattice cells of the knot's particles instead, which the
/// coupling corrects for once the particles exist (solver/net_coupling.hpp,
/// buoy_resolved_knots_by_their_particles).
double resolved_knot_volume(const KnotGeometry& g, double dp);

/// The environment of a case's nets: a standalone net (no fluid) hangs under fluid.gravity
/// with its buoyancy added; knots resolved in a fluid with gravity get their buoyancy from the
/// fluid's pressure; in a fluid without gravity, fluid.structure_gravity (if given) gives
/// knots and sinkers their weight less buoyancy directly.
NetEnvironment net_environment(const CaseSpec& spec);

/// Throws netsph::Error (naming the [[net]] table) when the outline is not a whole number of
/// numerical meshes within 5%.
NetModel generate_net(const NetSpec& spec, const NetEnvironment& env);

}  // namespace netsph
