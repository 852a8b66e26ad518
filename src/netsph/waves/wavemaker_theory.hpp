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
