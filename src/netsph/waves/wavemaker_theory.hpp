#pragma once
// First-order wavemaker theory: the height of the progressive wave a paddle makes for a given
// stroke, far enough from the paddle that its evanescent modes have died out (Biesel & Suquet
// 1951, as derived in Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers and
// Scientists", sec. 6.3, eqs. 6.16-6.17). kh: wave number times still-water depth; the stroke
// S is the paddle's full excursion (twice the amplitude of its motion) at the still-water
// level.
#include <cmath>

namespace netsph {

/// H / S of a piston paddle: 2 (cosh 2kh - 1) / (sinh 2kh + 2kh). Shallow water: kh (the
/// volume swept equals the wave's crest volume); deep water: 2.
inline double piston_height_to_stroke(double kh) {
  // Past kh = 20 the ratio is 2 to the last bit (and cosh overflows past 355).
  if (kh > 20) return 2;
  return 2 * (std::cosh(2 * kh) - 1) / (std::sinh(2 * kh) + 2 * kh);
}

/// H / S of a flap paddle hinged at the bottom: 4 (sinh kh / kh) (kh sinh kh - cosh kh + 1) /
/// (sinh 2kh + 2kh). Shallow water: kh / 2 (half the piston's swept volume); deep water:
/// 2 (1 - 1/kh), tending to 2.
inline double flap_height_to_stroke(double kh) {
  // Past kh = 20 the same ratio written so that cosh cannot overflow (it does past 355):
  // 2 (tanh kh - 1/kh + 1/(kh cosh kh)), exact but for terms of order kh e^-2kh < 1e-16.
  if (kh > 20) return 2 * (std::tanh(kh) - 1 / kh + 1 / (kh * std::cosh(kh)));
  return 4 * (std::sinh(kh) / kh) * (kh * std::sinh(kh) - std::cosh(kh) + 1) /
         (std::sinh(2 * kh) + 2 * kh);
}

}  // namespace netsph

namespace netsph {

/// Second-order generation with a piston (Madsen 1971, "On the generation of long waves",
/// J. Geophys. Res. 76(36):8672-8683; the form used by Altomare et al. 2017, Coastal Eng.
/// 127:37-54, eq. 9): a piston moving as first-order theory says makes, besides the Stokes
/// wave's bound second harmonic, a free second harmonic that travels at its own, slower speed,
/// so the wave's shape changes down the flume. Adding a second harmonic to the paddle's motion,
///   X2(t) = A2 sin(2 (omega t - phase)),
///   A2 = H^2 / (32 h) (3 cosh kh / sinh^3 kh - 2 / m1),   m1 = H / S (piston_height_to_stroke),
/// cancels it. The result comes from balancing, at the paddle, the second-order volume flux of
/// the bound wave against the paddle's and the first-order wave's, with the progressive mode
/// only (no evanescent modes): a long-wave result, exact as kh -> 0 (there A2 -> 3 H^2 /
/// (32 k^3 h^4), the stroke that makes the bound harmonic by itself). Past kh of about 1.16 it
/// changes sign, and the full theory with the evanescent modes (Schaffer 1996, Ocean Eng.
/// 23(1):47-88, not built) differs from it: use it in shallow and intermediate water, where
/// the free harmonic matters (it is measured at kh = 0.8, docs/VALIDATION.md "Waves").
/// Returns A2, m, signed. height H and depth h in m.
inline double piston_second_order_amplitude(double height, double kh, double depth) {
  // Past kh = 20, cosh / sinh^3 is below 4 e^-40: nothing beside 2 / m1 = 1.
  const double bound = kh > 20 ? 0.0 : 3 * std::cosh(kh) / std::pow(std::sinh(kh), 3);
  return height * height / (32 * depth) * (bound - 2 / piston_height_to_stroke(kh));
}

}  // namespace netsph
