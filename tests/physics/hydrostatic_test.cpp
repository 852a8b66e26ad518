// Still water in a 2D tank (cases/hydrostatic2d.toml at dp = 0.02 m): after the start-up
// transient the pressure at depth d is rho0 g d within 5% away from the walls, the water
// settles, no particle crosses a wall and the mass is conserved exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "case_runs.hpp"
#include "netsph/run/run_outputs.hpp"

namespace netsph {
namespace {

TEST(Hydrostatic, PressureIsRhoGDepthAndNothingLeaks) {
  Simulation sim(test::load_case("hydrostatic2d.toml", {"simulation.dp=0.02"}));
  const double dp = 0.02, rho0 = 1000, g = 9.81, width = 1.0;
  const std::size_t n_fluid = sim.particles().count(ParticleKind::Fluid);
  ASSERT_EQ(n_fluid, 50u * 25u);

  // Depth bins of 0.1 m; sums of depth and pressure over samples in the settled window.
  std::map<int, std::pair<double, double>> sums;
  std::map<int, int> counts;
  double min_x = 1e9, max_x = -1e9, min_z = 1e9;
  while (sim.time() < 2.0) {
    sim.step();
    const ParticleSet& p = sim.particles();
    double top = -1e9;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!is_fluid(p.kind[i])) continue;
      min_x = std::min(min_x, p.pos[i].x), max_x = std::max(max_x, p.pos[i].x);
      min_z = std::min(min_z, p.pos[i].z), top = std::max(top, p.pos[i].z);
    }
    if (sim.time() < 1.5 || sim.steps() % 50 != 0) continue;
    const double surface = top + dp / 2;
    const auto press = sim.pressures();
    for (std::size_t i = 0; i < p.size(); ++i) {
      // Away from the side walls by more than the kernel support.
      if (!is_fluid(p.kind[i]) || p.pos[i].x < 0.1 || p.pos[i].x > width - 0.1) continue;
      const double depth = surface - p.pos[i].z;
      const int bin = static_cast<int>(depth / 0.1);
      sums[bin].first += depth, sums[bin].second += press[i];
      ++counts[bin];
    }
  }
  EXPECT_EQ(sim.particles().count(ParticleKind::Fluid), n_fluid);  // mass exactly conserved
  EXPECT_EQ(sim.diagnostics().lost_total, 0u);
  // The wall surface is the box face; fluid particles start dp/2 inside it and must stay in.
  EXPECT_GT(min_x, 0.0);
  EXPECT_LT(max_x, width);
  EXPECT_GT(min_z, 0.0);

  ASSERT_GE(sums.size(), 4u);
  for (const auto& [bin, s] : sums) {
    const double depth = s.first / counts[bin], pressure = s.second / counts[bin];
    if (depth < 2 * dp) continue;  // the top row: p ~ 0 +- noise
    EXPECT_NEAR(pressure / (rho0 * g * depth), 1.0, 0.05) << "depth " << depth << " m";
  }
  // Settled: the kinetic energy is a tiny fraction of the potential energy scale M g H
  // (measured 3e-6 of it: slow particle rearrangement near the DBC walls, ~1 cm/s).
  const GlobalMeasures m = measure(sim);
  EXPECT_LT(m.kinetic_energy, 1e-5 * m.fluid_mass * g * 0.5);
  EXPECT_LT(m.max_speed, 0.02 * std::sqrt(g * 0.5));
}

}  // namespace
}  // namespace netsph
