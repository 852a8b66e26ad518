// Body shapes and their particles (geometry/shapes, geometry/body_particles): volumes, surface
// distances, and particle layouts whose effective surface (dp/2 beyond the outer layer) is
// the shape's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "netsph/core/real.hpp"
#include "netsph/geometry/body_particles.hpp"
#include "netsph/geometry/shapes.hpp"

namespace netsph {
namespace {

const std::vector<Vec3d> kPlaneXZ{{1, 0, 0}, {0, 0, 1}};

double min_spacing(const std::vector<Vec3d>& pts) {
  double best = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) best = std::min(best, norm(pts[i] - pts[j]));
  return best;
}

/// Depths of the points below the surface: min and max.
std::pair<double, double> depth_range(const Shape& s, const std::vector<Vec3d>& pts) {
  double lo = 1e300, hi = 0;
  for (const Vec3d& p : pts) {
    EXPECT_TRUE(s.inside(p)) << p.x << " " << p.y << " " << p.z;
    lo = std::min(lo, s.depth(p));
    hi = std::max(hi, s.depth(p));
  }
  return {lo, hi};
}

TEST(Shapes, MeasuresAgainstClosedForms) {
  EXPECT_NEAR(Shape::box({1, 2, 3}).measure(3), 6.0, 1e-12);
  EXPECT_NEAR(Shape::sphere(2).measure(3), 4.0 / 3.0 * kPi, 1e-12);
  EXPECT_NEAR(Shape::sphere(2).measure(2), kPi, 1e-12);
  EXPECT_NEAR(Shape::cylinder(2, 3).measure(3), 3 * kPi, 1e-12);
  // Two crossed cylinders: 2 pi r^2 L minus the Steinmetz solid 16 r^3 / 3.
  EXPECT_NEAR(Shape::cruciform(1, 0.1).measure(3), 2 * kPi * 0.0025 - 16.0 / 3.0 * 1.25e-4, 1e-12);
}

TEST(Shapes, NearestSurfacePointOfCylinderMantleAndCap) {
  const Shape c = Shape::cylinder(0.2, 1.0);  // radius 0.1, caps at x = +-0.5
  const Vec3d on_mantle = c.nearest_surface_point({0.1, 0.03, 0.04});
  EXPECT_NEAR(std::hypot(on_mantle.y, on_mantle.z), 0.1, 1e-12);
  EXPECT_NEAR(on_mantle.x, 0.1, 1e-12);
  const Vec3d on_cap = c.nearest_surface_point({0.48, 0.0, 0.01});
  EXPECT_NEAR(on_cap.x, 0.5, 1e-12);
}

TEST(BodyParticles, CylinderInThePlaneIsBodyFittedRings) {
  // DFG: D = 0.1 m at dp = D / 20, axis normal to the x-z plane (local x = world y).
  const double dp = 0.005;
  const Shape c = Shape::cylinder(0.1, 0.1);
  const std::vector<Vec3d> plane{{0, 1, 0}, {0, 0, 1}};  // world x, z seen in the local frame
  const auto pts = body_particles(c, dp, 0, 2, plane);
  const auto [lo, hi] = depth_range(c, pts);
  // The outer ring lies exactly dp/2 deep all round: the effective radius is the true one
  // (a lattice loses up to dp).
  EXPECT_NEAR(lo, 0.5 * dp, 1e-12);
  // Solid: one particle per dp^2 of the disc, within 3%.
  EXPECT_NEAR(static_cast<double>(pts.size()) * dp * dp / (kPi * 0.05 * 0.05), 1.0, 0.03);
  // Every point in the plane (local x is out of it), spacing near dp.
  for (const Vec3d& p : pts) EXPECT_NEAR(p.x, 0.0, 1e-15);
  EXPECT_GT(min_spacing(pts), 0.75 * dp);
  // The outer ring alone: round(2 pi r / dp) points with arc spacing within 1% of dp.
  std::size_t outer = 0;
  for (const Vec3d& p : pts)
    if (c.depth(p) < 0.6 * dp) ++outer;
  EXPECT_EQ(outer, static_cast<std::size_t>(std::lround(2 * kPi * 0.0475 / dp)));
  (void)hi;
}

TEST(BodyParticles, ShellKeepsOnlyTheLayersTheKernelReaches) {
  const double dp = 0.005;
  const Shape c = Shape::cylinder(0.1, 0.1);
  const std::vector<Vec3d> plane{{0, 1, 0}, {0, 0, 1}};
  const auto pts = body_particles(c, dp, 3, 2, plane);
  const auto [lo, hi] = depth_range(c, pts);
  EXPECT_NEAR(lo, 0.5 * dp, 1e-12);
  EXPECT_NEAR(hi, 2.5 * dp, 1e-12);
}

TEST(BodyParticles, CylinderAlongThePlaneIsARectangleOnTheLattice) {
  const double dp = 0.01;
  const Shape c = Shape::cylinder(0.1, 0.3);  // axis local x = world x: section 0.3 x 0.1
  const auto pts = body_particles(c, dp, 0, 2, kPlaneXZ);
  EXPECT_EQ(pts.size(), 30u * 10u);
  const auto [lo, hi] = depth_range(c, pts);
  EXPECT_NEAR(lo, 0.5 * dp, 1e-9);
  (void)hi;
}

TEST(BodyParticles, SphereShellsIn3D) {
  const double dp = 0.01;
  const Shape s = Shape::sphere(0.2);
  const auto pts = body_particles(s, dp, 0, 3, {});
  const auto [lo, hi] = depth_range(s, pts);
  EXPECT_NEAR(lo, 0.5 * dp, 1e-12);
  EXPECT_NEAR(static_cast<double>(pts.size()) * dp * dp * dp / s.measure(3), 1.0, 0.05);
  EXPECT_GT(min_spacing(pts), 0.6 * dp);
  (void)hi;
}

TEST(BodyParticles, ThinDiscHasTwoFullLayersAtHalfDpFromItsFaces) {
  // A circular plate of thickness 2 dp, as a net knot: two layers, each a full disc.
  const double dp = 0.005;
  const Shape disc = Shape::cylinder(0.05, 2 * dp);
  const auto pts = body_particles(disc, dp, 3, 3, {});
  std::size_t front = 0, back = 0;
  for (const Vec3d& p : pts) {
    EXPECT_NEAR(std::fabs(p.x), 0.5 * dp, 1e-12);
    (p.x > 0 ? front : back)++;
  }
  EXPECT_EQ(front, back);
  EXPECT_NEAR(static_cast<double>(front) * dp * dp / (kPi * 0.025 * 0.025), 1.0, 0.05);
}

TEST(BodyParticles, Cylinder3DShellIsHollowButCapsAreFull) {
  const double dp = 0.01;
  const Shape c = Shape::cylinder(0.2, 0.4);  // radius 10 dp, length 40 dp
  const auto pts = body_particles(c, dp, 3, 3, {});
  const auto [lo, hi] = depth_range(c, pts);
  EXPECT_NEAR(lo, 0.5 * dp, 1e-12);
  EXPECT_LE(hi, 3 * dp + 1e-12);
  bool centre_mid = false, centre_cap = false;
  for (const Vec3d& p : pts) {
    if (std::hypot(p.y, p.z) < 0.6 * dp && std::fabs(p.x) < 0.1) centre_mid = true;
    if (std::hypot(p.y, p.z) < 0.6 * dp && std::fabs(p.x) > 0.19) centre_cap = true;
  }
  EXPECT_FALSE(centre_mid);
  EXPECT_TRUE(centre_cap);
}

TEST(BodyParticles, BoxOfWholeDpHoldsExactLayers) {
  const double dp = 0.01;
  const Shape b = Shape::box({0.1, 0.02, 0.06});
  const auto pts = body_particles(b, dp, 0, 3, {});
  EXPECT_EQ(pts.size(), 10u * 2u * 6u);
  const auto [lo, hi] = depth_range(b, pts);
  EXPECT_NEAR(lo, 0.5 * dp, 1e-9);
  (void)hi;
}

TEST(BodyParticles, PlateThinnerThanTwoDpStillGetsTheNearestLayerCount) {
  // Table 1's square plate at the reduced dp = 0.025 m: 3.927 cm thick (1.57 dp), 19.365 cm
  // wide (7.75 dp): 2 x 8 x 8 particles.
  const double dp = 0.025;
  const Shape plate = Shape::box({0.03927, 0.19365, 0.19365});
  const auto pts = body_particles(plate, dp, 3, 3, {});
  EXPECT_EQ(pts.size(), 2u * 8u * 8u);
  for (const Vec3d& p : pts) EXPECT_NEAR(std::fabs(p.x), 0.5 * dp, 1e-12);
}

TEST(BodyParticles, CruciformOfTwoDpTwinesHasParticlesInEveryArm) {
  const double dp = 0.025;
  const Shape c = Shape::cruciform(0.4, 0.05);  // twine diameter 2 dp
  const auto pts = body_particles(c, dp, 3, 3, {});
  std::size_t y_arm = 0, z_arm = 0;
  for (const Vec3d& p : pts) {
    EXPECT_TRUE(c.inside(p));
    if (std::fabs(p.y) > 0.1) ++y_arm;
    if (std::fabs(p.z) > 0.1) ++z_arm;
  }
  EXPECT_GT(y_arm, 0u);
  EXPECT_EQ(y_arm, z_arm);
}

}  // namespace
}  // namespace netsph
