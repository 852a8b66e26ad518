// First-order consistent interpolation at ghost nodes (sph/ghost_interpolation.hpp): linear
// density and velocity fields are reproduced with their gradients, also near the edge of the
// particles where the Shepard (zeroth-order) value is biased; a singular matrix falls back to
// the Shepard value; no neighbours means no value.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph {
namespace {

constexpr double kDp = 0.01;
constexpr double kRho0 = 1000;

/// A linear field f(r) = f0 + g . r.
struct Linear {
  double f0;
  Vec3d g;
  double operator()(const Vec3d& r) const { return f0 + dot(g, r); }
};

// Density and velocity components, all linear in position (strong gradients so that the
// float inputs of ghost_accumulate do not hide them).
const Linear kRho{kRho0, {300.0, -150.0, -200.0}};
const Linear kVel[3] = {{0.3, {2.0, -1.0, 0.5}}, {-0.1, {0.7, 1.5, -2.5}}, {0.2, {-1.2, 0.4, 3.0}}};

struct Particle {
  Vec3d r;
  double rho;
  Vec3d v;
};

/// A block of n^dims lattice particles at i dp, carrying the linear fields.
std::vector<Particle> lattice(int dims, int n) {
  std::vector<Particle> out;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < (dims == 3 ? n : 1); ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3d r{i * kDp, dims == 3 ? j * kDp : 0.0, k * kDp};
        out.push_back({r, kRho(r), {kVel[0](r), kVel[1](r), kVel[2](r)}});
      }
  return out;
}

struct Ghost {
  GhostSums sums;
  int neighbours = 0;
  double shepard_rho = 0;  ///< sum V W rho / sum V W, computed here independently
  Vec3d shepard_vel{};
};

/// Accumulates the particles within the Wendland support around the ghost point rg.
Ghost accumulate(int dims, const std::vector<Particle>& ps, const Vec3d& rg) {
  const double h = 1.5 * kDp;
  const KernelScale ks = make_kernel_scale<WendlandC2>(dims, h);
  const Real mass = static_cast<Real>(kRho0 * std::pow(kDp, dims));
  Ghost g;
  double sw = 0, swr = 0;
  Vec3d swv{};
  for (const Particle& p : ps) {
    const Vec3d d = p.r - rg;  // d = r_j - r_g
    const double r = norm(d);
    if (r >= 2 * h) continue;
    const Real w = kernel_value<WendlandC2>(ks, static_cast<Real>(r));
    const Real f = kernel_grad_factor<WendlandC2>(ks, static_cast<Real>(r));
    ghost_accumulate(g.sums, Vec3f(d), w, f, mass, static_cast<Real>(p.rho), Vec3f(p.v));
    ++g.neighbours;
    const double vw = static_cast<double>(mass) / static_cast<double>(static_cast<Real>(p.rho)) *
                      static_cast<double>(w);
    sw += vw, swr += vw * static_cast<double>(static_cast<Real>(p.rho));
    swv += Vec3d(Vec3f(p.v)) * vw;
  }
  if (sw > 0) g.shepard_rho = swr / sw, g.shepard_vel = swv / sw;
  return g;
}

/// Checks the first-order solution against the linear fields at rg.
void expect_exact(const GhostValue& v, int dims, const Vec3d& rg, const char* what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(v.any);
  ASSERT_TRUE(v.first_order);
  auto project = [&](const Vec3d& g) { return dims == 2 ? Vec3d(g.x, 0, g.z) : g; };
  const Vec3d grho = project(kRho.g);
  EXPECT_NEAR(v.rho, kRho(rg), 1e-4 * kRho0 * 1e-3);  // 1e-7 relative to the density
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.grad_rho[a], grho[a], 1e-4 * norm(grho)) << a;
  for (int c = 0; c < 3; ++c) {
    const Vec3d gv = project(kVel[c].g);
    EXPECT_NEAR(v.vel[c], kVel[c](rg), 1e-4 * (std::fabs(kVel[c](rg)) + norm(gv) * kDp)) << c;
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(v.grad_vel[c][a], gv[a], 1e-4 * norm(gv)) << "component " << c << " axis " << a;
  }
}

