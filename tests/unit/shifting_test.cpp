// Particle shifting (sph/shifting.hpp): dr = -A h |v| dt grad(C) inside the fluid, off at and
// below the free-surface threshold on div(r), a linear ramp in between, each component capped.
// The last tests build grad(C) and div(r) on a lattice with the Wendland kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "netsph/sph/kernels.hpp"
#include "netsph/sph/shifting.hpp"

namespace netsph {
namespace {

constexpr double kDp = 0.01;

ShiftingParams params(int dims) {
  ShiftingParams s;
  s.coefficient = 2;
  s.h = static_cast<Real>(1.5 * kDp);
  s.threshold = static_cast<Real>(default_shifting_threshold(dims));
  s.dims = static_cast<Real>(dims);
  s.max_component = static_cast<Real>(0.1 * kDp);
  return s;
}

TEST(Shifting, DefaultThresholds) {
  EXPECT_DOUBLE_EQ(default_shifting_threshold(2), 1.85);
  EXPECT_DOUBLE_EQ(default_shifting_threshold(3), 2.75);
}

TEST(Shifting, InsideTheFluidOppositeToGradC) {
  for (int dims : {2, 3}) {
    const ShiftingParams s = params(dims);
    const Vec3f grad_c{12.0f, dims == 3 ? -20.0f : 0.0f, 5.0f};  // 1/m
    const Real speed = 1.5f, dt = 1e-4f;
    const double k = 2 * 1.5 * kDp * 1.5 * 1e-4;  // A h |v| dt = 4.5e-6 m^2
    for (Real div_r : {static_cast<Real>(dims), static_cast<Real>(dims) + 0.3f}) {
      const Vec3f d = shifting_displacement(s, grad_c, div_r, speed, dt);
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(d[a], -k * grad_c[a], 1e-6 * k * 20) << "dims " << dims << " axis " << a;
      // Antiparallel to grad(C): from crowded to sparse.
      EXPECT_LT(dot(d, grad_c), 0);
      EXPECT_NEAR(norm(d), k * norm(grad_c), 1e-5 * k * norm(grad_c));
    }
  }
}

TEST(Shifting, ProportionalToSpeedAndTimeStep) {
  const ShiftingParams s = params(3);
  const Vec3f g{3, -1, 2};
  const Vec3f d1 = shifting_displacement(s, g, 3, 1.0f, 1e-4f);
  const Vec3f d2 = shifting_displacement(s, g, 3, 2.0f, 1e-4f);
  const Vec3f d3 = shifting_displacement(s, g, 3, 1.0f, 3e-4f);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(d2[a], 2 * d1[a], 1e-6 * std::fabs(d1[a]) + 1e-15);
    EXPECT_NEAR(d3[a], 3 * d1[a], 1e-6 * std::fabs(d1[a]) + 1e-15);
  }
  // At rest nothing moves.
  const Vec3f d0 = shifting_displacement(s, g, 3, 0.0f, 1e-4f);
  EXPECT_TRUE(d0 == Vec3f{});
}

TEST(Shifting, ZeroAtAndBelowTheThreshold) {
  for (int dims : {2, 3}) {
    const ShiftingParams s = params(dims);
    const Vec3f g{10, 0, -30};
    for (Real div_r : {s.threshold, s.threshold - 0.01f, 1.0f, 0.0f, -2.0f}) {
      const Vec3f d = shifting_displacement(s, g, div_r, 1.0f, 1e-4f);
      EXPECT_TRUE(d == Vec3f{}) << "dims " << dims << " div_r " << div_r;
    }
    // Just above the threshold: small but not zero.
    const Vec3f d = shifting_displacement(s, g, s.threshold + 0.01f, 1.0f, 1e-4f);
    EXPECT_GT(norm(d), 0.0f);
  }
}

TEST(Shifting, LinearRampBetweenThresholdAndDims) {
  for (int dims : {2, 3}) {
    const ShiftingParams s = params(dims);
    const Vec3f g{-8, dims == 3 ? 4.0f : 0.0f, 6};
    const Vec3f full = shifting_displacement(s, g, s.dims, 1.0f, 1e-4f);
    for (double f : {0.1, 0.25, 0.5, 0.9}) {
      const Real div_r = static_cast<Real>(s.threshold + f * (s.dims - s.threshold));
      const Vec3f d = shifting_displacement(s, g, div_r, 1.0f, 1e-4f);
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(d[a], f * full[a], 1e-5 * norm(full)) << "dims " << dims << " f " << f;
    }
  }
}

TEST(Shifting, EachComponentIsCapped) {
  const ShiftingParams s = params(3);
  const Real cap = s.max_component;
  // A huge gradient in x and z, a small one in y: x and z are capped, y is not.
  const Vec3f g{1e5f, 1.0f, -1e5f};
  const Vec3f d = shifting_displacement(s, g, 3, 1.0f, 1e-4f);
  EXPECT_FLOAT_EQ(d.x, -cap);
  EXPECT_FLOAT_EQ(d.z, cap);
  const double k = 2 * 1.5 * kDp * 1e-4;
  EXPECT_NEAR(d.y, -k * 1.0, 1e-6 * k);
  // Also within the ramp.
  const Vec3f r = shifting_displacement(s, g, 2.9f, 1.0f, 1e-4f);
  EXPECT_FLOAT_EQ(r.x, -cap);
  EXPECT_FLOAT_EQ(r.z, cap);
  for (int a = 0; a < 3; ++a) EXPECT_LE(std::fabs(r[a]), cap);
}

// ---------------------------------------------------------------------------------------------
// grad(C) and div(r) on a 2D lattice (the sums of backend/cpu/rates.cpp, written out here).

struct Sums {
  Vec3f grad_c{};
  Real div_r = 0;
};

/// grad(C)_a = sum_b V_b F r_ab and div(r)_a = -sum_b V_b F r_ab^2 with V_b = dp^2.
Sums lattice_sums(const std::vector<Vec3d>& pos, const Vec3d& ra) {
  const double h = 1.5 * kDp;
  const KernelScale ks = make_kernel_scale<WendlandC2>(2, h);
  const double vol = kDp * kDp;
  Vec3d g{};
  double div = 0;
  for (const Vec3d& rb : pos) {
    const Vec3d rab = ra - rb;
    const double r = norm(rab);
    if (r >= 2 * h || r == 0) continue;
    const double f = kernel_grad_factor<WendlandC2>(ks, static_cast<Real>(r));
    g += rab * (vol * f);
    div -= vol * f * r * r;
  }
  return {Vec3f(g), static_cast<Real>(div)};
}

TEST(Shifting, LatticeParticleIsPushedBackTowardsItsSite) {
  // 2D lattice 20 x 20 with a free surface on top; one interior particle displaced by 0.2 dp
  // towards its right neighbour is shifted back (-x); a regular interior particle is not
  // shifted; a surface particle is not shifted (div(r) below the threshold).
  std::vector<Vec3d> pos;
  for (int k = 0; k < 20; ++k)
    for (int i = 0; i < 20; ++i) pos.push_back({(i + 0.5) * kDp, 0, (k + 0.5) * kDp});
  const ShiftingParams s = params(2);
  const Real speed = 1.0f, dt = 1e-4f;

  const Vec3d interior{10.5 * kDp, 0, 10.5 * kDp};
  const Sums reg = lattice_sums(pos, interior);
  EXPECT_NEAR(reg.div_r, 2.0, 0.05) << "div(r) = dims inside the fluid";
  EXPECT_LT(norm(reg.grad_c), 1e-3);
  const Vec3f d_reg = shifting_displacement(s, reg.grad_c, reg.div_r, speed, dt);
  EXPECT_LT(norm(d_reg), 1e-6 * kDp);

  // Move the particle (index of the interior site) by 0.2 dp in +x.
  std::vector<Vec3d> moved = pos;
  const std::size_t idx = 10 * 20 + 10;
  ASSERT_NEAR(moved[idx].x, interior.x, 1e-12);
  moved[idx].x += 0.2 * kDp;
  const Sums off = lattice_sums(moved, moved[idx]);
  EXPECT_GT(off.grad_c.x, 1.0f);  // crowded on the +x side
  EXPECT_NEAR(off.grad_c.z, 0.0f, 1e-3);
  const Vec3f d_off = shifting_displacement(s, off.grad_c, off.div_r, speed, dt);
  EXPECT_LT(d_off.x, 0.0f);
  EXPECT_GT(std::fabs(d_off.x), 100 * std::fabs(d_off.z));

  // Top row: half the neighbourhood is missing. grad(C) points down into the fluid, so -grad(C)
  // would pull the particle out of it; shifting is off there.
  const Vec3d top{10.5 * kDp, 0, 19.5 * kDp};
  const Sums surf = lattice_sums(pos, top);
  EXPECT_LT(surf.div_r, s.threshold);
  EXPECT_LT(surf.grad_c.z, -1.0f);
  const Vec3f d_surf = shifting_displacement(s, surf.grad_c, surf.div_r, speed, dt);
  EXPECT_TRUE(d_surf == Vec3f{});
}

}  // namespace
}  // namespace netsph
