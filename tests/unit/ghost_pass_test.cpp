// The CPU ghost-node pass (backend/cpu/ghost_pass.hpp) finds its neighbours with the vector
// candidate scan over the interaction view. Checked here against a brute-force sum over every
// particle (and every periodic image) with the shared ghost_accumulate: on a jittered block of
// fluid, buffer, wall and body particles, at points inside, on the faces, beyond the block
// and across a periodic axis, the pass must give the same sums (so the same neighbours), the
// same first-order flag and the same values; solids never count, buffers count only while
// their fluid flag is set (the open boundaries clear it), and a point outside the grid gets
// nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "netsph/backend/cpu/ghost_pass.hpp"
#include "particle_fixture.hpp"

namespace netsph {
namespace {

constexpr double kDp = 0.01;
constexpr int kN = 12;  // lattice sites per side
constexpr double kL = kN * kDp;

struct Block : test::ParticleBlock {
  bool periodic_x = false;
};

/// A jittered kN^3 lattice in [0, kL)^3 with random densities and velocities; one particle in
/// seven is a buffer particle, one in eleven a wall and one in thirteen a body particle.
Block block(bool periodic_x) {
  Block b;
  b.periodic_x = periodic_x;
  b.m = make_fluid_model(test::fluid_input(3, kDp, 10));
  test::configure_grid(b, 0, kL, 4 * kDp, 3, {periodic_x, false, false});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3 * kDp, 0.3 * kDp), u(-1, 1);
  int n = 0;
  test::for_each_site(3, kN, [&](int i, int j, int k) {
    Vec3d x = test::site_centre(i, j, k, kDp) + Vec3d{jitter(rng), jitter(rng), jitter(rng)};
    if (periodic_x) x.x = std::fmod(x.x + kL, kL);
    const ParticleKind kind = n % 13 == 0   ? ParticleKind::Body
                              : n % 11 == 0 ? ParticleKind::Wall
                              : n % 7 == 0  ? ParticleKind::Buffer
                                            : ParticleKind::Fluid;
    const Vec3f v(Vec3d{0.2 + 0.5 * x.z + 0.01 * u(rng), 0.1 * x.x, -0.05 + 0.02 * u(rng)});
    b.p.add(x, v, static_cast<Real>(1000 + 5 * u(rng)), kind);
    ++n;
  });
  b.sort_and_build_view();
  return b;
}

/// The sums at `point` over every particle whose view flag is set, periodic images included,
/// and the same sums of the terms' magnitudes (the scale of each sum's round-off).
struct Reference {
  GhostSums sums, magnitude;
};

Reference brute_force(const Block& b, const Vec3d& point) {
  Reference out;
  for (std::size_t j = 0; j < b.p.size(); ++j) {
    if (!(b.view.fluid[j] > 0)) continue;
    for (const int image : {-1, 0, 1}) {
      if (image != 0 && !b.periodic_x) continue;
      const Vec3d d = b.p.pos[j] + Vec3d{image * kL, 0, 0} - point;
      const double r = norm(d);
      if (!(r < b.m.support)) continue;
      const Real rf = static_cast<Real>(r);
      const Real w = kernel_value<WendlandC2>(b.m.kernel, rf);
      const Real f = kernel_grad_factor<WendlandC2>(b.m.kernel, rf);
      ghost_accumulate(out.sums, Vec3f(d), w, f, b.m.mass, b.p.rho[j], b.p.vel[j]);
      const GhostTerms t = ghost_terms(Vec3f(d), w, f, b.m.mass, b.p.rho[j], b.p.vel[j]);
      for (int row = 0; row < 4; ++row)
        for (int c = 0; c < 8; ++c) out.magnitude.s[row][c] += std::fabs(t.weight[row] * t.u[c]);
    }
  }
  return out;
}

void expect_same_sums(const GhostSums& a, const Reference& e, const Vec3d& at) {
  // Float offsets from the view against double ones here: each term differs by a few float
  // roundings, and sums of gradient terms cancel, so the bound is on the terms' magnitudes.
  // A point at the edge of the fluid sees its neighbours near the kernel's cut-off, where W
  // changes fastest with r: 1e-5 of the magnitudes. A missed or doubled neighbour (a range or
  // periodic image wrong) costs its whole share, about 1e-2.
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 8; ++c) {
      EXPECT_NEAR(a.s[r][c], e.sums.s[r][c], 1e-5 * e.magnitude.s[r][c] + 1e-12)
          << "row " << r << " column " << c << " at " << at.x << ", " << at.y << ", " << at.z;
    }
  }
}

