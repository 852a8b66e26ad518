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
  /// are resolved by SPH particles, whose pressure carries the buoyancy itself. The sinker,
  /// never resolved, always gets its buoyancy.
  bool knot_buoyancy = true;
};

/// Throws netsph::Error (naming the [[net]] table) when the outline is not a whole number of
/// numerical meshes within 5%.
NetModel generate_net(const NetSpec& spec, const NetEnvironment& env);

}  // namespace netsph
