#pragma once
// Screen-model force coefficients of a net panel in a current: drag along the relative flow
// and lift across it, F = 1/2 rho A |u|^2 (C_D i_D + C_L i_L), A the panel (outline) area and
// theta the angle between the panel normal and the flow (0: flow normal to the net).
// Coefficient sets:
//   S1  Aarsnes et al. (1990)
//   S2  Loland (1991)
//   S3  Kristiansen & Faltinsen (2012), J. Fluids Struct. 34:218-235, with the cylinder drag
//       C_D,cyl(Re) polynomial for Re = U d / (nu (1 - Sn)), and the Fourier series in theta
//       a1 = 0.9, a3 = 0.1, b2 = 1.0, b4 = 0.1.
// as written by Cheng et al. (2020), Aquacult. Eng. (their S1-S3), which ../shared/notes/
// net-models.md section 3.1 lists. Host and device share these definitions.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/physics_options.hpp"

namespace netsph {

struct ScreenForceCoefficients {
  double drag = 0;
  double lift = 0;
};

/// Drag coefficient of a circular cylinder in cross flow, the polynomial in log10(Re) used by
/// the S3 screen model (valid above Re ~ 30); below Re = 32 the creeping-flow fit
/// 1.45 + 8.55 Re^-0.9 (capped at 7), as REEF3D does. Above Re = 1e4 the polynomial runs away
/// (10.9 at 1e5), so Re is held there (C_D,cyl = 1.09, the subcritical plateau).
NETSPH_HD double cylinder_drag_coefficient(double reynolds) {
  if (reynolds <= 32) {
    const double cd = 1.45 + 8.55 * std::pow(reynolds > 1e-3 ? reynolds : 1e-3, -0.9);
    return cd < 7 ? cd : 7.0;
  }
  const double x = std::log10(reynolds < 1e4 ? reynolds : 1e4);
  return -78.46675 +
         x * (254.73873 +
              x * (-327.8864 +
                   x * (223.64577 +
                        x * (-87.92234 + x * (20.00769 + x * (-2.44894 + x * 0.12479))))));
}

/// The coefficients at cos(theta), theta in [0, pi/2]; solidity Sn; reynolds = U d_twine /
/// (nu (1 - Sn)) (S3 only). The published forms are in theta; the sines and the multiple angles
/// come from the cosine by the identities sin = sqrt(1 - cos^2), sin 2t = 2 sin cos,
/// cos 3t = 4 cos^3 - 3 cos, sin 4t = 2 sin 2t (2 cos^2 - 1), since the knots' loads have the
/// cosine (a dot product) and acos, cos and sin were 40% of a standalone net run (perf).
NETSPH_HD ScreenForceCoefficients screen_coefficients_at_cos(ScreenCoefficients set,
                                                             double solidity, double cos_theta,
                                                             double reynolds) {
  const double sn = solidity;
  const double c = cos_theta < 0 ? 0.0 : (cos_theta > 1 ? 1.0 : cos_theta);
  const double s = std::sqrt(1 - c * c);
  const double sin_2t = 2 * s * c;
  ScreenForceCoefficients k;
  switch (set) {
    case ScreenCoefficients::S1Aarsnes:
      k.drag = 0.04 + (-0.04 + sn - 1.24 * sn * sn + 13.7 * sn * sn * sn) * c;
      k.lift = (0.57 * sn - 3.54 * sn * sn + 10.1 * sn * sn * sn) * sin_2t;
      break;
    case ScreenCoefficients::S2Loland:
      k.drag = 0.04 + (-0.04 + 0.33 * sn + 6.54 * sn * sn - 4.88 * sn * sn * sn) * c;
      k.lift = (-0.05 * sn + 2.3 * sn * sn - 1.76 * sn * sn * sn) * sin_2t;
      break;
    case ScreenCoefficients::S3KristiansenFaltinsen: {
      const double cd_cyl = cylinder_drag_coefficient(reynolds);
      const double open = 1 - sn;
      const double cd0 = cd_cyl * sn * (2 - sn) / (2 * open * open);
      const double cn45 = 0.5 * cd_cyl * sn / (open * open);
      const double ct45 = 3.141592653589793 * cn45 / (8 + cn45);
      const double cl45 = (0.5 * cd0 - ct45) / 1.4142135623730951;
      const double cos_3t = (4 * c * c - 3) * c;
      const double sin_4t = 2 * sin_2t * (2 * c * c - 1);
      k.drag = cd0 * (0.9 * c + 0.1 * cos_3t);
      k.lift = cl45 * (sin_2t + 0.1 * sin_4t);
      break;
    }
  }
  return k;
}

}  // namespace netsph
