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
// projected area (sinker_drag, which coupled runs use too, with the SPH fluid's velocity at
// the bar). With [waves] (a standalone case's), the water's velocity at each knot, twine and
// bar is the current plus the waves' orbital velocity there (linear or Stokes-2 theory,
// waves/wave_train.hpp), and what lies above the wave's surface is in air and takes no load.
// Only drag: the inertia (Froude-Krylov and added mass) of twines a millimetre or two thick
// is small beside it at the Keulegan-Carpenter numbers of waves on nets (KC = u T / d in the
// hundreds).
#include <cstdint>
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
  /// Waves whose orbital velocity adds to `velocity` (a standalone case's [waves]), at `time`.
  const WaveSpec* waves = nullptr;
  double time = 0;  ///< s
};

/// The water's velocity at x (m/s) into `u`: the current, plus the waves' orbital velocity.
/// False where x lies above the wave's surface (in air: no load there).
bool water_velocity(const CurrentLoadParameters& p, const Vec3d& x, Vec3d& u);

/// Where the sinker bar that knot `k` carries is now: the net's bottom edge, below the bottom
/// row of knots by NetModel::sinker_offset along the deformed net (from the knot above it
/// to `k`; the net's down direction in a net one knot tall).
Vec3d sinker_point(const NetModel& net, const NetKnot& k);

/// Where the water that meets knot `k`'s share of the bar is sampled in a coupled run, with
/// the weights of a mean along the share.
struct SinkerSamples {
  Vec3d points[3];
  double weights[3] = {};
  int count = 0;
};
/// The ends of `k`'s share of the bar (midway to each neighbour along the bottom row, or the
/// bar's end at the net's side where the share reaches it: the end knots of the inset
/// layout) and, in the inset layout, the bar below the knot; by the trapezoidal rule. In the
/// crossings layout the bar runs through the knot, whose particles leave no water there: the
/// ends only. Returns the number of points (1 to 3).
int sinker_sample_points(const NetModel& net, const NetKnot& k, SinkerSamples& samples);

/// Drag on the length of sinker bar knot `k` carries in water flowing at `flow` (m/s, the
/// water's velocity at the bar) of density `water_density`: cylinder drag on the velocity
/// relative to the knot, normal to the bar (along the net's across direction),
/// F = 1/2 rho Cd d L |u_n| u_n (Morison et al. 1950, the drag term), N. Zero for knots
/// without a sinker share.
Vec3d sinker_drag(const NetModel& net, const NetKnot& k, const Vec3d& flow, double water_density);

/// The water's velocity where the loads act on a net (each knot, each twine's middle, each
/// knot's sinker bar) and whether there is water there: sampled once for many load
/// evaluations (a standalone run's knot sub-steps within one of its load steps), since waves
/// make it a sum over every component at every point.
struct NetWater {
  std::vector<Vec3d> knot, twine, sinker;
  std::vector<std::uint8_t> knot_wet, twine_wet, sinker_wet;
};
void sample_net_water(const NetModel& net, const CurrentLoadParameters& p, NetWater& out);

/// Adds the current's force on every knot to `forces` (one per knot), with the water's
/// velocity from `water` when given (sample_net_water of the same net), else evaluated here.
void add_current_loads(const NetModel& net, const CurrentLoadParameters& p,
                       std::vector<Vec3d>& forces, const NetWater* water = nullptr);

}  // namespace netsph
