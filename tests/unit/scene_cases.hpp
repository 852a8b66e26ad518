#pragma once
// Small scenes built in code for the set-up tests (scene_setup_test, scene_parts_test).
#include "netsph/case/case_spec.hpp"

namespace netsph::test {

/// A 0.4 m cube of fluid from the origin, 3D, with gravity.
inline CaseSpec fluid_cube(double dp) {
  CaseSpec spec;
  spec.simulation.dimensions = 3;
  spec.simulation.dp = dp;
  spec.fluid.gravity = {0, 0, -9.81};
  FillSpec f;
  f.box = {{0, 0, 0}, {0.4, 0.4, 0.4}};
  spec.fills.push_back(f);
  return spec;
}

/// The cube and two copies of it shifted by 0.3 dp and 0.6 dp along x. The second lies
/// 0.3 dp from the first everywhere: all of it goes. The third is 0.3 dp from the second
/// (removed: it removes nothing) and 0.4 dp from the first's next column, except its last
/// column, 0.6 dp beyond the first's last: only that column stays.
inline CaseSpec shifted_fill_copies(double dp) {
  CaseSpec spec = fluid_cube(dp);
  FillSpec f = spec.fills[0];
  for (const double shift : {0.3 * dp, 0.6 * dp}) {
    f.box = {spec.fills[0].box.min + Vec3d{shift, 0, 0},
             spec.fills[0].box.max + Vec3d{shift, 0, 0}};
    spec.fills.push_back(f);
  }
  return spec;
}

}  // namespace netsph::test
