#pragma once
// Tait equation of state for weakly compressible SPH (Monaghan 1994; Batchelor 1967):
//   P = B ((rho / rho0)^gamma - 1),   B = c0^2 rho0 / gamma
// and its inverse, used for the hydrostatic initial density.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"

namespace netsph {

struct TaitEos {
  Real rho0 = 1000;  ///< reference density, kg/m^3
  Real c0 = 0;       ///< numerical speed of sound, m/s
  Real gamma = 7;
  Real b = 0;  ///< c0^2 rho0 / gamma, Pa
  Real inv_rho0 = 0;
  /// Added to every pressure, Pa (0 by default). A positive background pressure keeps the
  /// pressure positive in suction regions of flows without a free surface (the wake of a
  /// body in a closed channel), where negative pressure makes SPH particles clump and open
  /// voids (tensile instability; the remedy of Morris, Fox & Zhu 1997 and Adami, Hu & Adams
  /// 2013). Gradients, and so the flow, do not change; a free surface needs 0.
  Real p_background = 0;

  static TaitEos make(double rho0, double c0, double gamma, double p_background = 0) {
    TaitEos e;
    e.rho0 = static_cast<Real>(rho0);
    e.c0 = static_cast<Real>(c0);
    e.gamma = static_cast<Real>(gamma);
    e.b = static_cast<Real>(c0 * c0 * rho0 / gamma);
    e.inv_rho0 = static_cast<Real>(1.0 / rho0);
    e.p_background = static_cast<Real>(p_background);
    return e;
  }

  NETSPH_HD Real pressure(Real rho) const {
    // gamma = 7 is the common case: three multiplications instead of pow().
    const Real x = rho * inv_rho0;
    if (gamma == Real(7)) {
      const Real x2 = x * x;
      return b * (x2 * x2 * x2 * x - Real(1)) + p_background;
    }
    return b * (std::pow(x, gamma) - Real(1)) + p_background;
  }

  /// rho such that pressure(rho) == p + p_background: p is the gauge pressure, as a
  /// hydrostatic column gives it (double: used to set initial states).
  NETSPH_HD double density(double p) const {
    return static_cast<double>(rho0) * std::pow(p / static_cast<double>(b) + 1.0, 1.0 / gamma);
  }
};

}  // namespace netsph