TEST(GhostInterpolation, LinearFieldsAreReproducedInside2D) {
  const auto ps = lattice(2, 20);
  for (const Vec3d rg : {Vec3d{0.1, 0, 0.1}, Vec3d{0.0937, 0, 0.1142}, Vec3d{0.121, 0, 0.077}}) {
    const Ghost g = accumulate(2, ps, rg);
    EXPECT_GT(g.neighbours, 20);
    expect_exact(ghost_solve(g.sums, 2), 2, rg, "interior");
  }
}

TEST(GhostInterpolation, LinearFieldsAreReproducedInside3D) {
  const auto ps = lattice(3, 10);
  for (const Vec3d rg : {Vec3d{0.045, 0.05, 0.04}, Vec3d{0.0437, 0.0521, 0.0466}}) {
    const Ghost g = accumulate(3, ps, rg);
    EXPECT_GT(g.neighbours, 80);
    expect_exact(ghost_solve(g.sums, 3), 3, rg, "interior");
  }
}

TEST(GhostInterpolation, FirstOrderCorrectsShepardBiasNearTheEdge2D) {
  // Ghost nodes half a spacing inside the block's corner, and just outside its bottom face:
  // the kernel is truncated, Shepard is biased by grad(f) . (its centroid offset), the
  // first-order solution is not.
  const auto ps = lattice(2, 20);
  for (const Vec3d rg : {Vec3d{0.005, 0, 0.186}, Vec3d{0.1, 0, -0.004}, Vec3d{0.0943, 0, 0.003}}) {
    const Ghost g = accumulate(2, ps, rg);
    const GhostValue v = ghost_solve(g.sums, 2);
    expect_exact(v, 2, rg, "edge");
    // Shepard (what the fallback would give) is off by a visible fraction of grad(rho) dp.
    EXPECT_GT(std::fabs(g.shepard_rho - kRho(rg)), 0.05);
    EXPECT_LT(std::fabs(v.rho - kRho(rg)), 1e-3 * std::fabs(g.shepard_rho - kRho(rg)));
  }
}

TEST(GhostInterpolation, FirstOrderCorrectsShepardBiasNearTheEdge3D) {
  const auto ps = lattice(3, 10);
  for (const Vec3d rg : {Vec3d{0.004, 0.045, 0.005}, Vec3d{0.045, 0.05, -0.003}}) {
    const Ghost g = accumulate(3, ps, rg);
    const GhostValue v = ghost_solve(g.sums, 3);
    expect_exact(v, 3, rg, "edge");
    EXPECT_GT(std::fabs(g.shepard_rho - kRho(rg)), 0.05);
    EXPECT_LT(std::fabs(v.rho - kRho(rg)), 1e-3 * std::fabs(g.shepard_rho - kRho(rg)));
  }
}

TEST(GhostInterpolation, ShepardValueWhenTheLimitIsNotMet) {
  // The same sums with an unreachable det limit: the zeroth-order (Shepard) values.
  for (int dims : {2, 3}) {
    const auto ps = lattice(dims, dims == 2 ? 20 : 10);
    const Vec3d rg = dims == 2 ? Vec3d{0.005, 0, 0.004} : Vec3d{0.004, 0.045, 0.005};
    const Ghost g = accumulate(dims, ps, rg);
    const GhostValue v = ghost_solve(g.sums, dims, 1e30);
    EXPECT_TRUE(v.any);
    EXPECT_FALSE(v.first_order);
    EXPECT_NEAR(v.rho, g.shepard_rho, 1e-9 * kRho0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v.vel[c], g.shepard_vel[c], 1e-9);
    EXPECT_TRUE(v.grad_rho == Vec3d{});
  }
}

