// Laminar flows between plates against their analytic profiles: Poiseuille (body force,
// periodic in x, mDBC no-slip plates) and Couette (top plate moving and wrapping around the
// periodic axis). Both reach their steady state after about 0.5 H^2 / nu = 0.5 s.
#include <gtest/gtest.h>

#include <cmath>

#include "case_runs.hpp"

namespace netsph {
namespace {

constexpr double kH = 0.1, kNu = 0.01;

double poiseuille_error(double dp) {
  Simulation sim(test::load_case("poiseuille2d.toml", {"simulation.dp=" + std::to_string(dp)}));
  test::run_until(sim, 1.0);
  const double g = 2.0;
  return test::relative_l2_error_x(sim, [&](double z) { return g / (2 * kNu) * z * (kH - z); });
}

TEST(LaminarChannel, PoiseuilleProfileConverges) {
  // Measured: 3.0% with 10 particles across, 0.60% with 20, 0.46% with 40 (docs/VALIDATION.md).
  const double coarse = poiseuille_error(0.01), fine = poiseuille_error(0.005);
  EXPECT_LT(fine, 0.03);
  EXPECT_LT(fine, 0.5 * coarse);
}

TEST(LaminarChannel, CouetteProfileIsLinear) {
  Simulation sim(test::load_case("couette2d.toml"));
  const ParticleSet& p0 = sim.particles();
  std::size_t n_fluid = p0.count(ParticleKind::Fluid);
  test::run_until(sim, 1.0);
  const double U = 0.25;
  const double l2 = test::relative_l2_error_x(sim, [&](double z) { return U * z / kH; });
  EXPECT_LT(l2, 0.03);
  // Pointwise too: every fluid particle within 3% of U of the line (measured 0.22%).
  const ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_fluid(p.kind[i])) continue;
    EXPECT_NEAR(p.vel[i].x, U * p.pos[i].z / kH, 0.03 * U) << "z = " << p.pos[i].z;
    EXPECT_GT(p.pos[i].z, 0.0);
    EXPECT_LT(p.pos[i].z, kH);
  }
  // The moving plate travelled 2.5 periods; its particles wrapped around the periodic x axis
  // (positions are wrapped at the start of each step, so allow one step's travel past it).
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p.pos[i].x, -0.001);
    EXPECT_LT(p.pos[i].x, 0.101);
  }
  EXPECT_EQ(p.count(ParticleKind::Fluid), n_fluid);
}

}  // namespace
}  // namespace netsph
