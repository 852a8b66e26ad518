#pragma once
// Shepard-corrected SPH interpolation at an arbitrary point x (Shepard 1968; in SPH e.g.
// Monaghan 2005, section 4, and DualSPHysics' MeasureTool):
//
//   f(x) = sum_j V_j W(x - x_j) f_j / sum_j V_j W(x - x_j),   V_j = m_j / rho_j
//
// The denominator ("coverage") is the kernel's volume sum: 1 inside the fluid, less near a
// free surface or a solid (fluid particles only are summed), 0 where no fluid is in reach.
// Dividing by it removes the kernel truncation there, so a uniform field is reproduced
// exactly everywhere the point sees fluid. Velocity probes (run/probes.hpp) use it.
#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/equation_of_state.hpp"

namespace netsph {

struct ShepardSums {
  double volume_weight = 0;  ///< sum V W (the coverage)
  Vec3d velocity{};          ///< sum V W v
  double pressure = 0;       ///< sum V W p
  double density = 0;        ///< sum V W rho = sum m W
};

/// Adds neighbour j: w = W(|x - x_j|), its mass, density, velocity and pressure.
NETSPH_HD void shepard_accumulate(ShepardSums& s, Real w, Real mass, Real rho, const Vec3f& v,
                                  Real p) {
  const double vw = static_cast<double>(mass) / static_cast<double>(rho) * w;
  s.volume_weight += vw;
  s.velocity += Vec3d(v) * vw;
  s.pressure += vw * p;
  s.density += vw * rho;
}

/// Adds fluid particle j at kernel weight w: its gauge pressure from the equation of state
/// (the background pressure removed), as the probes report it. CPU and device sampling share it.
NETSPH_HD void shepard_accumulate_fluid(ShepardSums& s, Real w, Real mass, Real rho, const Vec3f& v,
                                        const TaitEos& eos) {
  shepard_accumulate(s, w, mass, rho, v, eos.pressure(rho) - eos.p_background);
}

struct ShepardValue {
  double coverage = 0;  ///< sum V W: about 1 in the fluid, 0 with no fluid in reach
  Vec3d velocity{};     ///< m/s (zero when coverage is 0)
  double pressure = 0;  ///< Pa
  double density = 0;   ///< kg/m^3
};

NETSPH_HD ShepardValue shepard_value(const ShepardSums& s) {
  ShepardValue v;
  v.coverage = s.volume_weight;
  if (!(s.volume_weight > 0)) return v;
  const double inv = 1.0 / s.volume_weight;
  v.velocity = s.velocity * inv;
  v.pressure = s.pressure * inv;
  v.density = s.density * inv;
  return v;
}

}  // namespace netsph
