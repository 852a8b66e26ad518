// Tait equation of state: P(rho0) = 0, the round trip density(pressure(rho)), and the sound
// speed it implies at rest, dP/drho = c0^2.
#include <gtest/gtest.h>

#include <cmath>

#include "netsph/sph/equation_of_state.hpp"

namespace netsph {
namespace {

TEST(TaitEos, ZeroPressureAtReferenceDensity) {
  const TaitEos e = TaitEos::make(1000, 40, 7);
  EXPECT_FLOAT_EQ(e.pressure(1000.0f), 0.0f);
  EXPECT_FLOAT_EQ(e.b, 40.0f * 40.0f * 1000.0f / 7.0f);
}

TEST(TaitEos, RoundTrip) {
  for (double gamma : {7.0, 1.0, 3.5}) {
    const TaitEos e = TaitEos::make(1025, 25, gamma);
    for (double p : {-2000.0, 0.0, 50.0, 9810.0, 3e4}) {
      const double rho = e.density(p);
      EXPECT_NEAR(e.pressure(static_cast<Real>(rho)), p, 1e-4 * e.b) << "gamma " << gamma;
    }
  }
}

TEST(TaitEos, SoundSpeedAtRest) {
  const TaitEos e = TaitEos::make(1000, 30, 7);
  const double d = 1e-2;
  const double dpdrho =
      (e.pressure(static_cast<Real>(1000 + d)) - e.pressure(static_cast<Real>(1000 - d))) / (2 * d);
  EXPECT_NEAR(dpdrho, 30.0 * 30.0, 0.01 * 900);
}

TEST(TaitEos, HydrostaticDensityMatchesLinearisation) {
  // rho(P) = rho0 (1 + x)^(1/gamma), x = P/B: to second order rho0 (1 + x/gamma
  // + (1/gamma)(1/gamma - 1) x^2 / 2), with x/gamma = P / (rho0 c0^2).
  const TaitEos e = TaitEos::make(1000, 40, 7);
  const double p = 1000 * 9.81 * 0.5, x = p / e.b, g = 7.0;
  const double second_order = 1000 * (1 + x / g + (1 / g) * (1 / g - 1) * x * x / 2);
  EXPECT_NEAR(e.density(p), second_order, 1e-3);
  EXPECT_NEAR(e.density(p), 1000 + p / (40.0 * 40.0), 0.05);
}

}  // namespace
}  // namespace netsph
