#include "netsph/waves/dispersion.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

namespace netsph {
namespace {

void require_positive(const char* what, double v) {
  if (!(v > 0) || !std::isfinite(v))
    throw Error("waves", fmt::format("{} must be positive and finite, got {}", what, v));
}

}  // namespace

double intrinsic_frequency(double k, double depth, double g) {
  return std::sqrt(g * k * std::tanh(k * depth));
}

double relative_group_velocity(double k, double depth, double g) {
  // d/dk sqrt(g k tanh(kh)) = (sigma / k) (1/2) (1 + 2kh / sinh(2kh)), the textbook
  // c_g = n c with n = (1 + 2kh / sinh 2kh) / 2 (Dean & Dalrymple 1991, eq. 4.68).
  const double kh = k * depth;
  const double n = kh > 350 ? 0.5 : 0.5 * (1 + 2 * kh / std::sinh(2 * kh));
  return n * intrinsic_frequency(k, depth, g) / k;
}

double wave_number(double omega, double depth, double g) {
  require_positive("the angular frequency", omega);
  require_positive("the water depth", depth);
  require_positive("gravity", g);
  // Start from Fenton & McKee (1990): k h ~ k0 h coth((k0 h)^(3/4))^(2/3), k0 = omega^2 / g,
  // within 1.7% everywhere; Newton on f(k) = g k tanh(kh) - omega^2 (increasing in k) then
  // converges in a few steps.
  const double k0 = omega * omega / g;
  double k = k0 / std::pow(std::tanh(std::pow(k0 * depth, 0.75)), 2.0 / 3.0);
  for (int it = 0; it < 50; ++it) {
    const double t = std::tanh(k * depth);
    const double f = g * k * t - omega * omega;
    const double df = g * (t + k * depth * (1 - t * t));
    const double step = f / df;
    k -= step;
    if (std::abs(step) <= 1e-15 * k) break;
  }
  return k;
}

double wave_number_on_current(double omega, double depth, double current, double g) {
  if (current == 0) return wave_number(omega, depth, g);
  require_positive("the angular frequency", omega);
  require_positive("the water depth", depth);
  require_positive("gravity", g);
  if (!std::isfinite(current)) throw Error("waves", "the current must be finite");
  // F(k) = omega - k U - sigma(k): F(0) = omega > 0. sigma is increasing and concave, so for
  // U > 0 F falls monotonically and has one root, below omega / U. For U < 0, F falls while
  // sigma'(k) > -U and rises after: the wave exists if F's minimum, at k* where
  // sigma'(k*) = -U (the blocking point), is not above zero; the physical root is the one
  // below k*, the one connected to U = 0.
  const auto F = [&](double k) { return omega - k * current - intrinsic_frequency(k, depth, g); };
  double lo = 0, hi;
  if (current > 0) {
    hi = omega / current;
  } else {
    // sigma' falls from sqrt(g h) at k = 0 towards 0: find k* by bisection on sigma' + U.
    if (std::sqrt(g * depth) <= -current) {
      throw Error("waves", fmt::format("an opposing current of {:.4g} m/s is faster than "
                                       "shallow-water waves in {:.4g} m of water ({:.4g} m/s): "
                                       "no wave travels against it",
                                       -current, depth, std::sqrt(g * depth)));
    }
    double a = 0, b = wave_number(omega, depth, g);
    while (relative_group_velocity(b, depth, g) > -current) b *= 2;
    for (int it = 0; it < 200; ++it) {
      const double m = 0.5 * (a + b);
      (relative_group_velocity(m, depth, g) > -current ? a : b) = m;
    }
    const double k_block = 0.5 * (a + b);
    if (F(k_block) > 0) {
      throw Error("waves", fmt::format("an opposing current of {:.4g} m/s blocks a wave of period "
                                       "{:.4g} s in {:.4g} m of water (the wave's group velocity "
                                       "relative to the water cannot exceed the current)",
                                       -current, 2 * M_PI / omega, depth));
    }
    hi = k_block;
  }
  // Bisection to the last bit: F changes sign once in [lo, hi].
  for (int it = 0; it < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++it) {
    const double m = 0.5 * (lo + hi);
    (F(m) > 0 ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

double breaking_steepness(double kh) {
  return 0.142 * std::tanh(kh);
}

}  // namespace netsph
