// Shepard-corrected probe sampling (sph/shepard.hpp, backend/cpu/probe_pass.hpp) on a block of
// lattice particles: a uniform field is reproduced exactly everywhere the point sees fluid,
// also at the block's edge where the kernel is cut (that is what the Shepard division is
// for); a linear field is reproduced inside the block (the lattice is symmetric about the
// point) and biased towards the interior at the edge; the coverage is 1 inside, about 1/2 on
// a flat face, 0 beyond the kernel's reach; walls and bodies are never sampled; a periodic
// axis wraps the probe point. The point loads (sph/fluid_point_loads.hpp) spread a force over
// the same kernel weights the other way: the particles around the point take all of it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "netsph/backend/cpu/probe_pass.hpp"
#include "netsph/sph/fluid_point_loads.hpp"
#include "particle_fixture.hpp"

namespace netsph {
namespace {

constexpr double kDp = 0.01;
constexpr int kN = 12;  // lattice particles per side
constexpr double kL = kN * kDp;

struct Block : test::ParticleBlock {
  ShepardValue at(const Vec3d& x) const {
    std::vector<Vec3d> points{x};
    std::vector<ShepardValue> values(1);
    sample_points(m, grid, p, points, values);
    return values[0];
  }
};

/// A kN^3 lattice in [0, kL)^3 (particle centres at (i + 1/2) dp), in a grid with room around
/// it; velocity v(x), density 1002.
template <class Velocity>
Block lattice(Velocity velocity, std::array<bool, 3> periodic = {}) {
  Block b;
  FluidModelInput in = test::fluid_input(3, kDp, 10);
  in.p_background = 100;
  b.m = make_fluid_model(in);
  test::configure_grid(b, 0, kL, 4 * kDp, 3, periodic);
  test::for_each_site(3, kN, [&](int i, int j, int k) {
    const Vec3d x = test::site_centre(i, j, k, kDp);
    b.p.add(x, Vec3f(velocity(x)), 1002, ParticleKind::Fluid);
  });
  b.sort();
  return b;
}

const Vec3d kUniform{0.226, -0.05, 0.01};

TEST(ProbeSampling, UniformFieldIsExactWhereverFluidIsInReach) {
  Block b = lattice([](const Vec3d&) { return kUniform; });
  const double gauge = b.m.eos.pressure(1002) - b.m.eos.p_background;
  // Inside, on a face, at an edge and a corner of the block, and between particles.
  for (const Vec3d x : {Vec3d{0.06, 0.06, 0.06}, Vec3d{0.0, 0.06, 0.06}, Vec3d{0.0, 0.0, 0.06},
                        Vec3d{0.0, 0.0, 0.0}, Vec3d{0.0433, 0.0712, 0.0291}}) {
    const ShepardValue v = b.at(x);
    ASSERT_GT(v.coverage, 0.0);
    EXPECT_NEAR(v.velocity.x, kUniform.x, 1e-6);
    EXPECT_NEAR(v.velocity.y, kUniform.y, 1e-6);
    EXPECT_NEAR(v.velocity.z, kUniform.z, 1e-6);
    EXPECT_NEAR(v.density, 1002, 1e-3);
    EXPECT_NEAR(v.pressure, gauge, 1e-3 * gauge);  // gauge: the background removed
  }
}

TEST(ProbeSampling, CoverageIsOneInsideHalfOnAFaceZeroOutOfReach) {
  Block b = lattice([](const Vec3d&) { return kUniform; });
  EXPECT_NEAR(b.at({0.06, 0.06, 0.06}).coverage, 1.0, 0.02);
  EXPECT_NEAR(b.at({0.0, 0.06, 0.06}).coverage, 0.5, 0.03);  // the face (the last layer + dp/2)
  const ShepardValue out = b.at({-0.035, 0.06, 0.06});       // 3.5 dp out: beyond 2h = 3 dp
  EXPECT_EQ(out.coverage, 0.0);
  EXPECT_EQ(out.velocity.x, 0.0);
  EXPECT_EQ(b.at({-1.0, 0.0, 0.0}).coverage, 0.0);  // outside the grid
}

TEST(ProbeSampling, LinearFieldInsideTheFluid) {
  const Vec3d g{2.0, -1.0, 0.5};
  const auto u = [&](const Vec3d& x) { return Vec3d{0.2 + dot(g, x), 0, 0}; };
  Block b = lattice(u);
  for (const Vec3d x : {Vec3d{0.06, 0.06, 0.06}, Vec3d{0.05, 0.065, 0.07}}) {
    EXPECT_NEAR(b.at(x).velocity.x, u(x).x, 1e-5);
  }
  // At a face the sum only sees the interior side: zeroth order leans towards the interior.
  const Vec3d face{0.0, 0.06, 0.06};
  const double biased = b.at(face).velocity.x;
  EXPECT_GT(biased, u(face).x + 0.1 * g.x * kDp);
}

TEST(ProbeSampling, SolidsAreNotSampled) {
  Block b = lattice([](const Vec3d&) { return kUniform; });
  // A wall layer just outside the x = 0 face moving at another velocity.
  for (int k = 0; k < kN; ++k)
    for (int j = 0; j < kN; ++j)
      b.p.add({-0.5 * kDp, (j + 0.5) * kDp, (k + 0.5) * kDp}, {5.0f, 5.0f, 5.0f}, 1200,
              ParticleKind::Wall);
  b.sort();
  const ShepardValue v = b.at({0.0, 0.06, 0.06});
  EXPECT_NEAR(v.velocity.x, kUniform.x, 1e-6);
  EXPECT_NEAR(v.coverage, 0.5, 0.03);
}

TEST(ProbeSampling, PeriodicAxisWrapsThePoint) {
  Block b = lattice([](const Vec3d& x) { return Vec3d{x.x, 0, 0}; }, {true, false, false});
  // x = 0 lies between the last and the first layer: the images make the field symmetric
  // there, and x + L is the same point.
  const ShepardValue v0 = b.at({0.0, 0.06, 0.06}), v1 = b.at({kL, 0.06, 0.06});
  EXPECT_NEAR(v0.coverage, 1.0, 0.02);
  EXPECT_NEAR(v0.velocity.x, v1.velocity.x, 1e-9);
  EXPECT_NEAR(v0.velocity.x, 0.5 * kL, 1e-4);  // halfway between 0 and L by symmetry
}

/// The force the fluid particles of `b` take from `loads`: sum_i m a_i.
Vec3d force_taken(const Block& b, const FluidPointLoadSet& set) {
  Vec3d f{};
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const Vec3f a = point_loads_acceleration<WendlandC2>(set, b.m.kernel, b.m.support2,
                                                         b.grid.period(), b.p.pos[i]);
    f += Vec3d(a) * static_cast<double>(b.m.mass);
  }
  return f;
}

TEST(PointLoads, TheFluidAroundThePointTakesTheWholeForce) {
  // Uneven densities (the mass weight is sum m W, not rho0 sum V W); points inside, on a face
  // (half the kernel in the fluid), across the periodic ends and two overlapping ones.
  Block b = lattice([](const Vec3d&) { return kUniform; }, {true, false, false});
  for (std::size_t i = 0; i < b.p.size(); ++i)
    b.p.rho[i] = static_cast<Real>(1000 + 5 * std::sin(37.0 * static_cast<double>(i)));
  const std::vector<Vec3d> points = {
      {0.06, 0.06, 0.06}, {0.05, 0.0, 0.07}, {0.002, 0.06, 0.03}, {0.061, 0.062, 0.063}};
  const std::vector<Vec3d> forces = {
      {0.01, 0, 0}, {0, -0.02, 0.005}, {0.003, 0.004, -0.001}, {-0.007, 0, 0}};
  std::vector<ShepardValue> values(points.size());
  sample_points(b.m, b.grid, b.p, points, values);
  std::vector<FluidPointLoad> loads;
  for (std::size_t s = 0; s < points.size(); ++s) {
    ASSERT_GT(values[s].coverage, 0.4) << s;
    // sum V W rho = sum m W, the mass weight.
    loads.push_back({points[s], forces[s] / (values[s].coverage * values[s].density)});
    const FluidPointLoadSet one = point_load_set(&loads.back(), 1, b.m.support);
    const Vec3d taken = force_taken(b, one);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(taken[a], forces[s][a], 2e-6 * norm(forces[s])) << s;
  }
  const FluidPointLoadSet all = point_load_set(loads.data(), 4, b.m.support);
  Vec3d total{};
  for (const Vec3d& f : forces) total += f;
  const Vec3d taken = force_taken(b, all);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(taken[a], total[a], 1e-7);
  // Beyond the kernel's reach nothing: the box test and the support agree.
  const FluidPointLoad far{{0.5, 0.5, 0.5}, {1, 1, 1}};
  const FluidPointLoadSet far_set = point_load_set(&far, 1, b.m.support);
  EXPECT_EQ(norm(force_taken(b, far_set)), 0.0);
  // The box only skips particles that take nothing: an unbounded box gives the same.
  FluidPointLoadSet unbounded = all;
  unbounded.reach = {1e9, 1e9, 1e9};
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    const Vec3f a0 = point_loads_acceleration<WendlandC2>(all, b.m.kernel, b.m.support2,
                                                          b.grid.period(), b.p.pos[i]);
    const Vec3f a1 = point_loads_acceleration<WendlandC2>(unbounded, b.m.kernel, b.m.support2,
                                                          b.grid.period(), b.p.pos[i]);
    ASSERT_EQ(a0.x, a1.x) << i;
    ASSERT_EQ(a0.y, a1.y) << i;
    ASSERT_EQ(a0.z, a1.z) << i;
  }
}

}  // namespace
}  // namespace netsph
