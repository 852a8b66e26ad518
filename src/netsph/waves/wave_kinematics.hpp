#pragma once
// The free surface and the orbital velocity of a regular wave on a uniform current, to first
// order (Airy) or second order (Stokes), written once for the CPU step and the device step
// (an inlet buffer imposes them). Linear (Airy) and Stokes second-order theory as in Dean &
// Dalrymple (1991), "Water Wave Mechanics for Engineers and Scientists"; on a current
// the wave is the same in the frame moving with the water, so the amplitudes take the
// intrinsic frequency sigma = omega - k U and the phase the absolute frequency omega (Jonsson
// 1990). Coordinates: x along the wave's travel, z up from the still-water level (the bottom
// at z = -h).
#include <cmath>

#include "netsph/core/host_device.hpp"

namespace netsph {

/// A regular wave as its kinematics need it (set up with waves/dispersion.hpp).
struct RegularWave {
  double height = 0;   ///< H, crest to trough of the first-order wave, m
  double omega = 0;    ///< absolute angular frequency, rad/s
  double k = 0;        ///< wave number, rad/m (wave_number_on_current)
  double depth = 0;    ///< still-water depth h, m
  double current = 0;  ///< uniform current U along x, m/s
  double phase = 0;    ///< phase at x = 0, t = 0, rad (theta = k x - omega t + phase)
  int order = 1;       ///< 1: linear (Airy); 2: Stokes second order
};

/// The intrinsic frequency sigma = omega - k U, rad/s.
NETSPH_HD double intrinsic_omega(const RegularWave& w) {
  return w.omega - w.k * w.current;
}

/// The phase theta = k x - omega t + phase.
NETSPH_HD double wave_phase(const RegularWave& w, double x, double t) {
  return w.k * x - w.omega * t + w.phase;
}

/// The second-order surface's cos 2 theta amplitude, m: (H^2 k / 16) cosh kh (2 + cosh 2kh)
/// / sinh^3 kh (Stokes second order, Dean & Dalrymple 1991). Zero for a linear wave.
NETSPH_HD double second_order_surface_amplitude(const RegularWave& w) {
  if (w.order < 2) return 0;
  // cosh kh / sinh kh and (2 + cosh 2kh) / sinh^2 kh written with e = exp(-2kh), so that deep
  // water (cosh overflows past kh = 355) gives the deep-water limit H^2 k / 8 instead of NaN.
  const double e = std::exp(-2 * w.k * w.depth), one_minus = -std::expm1(-2 * w.k * w.depth);
  const double coth = (1 + e) / one_minus;
  const double ratio = (8 * e + 2 + 2 * e * e) / (one_minus * one_minus);
  return w.height * w.height * w.k / 16 * coth * ratio;
}

/// The free-surface elevation above the still-water level at x, t, m.
NETSPH_HD double wave_elevation(const RegularWave& w, double x, double t) {
  const double theta = wave_phase(w, x, t);
  return 0.5 * w.height * std::cos(theta) + second_order_surface_amplitude(w) * std::cos(2 * theta);
}

/// The velocity (u along x, w up) at x, z (z from the still-water level, -h <= z), time t:
/// the current plus the orbital velocity, u = U + (H/2) sigma cosh k(z+h) / sinh kh cos theta
/// (+ (3/16) H^2 sigma k cosh 2k(z+h) / sinh^4 kh cos 2 theta at second order), and w the
/// same with sinh and sin (Dean & Dalrymple 1991). Above the
/// still-water level the expressions are used as they are (Wheeler stretching is not applied).
NETSPH_HD void wave_velocity(const RegularWave& w, double x, double z, double t, double& u,
                             double& v_up) {
  const double theta = wave_phase(w, x, t);
  const double sigma = intrinsic_omega(w);
  // The depth ratios cosh k(z+h) / sinh kh and sinh k(z+h) / sinh kh as exp(k z) times
  // factors in exp(-2 k (z+h)) and exp(-2kh), which stay finite in deep water (the plain
  // hyperbolic functions overflow past kh = 710 and give inf / inf). z + h is kept >= 0: below
  // the bottom the bottom's value.
  const double kh = w.k * w.depth, kz = w.k * std::fmax(z + w.depth, 0.0);
  const double ez = std::exp(-2 * kz), decay = std::exp(kz - kh);
  const double one_minus_eh = -std::expm1(-2 * kh), one_minus_ez = -std::expm1(-2 * kz);
  const double a1 = 0.5 * w.height * sigma;
  const double cosh_ratio = decay * (1 + ez) / one_minus_eh;
  const double sinh_ratio = decay * one_minus_ez / one_minus_eh;
  u = w.current + a1 * cosh_ratio * std::cos(theta);
  v_up = a1 * sinh_ratio * std::sin(theta);
  if (w.order >= 2) {
    // cosh 2k(z+h) / sinh^4 kh = 8 exp(2k(z+h) - 4kh) (1 + exp(-4k(z+h))) / (1 - exp(-2kh))^4,
    // and the same with sinh and a minus sign.
    const double d2 = std::exp(2 * kz - 4 * kh), q = one_minus_eh * one_minus_eh;
    const double a2 = 3.0 / 16.0 * w.height * w.height * sigma * w.k * 8 * d2 / (q * q);
    u += a2 * (1 + ez * ez) * std::cos(2 * theta);
    v_up += a2 * one_minus_ez * (1 + ez) * std::sin(2 * theta);
  }
}

/// The factor that ramps a wave up from rest over `ramp` seconds: (1 - cos(pi t / ramp)) / 2,
/// then 1 (smooth in the displacement and velocity it scales, so that the start launches no
/// transient of its own).
NETSPH_HD double wave_ramp(double t, double ramp) {
  if (!(ramp > 0) || t >= ramp) return 1;
  if (t <= 0) return 0;
  return 0.5 * (1 - std::cos(M_PI * t / ramp));
}

/// d(wave_ramp)/dt, 1/s: (pi / (2 ramp)) sin(pi t / ramp) inside the ramp, 0 outside.
NETSPH_HD double wave_ramp_rate(double t, double ramp) {
  if (!(ramp > 0) || t <= 0 || t >= ramp) return 0;
  return 0.5 * M_PI / ramp * std::sin(M_PI * t / ramp);
}

}  // namespace netsph