TEST(GhostInterpolation, SingleNeighbourFallsBackToShepard) {
  // One neighbour: every row of the matrix is a multiple of (1, d), det = 0. Shepard with one
  // particle is that particle's value.
  for (int dims : {2, 3}) {
    const Vec3d r{0.012, dims == 3 ? -0.004 : 0.0, 0.007};
    const std::vector<Particle> ps = {{r, 1003.5, {0.4, -0.2, 0.1}}};
    const Ghost g = accumulate(dims, ps, {0, 0, 0});
    ASSERT_EQ(g.neighbours, 1);
    const GhostValue v = ghost_solve(g.sums, dims);
    EXPECT_TRUE(v.any);
    EXPECT_FALSE(v.first_order);
    EXPECT_NEAR(v.rho, 1003.5, 1e-9 * kRho0);
    EXPECT_NEAR(v.vel.x, 0.4, 1e-7);
    EXPECT_NEAR(v.vel.y, -0.2, 1e-7);
    EXPECT_NEAR(v.vel.z, 0.1, 1e-7);
    EXPECT_TRUE(v.grad_rho == Vec3d{});
  }
}

TEST(GhostInterpolation, ParticlesOnALineFallBackToShepard) {
  // 2D: a row of particles along x (no z extent) cannot give d/dz. 3D: a plane z = const
  // cannot either.
  for (int dims : {2, 3}) {
    std::vector<Particle> ps;
    for (int i = -4; i <= 4; ++i)
      for (int j = (dims == 3 ? -4 : 0); j <= (dims == 3 ? 4 : 0); ++j) {
        const Vec3d r{i * kDp, j * kDp, 0.0};
        ps.push_back({r, kRho(r), {kVel[0](r), kVel[1](r), kVel[2](r)}});
      }
    const Vec3d rg{0.0033, dims == 3 ? 0.0021 : 0.0, 0.006};
    const Ghost g = accumulate(dims, ps, rg);
    ASSERT_GT(g.neighbours, 3);
    const GhostValue v = ghost_solve(g.sums, dims);
    EXPECT_TRUE(v.any) << dims;
    EXPECT_FALSE(v.first_order) << dims;
    EXPECT_NEAR(v.rho, g.shepard_rho, 1e-9 * kRho0) << dims;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v.vel[c], g.shepard_vel[c], 1e-9) << dims;
  }
}

TEST(GhostInterpolation, NoNeighboursGivesNothing) {
  const GhostSums empty;
  for (int dims : {2, 3}) {
    const GhostValue v = ghost_solve(empty, dims);
    EXPECT_FALSE(v.any);
    EXPECT_FALSE(v.first_order);
  }
  // Particles beyond the support contribute W = 0: still nothing.
  const auto ps = lattice(2, 5);
  const Ghost g = accumulate(2, ps, {1.0, 0, 1.0});
  EXPECT_EQ(g.neighbours, 0);
  EXPECT_FALSE(ghost_solve(g.sums, 2).any);
}

TEST(GhostInterpolation, TheMatrixIsAboutDiagInsideTheFluid) {
  // Inside a full lattice sum V W ~ 1 and sum V F d d^T ~ -I (both are partitions of unity
  // of the kernel), so |det| ~ 1 and the 1e-3 limit is far away.
  const auto ps = lattice(2, 20);
  const Ghost g = accumulate(2, ps, {0.1, 0, 0.1});
  EXPECT_NEAR(g.sums.a(0, 0), 1.0, 0.02);
  EXPECT_NEAR(g.sums.a(1, 1), -1.0, 0.02);
  EXPECT_NEAR(g.sums.a(3, 3), -1.0, 0.02);
  // Off-diagonal terms only from the volumes m / rho_j, which vary by ~1% over the support.
  EXPECT_NEAR(g.sums.a(1, 3), 0.0, 1e-3);
  EXPECT_NEAR(g.sums.a(0, 1), 0.0, 1e-3);
  EXPECT_TRUE(ghost_solve(g.sums, 2, 0.5).first_order);
}

}  // namespace
}  // namespace netsph
