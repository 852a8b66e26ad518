// The per-particle symplectic stages both backends call (sph/symplectic.hpp): the update each
// particle kind gets, exactness where the scheme is exact, and how little a double position
// drifts over 1e6 steps (the precision docs/PERFORMANCE.md states for the device step).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "netsph/sph/symplectic.hpp"

namespace netsph {
namespace {

/// One whole step of one particle under constant rates: predictor, then corrector.
void full_step(ParticleKind kind, const WallKinematics* wall, const Vec3f& acc, Real drho,
               double dt, Vec3d& r, Vec3f& v, Real& rho) {
  const Vec3f v0 = v;
  const Real rho0 = rho;
  symplectic_predict_particle(kind, wall, acc, drho, dt, 1000.0f, r, v, rho);
  symplectic_correct_particle(kind, wall, v0, rho0, acc, drho, dt, 1000.0f, r, v, rho);
}

TEST(Symplectic, ConstantAccelerationIsExact) {
  // Position Verlet is exact for constant acceleration: r = r0 + v0 t + a t^2 / 2. A step of
  // 2^-10 s and an acceleration of 9.8125 m/s^2 (157/16) keep every float velocity exact, so
  // what is left is the double positions' round-off.
  Vec3d r{0.5, 0.25, 1.0};
  Vec3f v{0.5f, 0.0f, 0.25f};
  Real rho = 1000;
  const Vec3f a{0.0f, 0.0f, -9.8125f};
  const double dt = std::ldexp(1.0, -10);
  const int steps = 1000;
  for (int s = 0; s < steps; ++s) full_step(ParticleKind::Fluid, nullptr, a, 0, dt, r, v, rho);
  const double t = steps * dt;
  EXPECT_NEAR(r.x, 0.5 + 0.5 * t, 1e-13);
  EXPECT_NEAR(r.z, 1.0 + 0.25 * t - 0.5 * 9.8125 * t * t, 1e-13);
  EXPECT_EQ(v.z, static_cast<float>(0.25 - 9.8125 * t));
}

TEST(Symplectic, HalfStepCorrectorIsTheTextbookCorrector) {
  // r* + dt/2 v^{n+1} against r^n + dt/2 (v^n + v^{n+1}): the same update, to round-off.
  const Vec3d r0{1.234567, -0.5, 2.0};
  const Vec3f v0{0.3f, -1.2f, 0.7f}, a{4.0f, 2.5f, -9.81f};
  const double dt = 2.5e-4;
  Vec3d r = r0;
  Vec3f v = v0;
  Real rho = 1002;
  full_step(ParticleKind::Fluid, nullptr, a, -3.0f, dt, r, v, rho);
  const Vec3f v1 = v0 + a * static_cast<Real>(dt);
  const Vec3d textbook = r0 + (Vec3d(v0) + Vec3d(v1)) * (0.5 * dt);
  // A few roundings of numbers below 2 apart (with or without fused multiply-adds); a wrong
  // update would be off by about dt |v| = 1e-4.
  EXPECT_NEAR(r.x, textbook.x, 4e-15);
  EXPECT_NEAR(r.y, textbook.y, 4e-15);
  EXPECT_NEAR(r.z, textbook.z, 4e-15);
  EXPECT_FLOAT_EQ(v.x, v1.x);
  // Density: rho^n (2 - eps) / (2 + eps) with eps from the half-step rate.
  const Real rho_half = 1002 + Real(-3.0f * 0.5 * dt);
  const Real eps = -(Real(-3.0f) / rho_half) * static_cast<Real>(dt);
  EXPECT_FLOAT_EQ(rho, 1002 * (2 - eps) / (2 + eps));
}

TEST(Symplectic, WallFollowsALinearVelocityExactly) {
  // Trapezoid rule over the step: exact for a velocity linear in time.
  const double dt = 0.01, accel = 3.0;  // v(t) = accel t along x, from t = 0
  WallKinematics w;
  w.start = {0.0f, 0.0f, 0.0f};
  w.half = {static_cast<float>(accel * dt / 2), 0.0f, 0.0f};
  w.end = {static_cast<float>(accel * dt), 0.0f, 0.0f};
  Vec3d r{0.1, 0.0, 0.0};
  Vec3f v{};
  Real rho = 990;  // below rho0: the wall clamps it
  const double d2 =
      symplectic_predict_particle(ParticleKind::Wall, &w, {}, 0, dt, 1000.0f, r, v, rho);
  EXPECT_EQ(d2, 0.0);  // the start velocity is zero
  EXPECT_FLOAT_EQ(v.x, w.half.x);
  EXPECT_EQ(rho, 1000.0f);
  symplectic_correct_particle(ParticleKind::Wall, &w, {}, 990.0f, {}, 0, dt, 1000.0f, r, v, rho);
  EXPECT_NEAR(r.x, 0.1 + 0.5 * accel * dt * dt, 1e-9);  // float velocities: 1e-7 relative
  EXPECT_FLOAT_EQ(v.x, w.end.x);
}

TEST(Symplectic, BodyParticlesIntegrateOnlyContinuity) {
  Vec3d r{1.0, 2.0, 3.0};
  Vec3f v{1.0f, 0.0f, 0.0f};
  Real rho = 1000;
  full_step(ParticleKind::Body, nullptr, {5.0f, 0.0f, 0.0f}, 20.0f, 0.01, r, v, rho);
  EXPECT_EQ(r.x, 1.0);  // the rigid body places its particles
  EXPECT_EQ(v.x, 1.0f);
  EXPECT_GT(rho, 1000.0f);
}

TEST(Symplectic, BufferParticlesMoveWithTheirVelocity) {
  Vec3d r{0.0, 0.0, 0.5};
  Vec3f v{0.4f, 0.0f, 0.0f};
  Real rho = 1000;
  full_step(ParticleKind::Buffer, nullptr, {9.0f, 0.0f, 0.0f}, 50.0f, 0.01, r, v, rho);
  EXPECT_NEAR(r.x, 0.01 * static_cast<double>(0.4f), 1e-15);
  EXPECT_EQ(v.x, 0.4f);  // state kept: the buffer's velocity is imposed or extrapolated
  EXPECT_EQ(rho, 1000.0f);
}

TEST(Symplectic, DoublePositionsDriftFarBelowAThousandthOfDpOverAMillionSteps) {
  // The paper's finest net case: dp = 1.2 mm in a domain of about 1e3 dp. A fluid particle
  // crossing it at 0.1 m/s for 1e6 steps of 2e-6 s: every stage rounds the double position
  // once, so the drift is at most 2e6 roundings of 2^-53 |x|.
  const double dp = 1.2e-3, x0 = 1.0, dt = 2e-6;
  const int steps = 1000000;
  const Vec3f v0{0.1f, 0.0f, -0.05f};
  Vec3d r{x0, 0.3, 0.6};
  Vec3f v = v0;
  Real rho = 1000;
  for (int s = 0; s < steps; ++s) full_step(ParticleKind::Fluid, nullptr, {}, 0, dt, r, v, rho);
  const long double t = static_cast<long double>(steps) * dt;
  const long double exact_x = x0 + t * static_cast<long double>(v0.x);
  const long double exact_z = 0.6L + t * static_cast<long double>(v0.z);
  const double err =
      std::hypot(static_cast<double>(r.x - exact_x), static_cast<double>(r.z - exact_z));
  const double bound = 2.0 * steps * std::ldexp(1.0, -53) * std::hypot(r.x, r.z);
  std::printf("drift after 1e6 steps: %.3g m = %.3g dp (worst-case bound %.3g dp)\n", err, err / dp,
              bound / dp);
  EXPECT_LE(err, bound);
  EXPECT_LT(err / dp, 1e-3);
}

}  // namespace
}  // namespace netsph
