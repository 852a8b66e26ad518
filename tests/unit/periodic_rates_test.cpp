// The interaction pass (backend/cpu/rates.cpp) on a periodic grid: a fully periodic lattice in a
// uniform state has no rates apart from gravity (every particle sees the full neighbourhood
// through the periodic images), momentum is conserved pairwise across the periodic boundary,
// and a periodic block gives the same rates as the middle copy of the block tiled 3 x 3 x 3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "particle_fixture.hpp"

namespace netsph {
namespace {

constexpr double kDp = 0.01;
constexpr int kN = 8;  // lattice cells per side: period 8 dp = 5 grid cells (the minimum)
constexpr double kL = kN * kDp;

using Block = test::ParticleBlock;

FluidModelInput input(DensityDiffusion diffusion = DensityDiffusion::Molteni) {
  FluidModelInput in = test::fluid_input(3, kDp, 20);
  in.alpha = 0.1;
  in.diffusion = diffusion;
  return in;
}

/// kN^3 lattice filling the periodic box [0, kL)^3, shifted by `offset` (then wrapped).
Block periodic_lattice(const FluidModelInput& in,
                       const Vec3d& offset = {0.5 * kDp, 0.5 * kDp, 0.5 * kDp}) {
  Block b;
  b.m = make_fluid_model(in);
  b.with_shifting = true;
  test::configure_grid(b, 0, kL, 0, 3, {true, true, true});
  test::for_each_site(3, kN, [&](int i, int j, int k) {
    b.p.add(Vec3d{i * kDp, j * kDp, k * kDp} + offset, {}, 1000, ParticleKind::Fluid);
  });
  return b;
}

TEST(PeriodicRates, UniformStateHasOnlyGravity) {
  // Uniform density above rho0 (pressure ~2 kPa, so every missing or doubled neighbour would
  // leave an unbalanced pressure force of tens of m/s^2) and uniform velocity.
  for (auto diffusion : {DensityDiffusion::Molteni, DensityDiffusion::Fourtakas}) {
    Block b = periodic_lattice(input(diffusion));
    for (std::size_t i = 0; i < b.p.size(); ++i)
      b.p.vel[i] = {0.3f, -0.1f, 0.2f}, b.p.rho[i] = 1005;
    b.compute();
    ASSERT_GT(b.m.eos.pressure(1005), 1000);
    const Real div0 = b.shifting.div_r[0];
    EXPECT_NEAR(div0, 3.0, 0.1);
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      EXPECT_NEAR(b.acc[i].x, 0.0, 2e-3) << i;
      EXPECT_NEAR(b.acc[i].y, 0.0, 2e-3) << i;
      EXPECT_NEAR(b.acc[i].z, -9.81, 2e-3) << i;
      EXPECT_NEAR(b.drho[i], 0.0, 1e-3) << i;
      // The same neighbourhood everywhere: same div(r), no concentration gradient.
      EXPECT_NEAR(b.shifting.div_r[i], div0, 1e-4) << i;
      EXPECT_LT(norm(b.shifting.grad_c[i]), 1e-3) << i;
    }
  }
}

TEST(PeriodicRates, UniformStateAcrossBoundaryAtCellFaces) {
  // The lattice shifted so that particles sit exactly on the period ends (x = 0) and cell
  // faces: the result must not depend on where the period starts.
  Block b = periodic_lattice(input(), {0.0, 0.25 * kDp, 0.0});
  for (std::size_t i = 0; i < b.p.size(); ++i) b.p.rho[i] = 1005;
  b.compute();
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    EXPECT_NEAR(b.acc[i].x, 0.0, 2e-3) << i;
    EXPECT_NEAR(b.acc[i].y, 0.0, 2e-3) << i;
    EXPECT_NEAR(b.acc[i].z, -9.81, 2e-3) << i;
    EXPECT_NEAR(b.drho[i], 0.0, 1e-3) << i;
  }
}

TEST(PeriodicRates, MomentumIsConservedAcrossThePeriodicBoundary) {
  for (auto visc : {ViscosityModel::Artificial, ViscosityModel::Laminar}) {
    FluidModelInput in = input();
    in.viscosity = visc;
    in.nu = 1e-3;
    // Lattice at 0.9 dp + perturbation: the last layer crosses hi and must be wrapped.
    Block b = periodic_lattice(in, {0.9 * kDp, 0.9 * kDp, 0.9 * kDp});
    test::perturb(b, 3, 0.3 * kDp);
    EXPECT_GT(b.grid.wrap(b.p.pos), 50u);
    b.compute();
    Vec3d total{}, scale{};
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      const Vec3d a = Vec3d(b.acc[i] - b.m.gravity) * static_cast<double>(b.m.mass);
      total += a;
      scale += Vec3d(std::fabs(a.x), std::fabs(a.y), std::fabs(a.z));
    }
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(scale[a], 0.0);
      EXPECT_LT(std::fabs(total[a]), 1e-5 * scale[a]) << "axis " << a;
    }
  }
}

TEST(PeriodicRates, SameAsTheMiddleOfATiledBlock) {
  // The periodic block against the same particles tiled 3 x 3 x 3 on a non-periodic grid:
  // the middle copy sees exactly the neighbours the periodic images provide.
  const FluidModelInput in = input();
  Block per = periodic_lattice(in, {0.9 * kDp, 0.4 * kDp, 0.7 * kDp});
  test::perturb(per, 9, 0.3 * kDp);
  per.grid.wrap(per.p.pos);

  Block tiled;
  tiled.m = make_fluid_model(in);
  tiled.with_shifting = true;
  test::configure_grid(tiled, -kL, 2 * kL, 4 * kDp);
  std::vector<std::uint32_t> middle_id(per.p.size());
  for (int tz = -1; tz <= 1; ++tz)
    for (int ty = -1; ty <= 1; ++ty)
      for (int tx = -1; tx <= 1; ++tx)
        for (std::size_t i = 0; i < per.p.size(); ++i) {
          const std::uint32_t id = tiled.p.add(per.p.pos[i] + Vec3d(tx * kL, ty * kL, tz * kL),
                                               per.p.vel[i], per.p.rho[i], ParticleKind::Fluid);
          if (tx == 0 && ty == 0 && tz == 0) middle_id[i] = id;
        }
  // Ids of the periodic block are 0..n-1 in creation order.
  per.compute();
  tiled.compute();

  std::vector<std::size_t> slot_of_id(tiled.p.size());
  for (std::size_t s = 0; s < tiled.p.size(); ++s) slot_of_id[tiled.p.id[s]] = s;
  double max_acc = 0;
  for (const auto& a : per.acc) max_acc = std::max(max_acc, static_cast<double>(norm(a)));
  double max_drho = 0;
  for (const auto d : per.drho) max_drho = std::max(max_drho, std::fabs(static_cast<double>(d)));
  ASSERT_GT(max_acc, 1.0);
  ASSERT_GT(max_drho, 1.0);
  for (std::size_t s = 0; s < per.p.size(); ++s) {
    const std::uint32_t orig = per.p.id[s];  // index in creation order
    const std::size_t t = slot_of_id[middle_id[orig]];
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(per.acc[s][a], tiled.acc[t][a], 1e-4 * max_acc) << "particle " << orig;
    EXPECT_NEAR(per.drho[s], tiled.drho[t], 1e-4 * max_drho) << "particle " << orig;
    EXPECT_NEAR(per.shifting.div_r[s], tiled.shifting.div_r[t], 1e-4) << "particle " << orig;
  }
}

}  // namespace
}  // namespace netsph
