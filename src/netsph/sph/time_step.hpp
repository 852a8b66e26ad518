#pragma once
// Variable time step of DualSPHysics (Monaghan & Kos 1999; Crespo et al. 2015):
//   dt_f  = sqrt(h / max_a |a_a|)                      (force criterion)
//   dt_cv = h / (c0 + h max_ab |v_ab.r_ab/(r^2+eta^2)|) (acoustic-viscous criterion)
//   dt    = CFL min(dt_f, dt_cv)
// plus, with laminar viscosity, the explicit diffusion limit dt_nu = 0.125 h^2 / nu
// (Morris et al. 1997), which only binds at low Reynolds numbers.
#include <algorithm>
#include <cmath>
#include <limits>

#include "netsph/sph/fluid_model.hpp"

namespace netsph {

struct TimeStepInputs {
  double max_acc = 0;      ///< max |dv/dt| over fluid particles, m/s^2 (gravity included)
  double max_visc_dt = 0;  ///< max |h v_ab.r_ab/(r^2+eta^2)| over pairs, 1/s
};

struct TimeStepLimits {
  double force = 0;
  double acoustic = 0;
  double viscous = 0;  ///< infinity unless the laminar model is on
  double dt = 0;       ///< CFL * min of the three
};

inline TimeStepLimits compute_time_step(const FluidModel& m, double cfl, const TimeStepInputs& in) {
  const double h = m.kernel.h;
  const double inf = std::numeric_limits<double>::infinity();
  TimeStepLimits lim;
  lim.force = in.max_acc > 0 ? std::sqrt(h / in.max_acc) : inf;
  lim.acoustic = h / (static_cast<double>(m.eos.c0) + h * in.max_visc_dt);
  lim.viscous = m.viscosity == ViscosityModel::Laminar && m.nu > 0 ? 0.125 * h * h / m.nu : inf;
  lim.dt = cfl * std::min({lim.force, lim.acoustic, lim.viscous});
  return lim;
}

}  // namespace netsph
