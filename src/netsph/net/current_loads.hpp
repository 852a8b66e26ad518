#pragma once
// Loads of a uniform current on a standalone net (no SPH fluid): the classic lumped-mass net
// models that the paper compares with.
//  - Screen model: each knot carries its share of the outline area as a small screen whose
//    normal follows the deformed net (from its neighbours); coefficients from
//    net/screen_model.hpp with the netting's solidity.
//  - Morison model: each twine feels normal and tangential drag,
//    F = 1/2 rho d (L - d) (Cn |u_n| u_n + Ct |u_t| u_t) (Cheng et al. 2020, model M1 with
//    Bessonneau & Marichal's Cn = 1.2, Ct = 0.1), half to each end knot; (L - d) leaves out
//    the crossing.
// Both use the velocity relative to the moving knots. A sinker bar adds cylinder drag on its
// projected area.
#include <vector>

#include "netsph/case/case_spec.hpp"
#include "netsph/net/net_model.hpp"

namespace netsph {

struct CurrentLoadParameters {
  Vec3d velocity{};                   ///< m/s
  double water_density = 1000;        ///< kg/m^3
  double kinematic_viscosity = 1e-6;  ///< m^2/s (S3 Reynolds number)
  NetLoadModel model = NetLoadModel::Screen;
  ScreenCoefficients screen = ScreenCoefficients::S3KristiansenFaltinsen;
  double normal_drag = 1.2;
  double tangential_drag = 0.1;
};

/// Adds the current's force on every knot to `forces` (one per knot).
void add_current_loads(const NetModel& net, const CurrentLoadParameters& p,
                       std::vector<Vec3d>& forces);

}  // namespace netsph
