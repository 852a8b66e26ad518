// Current loads on standalone nets: the screen-model coefficients against values computed
// independently from Cheng et al.'s code (../shared/notes/net-models.md, section 3.1, for a
// Patursson-type net: d = 2.8 mm, l = 29 mm, Sn = 0.1838, nu = 1.004e-6), and the Morison
// drag of a single twine.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "netsph/net/current_loads.hpp"
#include "netsph/net/equivalent_knot.hpp"
#include "netsph/net/screen_model.hpp"

namespace netsph {
namespace {

constexpr double kDeg45 = std::numbers::pi / 4;

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
  EXPECT_NEAR(screen_coefficients(S::S1Aarsnes, sn, 0, reynolds(0.125)).drag, 0.227, 0.001);
  EXPECT_NEAR(screen_coefficients(S::S2Loland, sn, 0, reynolds(0.125)).drag, 0.251, 0.001);
  EXPECT_NEAR(screen_coefficients(S::S3KristiansenFaltinsen, sn, 0, reynolds(0.125)).drag, 0.297,
              0.001);
  const auto s1 = screen_coefficients(S::S1Aarsnes, sn, kDeg45, reynolds(0.125));
  EXPECT_NEAR(s1.drag, 0.172, 0.001);
  EXPECT_NEAR(s1.lift, 0.048, 0.001);
  const auto s2 = screen_coefficients(S::S2Loland, sn, kDeg45, reynolds(0.125));
  EXPECT_NEAR(s2.drag, 0.189, 0.001);
  EXPECT_NEAR(s2.lift, 0.058, 0.001);
  const auto s3 = screen_coefficients(S::S3KristiansenFaltinsen, sn, kDeg45, reynolds(0.125));
  EXPECT_NEAR(s3.drag, 0.168, 0.001);
  EXPECT_NEAR(s3.lift, 0.061, 0.001);
  // U = 0.25, 0.5, 0.75 m/s at normal incidence, and 0.5 at 45 degrees (S3)
  EXPECT_NEAR(screen_coefficients(S::S3KristiansenFaltinsen, sn, 0, reynolds(0.25)).drag, 0.259,
              0.001);
  EXPECT_NEAR(screen_coefficients(S::S3KristiansenFaltinsen, sn, 0, reynolds(0.5)).drag, 0.238,
              0.001);
  EXPECT_NEAR(screen_coefficients(S::S3KristiansenFaltinsen, sn, 0, reynolds(0.75)).drag, 0.240,
              0.001);
  const auto s3_05 = screen_coefficients(S::S3KristiansenFaltinsen, sn, kDeg45, reynolds(0.5));
  EXPECT_NEAR(s3_05.drag, 0.134, 0.001);
  EXPECT_NEAR(s3_05.lift, 0.048, 0.001);
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
  const double cd = screen_coefficients(p.screen, net.real_solidity, 0, 0).drag;
  EXPECT_NEAR(total.x, 0.5 * 1000 * 0.09 * cd * 0.04, 1e-12);
  EXPECT_NEAR(std::abs(total.y) + std::abs(total.z), 0.0, 1e-15);
}

}  // namespace
}  // namespace netsph
