// Kernel properties: unit integral, consistent derivative, compact support, and the discrete
// sums on the dp lattice that SPH relies on (partition of unity, gradient of a linear field).
#include <gtest/gtest.h>

#include <cmath>

#include "netsph/sph/kernels.hpp"

namespace netsph {
namespace {

/// Integral of W over the plane (2D) or space (3D) by the radial quadrature int W 2 pi r dr or
/// int W 4 pi r^2 dr with the midpoint rule (1e5 intervals: error ~1e-9).
template <class K>
double radial_integral(int dims, double h) {
  const KernelScale s = make_kernel_scale<K>(dims, h);
  const int n = 100000;
  const double dr = 2 * h / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    const double shell = dims == 2 ? 2 * kPi * r : 4 * kPi * r * r;
    sum += static_cast<double>(kernel_value<K>(s, static_cast<Real>(r))) * shell * dr;
  }
  return sum;
}

template <class K>
void expect_unit_integral() {
  EXPECT_NEAR(radial_integral<K>(2, 0.015), 1.0, 1e-5);
  EXPECT_NEAR(radial_integral<K>(3, 0.015), 1.0, 1e-5);
  EXPECT_NEAR(radial_integral<K>(3, 2.0), 1.0, 1e-5);
}

TEST(Kernel, WendlandIntegratesToOne) {
  expect_unit_integral<WendlandC2>();
}
TEST(Kernel, CubicSplineIntegratesToOne) {
  expect_unit_integral<CubicSpline>();
}

template <class K>
void expect_gradient_matches_finite_difference(int dims) {
  const double h = 0.03;
  const KernelScale s = make_kernel_scale<K>(dims, h);
  for (double q = 0.05; q < 1.99; q += 0.05) {
    const double r = q * h, e = 1e-4 * h;
    const double fd = (static_cast<double>(kernel_value<K>(s, static_cast<Real>(r + e))) -
                       static_cast<double>(kernel_value<K>(s, static_cast<Real>(r - e)))) /
                      (2 * e);
    const double analytic = static_cast<double>(kernel_grad_factor<K>(s, static_cast<Real>(r))) * r;
    EXPECT_NEAR(analytic, fd, 2e-3 * std::fabs(s.alpha_d / h)) << "q = " << q;
  }
}

TEST(Kernel, WendlandGradientIsDerivative) {
  expect_gradient_matches_finite_difference<WendlandC2>(2);
  expect_gradient_matches_finite_difference<WendlandC2>(3);
}
TEST(Kernel, CubicSplineGradientIsDerivative) {
  expect_gradient_matches_finite_difference<CubicSpline>(2);
  expect_gradient_matches_finite_difference<CubicSpline>(3);
}

template <class K>
void expect_compact_support() {
  const KernelScale s = make_kernel_scale<K>(3, 0.01);
  EXPECT_EQ(kernel_value<K>(s, 0.02f), 0.0f);
  EXPECT_EQ(kernel_value<K>(s, 0.025f), 0.0f);
  EXPECT_EQ(kernel_grad_factor<K>(s, 0.03f), 0.0f);
  EXPECT_GT(kernel_value<K>(s, 0.0199f), 0.0f);
  EXPECT_LT(kernel_grad_factor<K>(s, 0.001f), 0.0f);  // W decreases away from the centre
}
TEST(Kernel, CompactSupportOf2h) {
  expect_compact_support<WendlandC2>();
  expect_compact_support<CubicSpline>();
}

/// Discrete sums over a full lattice around the origin with spacing dp and h = 1.5 dp:
/// sum V W = 1 (partition of unity) and sum V (f_b - f_a) grad_a W = grad f for linear f.
template <class K>
void expect_lattice_consistency(int dims) {
  const double dp = 0.01, h = 1.5 * dp, vol = std::pow(dp, dims);
  const KernelScale s = make_kernel_scale<K>(dims, h);
  const double c[3] = {0.7, -1.3, 2.1};  // f(r) = c . r
  double sum_w = 0, grad[3] = {0, 0, 0};
  const int n = 4;
  for (int k = -n; k <= n; ++k)
    for (int j = (dims == 3 ? -n : 0); j <= (dims == 3 ? n : 0); ++j)
      for (int i = -n; i <= n; ++i) {
        // Offset the lattice by a fraction of dp so that the sums are not helped by symmetry.
        const double rb[3] = {(i + 0.2) * dp, (dims == 3 ? (j - 0.1) * dp : 0.0), (k + 0.3) * dp};
        const double r = std::sqrt(rb[0] * rb[0] + rb[1] * rb[1] + rb[2] * rb[2]);
        sum_w += vol * static_cast<double>(kernel_value<K>(s, static_cast<Real>(r)));
        const double f = static_cast<double>(kernel_grad_factor<K>(s, static_cast<Real>(r)));
        const double df = c[0] * rb[0] + c[1] * rb[1] + c[2] * rb[2];    // f_b - f_a, a at origin
        for (int a = 0; a < 3; ++a) grad[a] += vol * df * f * (-rb[a]);  // r_ab = -r_b
      }
  EXPECT_NEAR(sum_w, 1.0, 0.02) << "dims " << dims;
  EXPECT_NEAR(grad[0], c[0], 0.02 * std::fabs(c[0])) << "dims " << dims;
  EXPECT_NEAR(grad[2], c[2], 0.02 * std::fabs(c[2])) << "dims " << dims;
  if (dims == 3) {
    EXPECT_NEAR(grad[1], c[1], 0.02 * std::fabs(c[1]));
  }
}

TEST(Kernel, WendlandLatticeConsistency) {
  expect_lattice_consistency<WendlandC2>(2);
  expect_lattice_consistency<WendlandC2>(3);
}
TEST(Kernel, CubicSplineLatticeConsistency) {
  expect_lattice_consistency<CubicSpline>(2);
  expect_lattice_consistency<CubicSpline>(3);
}

}  // namespace
}  // namespace netsph
