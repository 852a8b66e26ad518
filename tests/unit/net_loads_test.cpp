// Current loads on standalone nets: the screen-model coefficients against values computed
// independently from Cheng et al.'s code (../shared/notes/net-models.md, section 3.1, for a
// Patursson-type net: d = 2.8 mm, l = 29 mm, Sn = 0.1838, nu = 1.004e-6), and the Morison
// drag of a single twine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "net_test_specs.hpp"
#include "netsph/net/current_loads.hpp"
#include "netsph/net/equivalent_knot.hpp"
#include "netsph/net/net_generator.hpp"
#include "netsph/net/screen_model.hpp"

namespace netsph {
namespace {

const double kCos45 = std::cos(std::numbers::pi / 4);

double reynolds(double u) {
  const double sn = netting_solidity(0.029, 0.0028);
  return u * 0.0028 / (1.004e-6 * (1 - sn));
}

TEST(ScreenModel, MatchesTheReferenceTable) {
  const double sn = netting_solidity(0.029, 0.0028);
  EXPECT_NEAR(sn, 0.1838, 1e-4);
  EXPECT_NEAR(reynolds(0.125), 427, 1);
  using S = ScreenCoefficients;
  // U = 0.125 m/s
  EXPECT_NEAR(screen_coefficients_at_cos(S::S1Aarsnes, sn, 1, reynolds(0.125)).drag, 0.227, 0.001);
  EXPECT_NEAR(screen_coefficients_at_cos(S::S2Loland, sn, 1, reynolds(0.125)).drag, 0.251, 0.001);
  EXPECT_NEAR(screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, 1, reynolds(0.125)).drag,
              0.297, 0.001);
  const auto s1 = screen_coefficients_at_cos(S::S1Aarsnes, sn, kCos45, reynolds(0.125));
  EXPECT_NEAR(s1.drag, 0.172, 0.001);
  EXPECT_NEAR(s1.lift, 0.048, 0.001);
  const auto s2 = screen_coefficients_at_cos(S::S2Loland, sn, kCos45, reynolds(0.125));
  EXPECT_NEAR(s2.drag, 0.189, 0.001);
  EXPECT_NEAR(s2.lift, 0.058, 0.001);
  const auto s3 =
      screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, kCos45, reynolds(0.125));
  EXPECT_NEAR(s3.drag, 0.168, 0.001);
  EXPECT_NEAR(s3.lift, 0.061, 0.001);
  // U = 0.25, 0.5, 0.75 m/s at normal incidence, and 0.5 at 45 degrees (S3)
  EXPECT_NEAR(screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, 1, reynolds(0.25)).drag,
              0.259, 0.001);
  EXPECT_NEAR(screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, 1, reynolds(0.5)).drag,
              0.238, 0.001);
  EXPECT_NEAR(screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, 1, reynolds(0.75)).drag,
              0.240, 0.001);
  const auto s3_05 =
      screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, kCos45, reynolds(0.5));
  EXPECT_NEAR(s3_05.drag, 0.134, 0.001);
  EXPECT_NEAR(s3_05.lift, 0.048, 0.001);
}

// The coefficients come from cos(theta) through trigonometric identities; here each set's
// published form in theta, written with the trigonometric functions, at angles where every
// multiple-angle term is non-zero and differs from its neighbours.
TEST(ScreenModel, CosineFormIsThePublishedFormInTheta) {
  const double sn = netting_solidity(0.029, 0.0028), re = reynolds(0.3);
  const double cd_cyl = cylinder_drag_coefficient(re), open = 1 - sn;
  const double cd0 = cd_cyl * sn * (2 - sn) / (2 * open * open);
  const double cn45 = 0.5 * cd_cyl * sn / (open * open);
  const double cl45 = (0.5 * cd0 - std::numbers::pi * cn45 / (8 + cn45)) / std::numbers::sqrt2;
  using S = ScreenCoefficients;
  for (double deg : {0.0, 7.0, 20.0, 33.0, 45.0, 58.0, 71.0, 84.0, 90.0}) {
    const double t = deg * std::numbers::pi / 180, c = std::cos(t);
    const auto s1 = screen_coefficients_at_cos(S::S1Aarsnes, sn, c, re);
    EXPECT_NEAR(s1.drag, 0.04 + (-0.04 + sn - 1.24 * sn * sn + 13.7 * std::pow(sn, 3)) * c, 1e-14);
    EXPECT_NEAR(s1.lift, (0.57 * sn - 3.54 * sn * sn + 10.1 * std::pow(sn, 3)) * std::sin(2 * t),
                1e-14)
        << deg;
    const auto s2 = screen_coefficients_at_cos(S::S2Loland, sn, c, re);
    EXPECT_NEAR(s2.lift, (-0.05 * sn + 2.3 * sn * sn - 1.76 * std::pow(sn, 3)) * std::sin(2 * t),
                1e-14)
        << deg;
    const auto s3 = screen_coefficients_at_cos(S::S3KristiansenFaltinsen, sn, c, re);
    EXPECT_NEAR(s3.drag, cd0 * (0.9 * std::cos(t) + 0.1 * std::cos(3 * t)), 1e-14) << deg;
    EXPECT_NEAR(s3.lift, cl45 * (std::sin(2 * t) + 0.1 * std::sin(4 * t)), 1e-14) << deg;
  }
  // Outside [0, 1] (round-off in a dot product) the cosine is held at the nearer end.
  EXPECT_EQ(screen_coefficients_at_cos(S::S2Loland, sn, 1 + 1e-15, re).lift, 0.0);
  EXPECT_EQ(screen_coefficients_at_cos(S::S2Loland, sn, -1e-15, re).drag, 0.04);
}

