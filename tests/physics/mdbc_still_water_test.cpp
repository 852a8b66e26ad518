// Still water in a tank with mDBC walls (cases/hydrostatic2d.toml with model = "mdbc",
// dp = 0.02 m): no particle penetrates the wall surface and the pressure at depth d is
// rho0 g d within 3% away from the walls; mass is conserved exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "case_runs.hpp"

namespace netsph {
namespace {

TEST(MdbcStillWater, HydrostaticWithinThreePercentAndNoPenetration) {
  Simulation sim(
      test::load_case("hydrostatic2d.toml", {"simulation.dp=0.02", "wall.0.model=mdbc"}));
  ASSERT_EQ(sim.spec().walls[0].model, WallModel::Mdbc);
  const double dp = 0.02, rho0 = 1000, g = 9.81;
  const std::size_t n_fluid = sim.particles().count(ParticleKind::Fluid);
  std::map<int, std::pair<double, double>> sums;
  std::map<int, int> counts;
  double min_gap = 1e9;  // closest approach of a fluid particle to the wall surface
  while (sim.time() < 2.0) {
    sim.step();
    const ParticleSet& p = sim.particles();
    double top = -1e9;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!is_fluid(p.kind[i])) continue;
      const Vec3d x = p.pos[i];
      min_gap = std::min({min_gap, x.x, 1.0 - x.x, x.z});
      top = std::max(top, x.z);
    }
    if (sim.time() < 1.5 || sim.steps() % 50 != 0) continue;
    const auto press = sim.pressures();
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!is_fluid(p.kind[i]) || p.pos[i].x < 0.1 || p.pos[i].x > 0.9) continue;
      const double depth = top + dp / 2 - p.pos[i].z;
      const int bin = static_cast<int>(depth / 0.1);
      sums[bin].first += depth, sums[bin].second += press[i];
      ++counts[bin];
    }
  }
  // mDBC keeps the fluid about dp/2 off the wall surface (measured: 0.44 dp).
  EXPECT_GT(min_gap, 0.25 * dp);
  EXPECT_EQ(sim.particles().count(ParticleKind::Fluid), n_fluid);
  EXPECT_EQ(sim.diagnostics().lost_total, 0u);
  ASSERT_GE(sums.size(), 4u);
  for (const auto& [bin, s] : sums) {
    const double depth = s.first / counts[bin], pressure = s.second / counts[bin];
    if (depth < 2 * dp) continue;
    EXPECT_NEAR(pressure / (rho0 * g * depth), 1.0, 0.03) << "depth " << depth << " m";
  }
}

}  // namespace
}  // namespace netsph
