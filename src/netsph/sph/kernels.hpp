#pragma once
// SPH smoothing kernels with support radius 2h, written once for both backends.
// Each kernel is a type with static functions of q = r/h, so the interaction loops can be
// compiled for one kernel without a branch per pair.
//
// Wendland C2 (Wendland 1995; the "quintic" kernel of DualSPHysics, Crespo et al. 2015):
//   W(q) = aD (1 - q/2)^4 (2q + 1),            0 <= q <= 2
//   aD = 7 / (4 pi h^2) in 2D, 21 / (16 pi h^3) in 3D
//   (1/r) dW/dr = -5 aD / h^2 (1 - q/2)^3      (finite at r = 0)
// Cubic spline (Monaghan & Lattanzio 1985):
//   W(q) = aD (1 - 1.5 q^2 + 0.75 q^3),        0 <= q < 1
//        = aD 0.25 (2 - q)^3,                  1 <= q < 2
//   aD = 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D
#include "netsph/core/host_device.hpp"
#include "netsph/core/physics_options.hpp"
#include "netsph/core/real.hpp"

namespace netsph {

/// Normalisation and scale of a kernel for one smoothing length and dimension.
struct KernelScale {
  Real h = 0;  ///< smoothing length, m
  Real inv_h = 0;
  Real alpha_d = 0;    ///< W = alpha_d * shape(q)
  Real grad_coef = 0;  ///< (1/r) dW/dr = grad_coef * grad_shape(q)
};

struct WendlandC2 {
  static constexpr KernelType type = KernelType::Wendland;
  static double alpha_d(int dims, double h) {
    return dims == 2 ? 7.0 / (4.0 * kPi * h * h) : 21.0 / (16.0 * kPi * h * h * h);
  }
  NETSPH_HD static Real shape(Real q) {
    const Real a = Real(1) - Real(0.5) * q;
    return q < Real(2) ? a * a * a * a * (Real(2) * q + Real(1)) : Real(0);
  }
  /// (1/r) dW/dr divided by alpha_d / h^2.
  NETSPH_HD static Real grad_shape(Real q) {
    const Real a = Real(1) - Real(0.5) * q;
    return q < Real(2) ? Real(-5) * a * a * a : Real(0);
  }
};

struct CubicSpline {
  static constexpr KernelType type = KernelType::CubicSpline;
  static double alpha_d(int dims, double h) {
    return dims == 2 ? 10.0 / (7.0 * kPi * h * h) : 1.0 / (kPi * h * h * h);
  }
  NETSPH_HD static Real shape(Real q) {
    if (q < Real(1)) return Real(1) - Real(1.5) * q * q + Real(0.75) * q * q * q;
    const Real a = Real(2) - q;
    return q < Real(2) ? Real(0.25) * a * a * a : Real(0);
  }
  /// (1/r) dW/dr divided by alpha_d / h^2: (dshape/dq) / q.
  NETSPH_HD static Real grad_shape(Real q) {
    if (q < Real(1)) return Real(-3) + Real(2.25) * q;
    const Real a = Real(2) - q;
    return q < Real(2) ? Real(-0.75) * a * a / q : Real(0);
  }
};

template <class Kernel>
KernelScale make_kernel_scale(int dims, double h) {
  KernelScale s;
  const double ad = Kernel::alpha_d(dims, h);
  s.h = static_cast<Real>(h);
  s.inv_h = static_cast<Real>(1.0 / h);
  s.alpha_d = static_cast<Real>(ad);
  s.grad_coef = static_cast<Real>(ad / (h * h));
  return s;
}

template <class Kernel>
NETSPH_HD Real kernel_value(const KernelScale& s, Real r) {
  return s.alpha_d * Kernel::shape(r * s.inv_h);
}

/// (1/r) dW/dr, so that grad_a W_ab = kernel_grad_factor * (r_a - r_b). Negative inside the
/// support.
template <class Kernel>
NETSPH_HD Real kernel_grad_factor(const KernelScale& s, Real r) {
  return s.grad_coef * Kernel::grad_shape(r * s.inv_h);
}

/// Calls f(Kernel{}) with the kernel type chosen at run time; used to instantiate loops.
template <class F>
decltype(auto) with_kernel(KernelType type, F&& f) {
  if (type == KernelType::CubicSpline) return f(CubicSpline{});
  return f(WendlandC2{});
}

}  // namespace netsph