TEST(ScreenModel, CylinderDragStaysBounded) {
  for (double re = 1; re < 1e7; re *= 1.5) {
    const double cd = cylinder_drag_coefficient(re);
    EXPECT_GT(cd, 0.8) << re;
    EXPECT_LE(cd, 7.0) << re;
  }
}

TEST(MorisonModel, SingleTwineNormalAndTangential) {
  NetModel net;
  net.rows = 1;
  net.columns = 2;
  net.normal = {1, 0, 0};
  net.across = {0, 1, 0};
  NetKnot a, b;
  b.position = {0, 0.1, 0};
  net.knots = {a, b};
  NetTwine t;
  t.a = 0;
  t.b = 1;
  t.rest = 0.1;
  t.diameter = 0.002;
  net.twines = {t};
  CurrentLoadParameters p;
  p.model = NetLoadModel::Morison;
  p.velocity = {0.5, 0.3, 0};  // 0.5 normal to the twine, 0.3 along it
  std::vector<Vec3d> f(2);
  add_current_loads(net, p, f);
  const double area = 0.002 * (0.1 - 0.002);
  const Vec3d total = f[0] + f[1];
  EXPECT_NEAR(total.x, 0.5 * 1000 * 1.2 * area * 0.5 * 0.5, 1e-12);
  EXPECT_NEAR(total.y, 0.5 * 1000 * 0.1 * area * 0.3 * 0.3, 1e-12);
  EXPECT_NEAR(f[0].x, f[1].x, 1e-15);
}

TEST(ScreenLoads, FlatNetFacingTheFlowFeelsTheScreenDrag) {
  // A 3 x 3 inset net, 0.3 m square, facing +x: drag = 1/2 rho A Cd(0) U^2, no lift.
  NetModel net;
  net.rows = net.columns = 3;
  net.normal = {1, 0, 0};
  net.across = {0, 1, 0};
  net.up = {0, 0, 1};
  net.twine_diameter = 0.0026;
  net.real_solidity = netting_solidity(0.02, 0.0026);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      NetKnot k;
      k.row = r;
      k.column = c;
      k.position = {0, 0.1 * c, 0.1 * r};
      k.screen_area = 0.01;
      net.knots.push_back(k);
    }
  }
  CurrentLoadParameters p;
  p.velocity = {0.2, 0, 0};
  p.screen = ScreenCoefficients::S2Loland;
  std::vector<Vec3d> f(9);
  add_current_loads(net, p, f);
  Vec3d total{};
  for (const Vec3d& v : f) total += v;
  const double cd = screen_coefficients_at_cos(p.screen, net.real_solidity, 1, 0).drag;
  EXPECT_NEAR(total.x, 0.5 * 1000 * 0.09 * cd * 0.04, 1e-12);
  EXPECT_NEAR(std::abs(total.y) + std::abs(total.z), 0.0, 1e-15);
}

using test::net_with_sinker;

// The bar hangs on the net's bottom edge: half a mesh below the bottom knots in the inset
// layout (knots at the mesh centres), at them in the crossings layout; once the net swings,
// along the deformed net, continuing the line from the knot above.
TEST(SinkerLoads, TheBarHangsOnTheBottomEdgeOfTheDeformedNet) {
  for (const KnotLayout layout : {KnotLayout::Inset, KnotLayout::Crossings}) {
    NetModel net = generate_net(net_with_sinker(layout), {});
    const double bottom = -0.15;  // the outline's bottom edge, about the centre
    int bars = 0;
    for (const NetKnot& k : net.knots) {
      if (k.sinker_length <= 0) continue;
      ++bars;
      EXPECT_EQ(k.row, 0);
      EXPECT_NEAR(dot(sinker_point(net, k) - net.center, net.up), bottom, 1e-12);
      EXPECT_NEAR(dot(sinker_point(net, k) - k.position, net.across), 0, 1e-12);
    }
    EXPECT_EQ(bars, net.columns);
    // Swung 30 degrees downstream about the top edge: the bar on the line through the bottom
    // two knots, sinker_offset beyond the bottom one.
    const double a = std::numbers::pi / 6;
    const Vec3d top = net.center + net.up * 0.15;
    for (NetKnot& k : net.knots) {
      const double below = dot(top - k.position, net.up);
      k.position = top - net.up * (below * std::cos(a)) + net.normal * (below * std::sin(a)) +
                   net.across * dot(k.position - top, net.across);
    }
    const NetKnot& k = net.knots[net.index(0, 1)];
    const Vec3d down = -net.up * std::cos(a) + net.normal * std::sin(a);
    const Vec3d expected = k.position + down * net.sinker_offset;
    EXPECT_NEAR(norm(sinker_point(net, k) - expected), 0, 1e-12);
    EXPECT_NEAR(net.sinker_offset, layout == KnotLayout::Inset ? 0.05 : 0.0, 1e-12);
  }
}