std::vector<Vec3d> test_points(bool periodic_x) {
  std::vector<Vec3d> pts{{0.06, 0.06, 0.06},       {0.0431, 0.0712, 0.0291}, {0.06, 0.0, 0.06},
                         {0.06, 0.06, kL + 0.005}, {0.06, -0.015, 0.06},     {0.11, 0.11, 0.005}};
  if (periodic_x) {  // across the periodic seam, and outside the period (wrapped first)
    pts.push_back({0.002, 0.06, 0.06});
    pts.push_back({kL - 0.003, 0.05, 0.07});
    pts.push_back({kL + 0.004, 0.05, 0.07});
  }
  return pts;
}

GhostSums pass_sums(const Block& b, const Vec3d& x) {
  CellRangesMemo memo;
  return ghost_sums_at<WendlandC2>(b.m, b.grid, b.view, x, memo);
}

TEST(GhostPass, SumsEqualABruteForceSumOverTheFlaggedParticles) {
  for (const bool periodic : {false, true}) {
    const Block b = block(periodic);
    for (const Vec3d& x : test_points(periodic)) {
      const Reference e = brute_force(b, x);
      ASSERT_GT(e.sums.a(0, 0), 0.0) << "the test point sees no fluid";
      expect_same_sums(pass_sums(b, x), e, x);
    }
  }
}

TEST(GhostPass, OneMemoOverNodesInTheSameAndOtherCellsGivesEachItsOwnSums) {
  // Nodes close together (one cell, as the ghost nodes of neighbouring wall particles), then
  // elsewhere, then back, then across the periodic seam: the memo's ranges must be rebuilt
  // whenever the cell changes and only then be reused.
  const Block b = block(true);
  const std::vector<Vec3d> pts{{0.060, 0.060, 0.060},    {0.0605, 0.0601, 0.0598},
                               {0.0431, 0.0712, 0.0291}, {0.0602, 0.0603, 0.0601},
                               {0.002, 0.06, 0.06},      {kL + 0.004, 0.05, 0.07},
                               {kL - 0.003, 0.05, 0.07}};
  CellRangesMemo memo;
  for (const Vec3d& x : pts)
    expect_same_sums(ghost_sums_at<WendlandC2>(b.m, b.grid, b.view, x, memo), brute_force(b, x), x);
}

TEST(GhostPass, ValuesAndFirstOrderFlagMatchTheBruteForceSolve) {
  const Block b = block(true);
  const std::vector<Vec3d> pts = test_points(true);
  std::vector<GhostValue> got(pts.size());
  for_each_ghost_value(b.m, b.grid, b.view, pts,
                       [&](std::size_t k, const GhostValue& g) { got[k] = g; });
  int first_order = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const GhostValue e = ghost_solve(brute_force(b, pts[k]).sums, 3);
    EXPECT_EQ(got[k].any, e.any);
    EXPECT_EQ(got[k].first_order, e.first_order) << k;
    EXPECT_NEAR(got[k].rho, e.rho, 1e-3) << k;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[k].vel[c], e.vel[c], 1e-5) << k;
    first_order += e.first_order ? 1 : 0;
  }
  EXPECT_GE(first_order, 5);  // the interior points: the test covers the first-order solve
}

TEST(GhostPass, ClearedFlagsAndSolidsAreNotSources) {
  Block b = block(false);
  const Vec3d x{0.06, 0.06, 0.06};
  const GhostSums with_buffer = pass_sums(b, x);
  // The open boundaries' rule: buffer particles out while their own ghost nodes sum.
  for (std::size_t j = 0; j < b.p.size(); ++j)
    if (b.p.kind[j] == ParticleKind::Buffer) b.view.fluid[j] = 0;
  const GhostSums fluid_only = pass_sums(b, x);
  expect_same_sums(fluid_only, brute_force(b, x), x);
  EXPECT_LT(fluid_only.a(0, 0), 0.95 * with_buffer.a(0, 0));
  // The view's flags were built from the kinds: walls and bodies never had one.
  for (std::size_t j = 0; j < b.p.size(); ++j) {
    if (is_solid(b.p.kind[j])) {
      EXPECT_EQ(b.view.fluid[j], 0);
    }
  }
}

TEST(GhostPass, NothingOutsideTheGrid) {
  const Block b = block(false);
  const GhostSums s = pass_sums(b, {1.0, 0.06, 0.06});
  EXPECT_FALSE(ghost_solve(s, 3).any);
}

}  // namespace
}  // namespace netsph