// The water that meets the bar is sampled at the ends of each knot's share, midway between
// neighbouring bottom knots or at the bar's ends where a share reaches the net's side (the
// inset layout), and below each knot in the inset layout (not in the crossings layout, where
// the bar runs through the knots, which hold no water): never inside a knot. The weights are
// the trapezoidal rule's along the share.
TEST(SinkerLoads, TheWaterIsSampledAlongTheBarOutsideTheKnots) {
  for (const KnotLayout layout : {KnotLayout::Inset, KnotLayout::Crossings}) {
    const bool inset = layout == KnotLayout::Inset;
    const NetModel net = generate_net(net_with_sinker(layout), {});
    std::vector<double> across;  // every sample point's position along the bar
    for (const NetKnot& k : net.knots) {
      if (k.sinker_length <= 0) continue;
      SinkerSamples s;
      const int n = sinker_sample_points(net, k, s);
      const bool end = k.column == 0 || k.column == net.columns - 1;
      EXPECT_EQ(n, inset ? 3 : (end ? 1 : 2));
      EXPECT_EQ(s.count, n);
      double weights = 0;
      for (int i = 0; i < n; ++i) {
        weights += s.weights[i];
        const Vec3d& at = s.points[i];
        EXPECT_NEAR(dot(at - net.center, net.up), -0.15, 1e-12);  // on the bar
        const double y = dot(at - net.center, net.across);
        const double from_knot = std::abs(y - dot(k.position - net.center, net.across));
        EXPECT_TRUE(std::abs(from_knot - 0.05) < 1e-12 || (inset && from_knot < 1e-12)) << y;
        EXPECT_NEAR(s.weights[i], !inset ? 1.0 / n : (from_knot < 1e-12 ? 0.5 : 0.25), 1e-15);
        across.push_back(y);
        for (const NetKnot& other : net.knots)  // in the water, outside every knot
          EXPECT_GT(norm(at - other.position), 0.5 * std::sqrt(2.0) * other.geometry.size);
      }
      EXPECT_NEAR(weights, 1, 1e-15);
    }
    std::sort(across.begin(), across.end());
    // Inset (knots at -0.1, 0, 0.1, the bar 0.05 below them): the ends -0.15, 0.15, the
    // midpoints -0.05, 0.05 (twice each) and below the knots. Crossings (knots at -0.15 ...
    // 0.15, on the bar): the midpoints -0.1, 0, 0.1 (twice each).
    const std::vector<double> expected =
        inset ? std::vector<double>{-0.15, -0.1, -0.05, -0.05, 0, 0.05, 0.05, 0.1, 0.15}
              : std::vector<double>{-0.1, -0.1, 0, 0, 0.1, 0.1};
    ASSERT_EQ(across.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(across[i], expected[i], 1e-12);
  }
}

// Cylinder drag on the bar, per knot's share: 1/2 rho Cd d L U^2 across the bar, on the flow
// relative to the knot, nothing from flow along the bar; the shares add up to the whole bar's.
TEST(SinkerLoads, CylinderDragOnTheFlowAcrossTheBarRelativeToTheKnot) {
  NetModel net = generate_net(net_with_sinker(KnotLayout::Inset), {});
  const Vec3d flow{0.226, 0.1, 0.0};  // x normal to the net, y along the bar
  Vec3d total{};
  for (const NetKnot& k : net.knots) total += sinker_drag(net, k, flow, 1000);
  const double whole_bar = 0.5 * 1000 * 1.2 * 0.006 * 0.3 * 0.226 * 0.226;
  EXPECT_NEAR(total.x, whole_bar, 1e-12);  // about 0.055 N
  EXPECT_NEAR(total.y, 0, 1e-15);
  EXPECT_NEAR(total.z, 0, 1e-15);
  // A knot moving with the water takes none; one moving upstream at U takes four times.
  NetKnot k = net.knots[net.index(0, 0)];
  k.velocity = {0.226, 0, 0};
  EXPECT_NEAR(norm(sinker_drag(net, k, flow, 1000)), 0, 1e-15);
  k.velocity = {-0.226, 0, 0};
  EXPECT_NEAR(sinker_drag(net, k, flow, 1000).x, 4 * whole_bar / 3, 1e-12);
  // Knots off the bottom row carry no bar.
  EXPECT_NEAR(norm(sinker_drag(net, net.knots[net.index(1, 0)], flow, 1000)), 0, 0);
}

}  // namespace
}  // namespace netsph
