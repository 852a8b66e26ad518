#pragma once
// A damping zone (a "sponge layer" or numerical beach): the fluid's velocity is relaxed towards
// a target (zero, or the current) at a rate that grows smoothly along x, so that waves entering
// it die out instead of reflecting from the end of the tank. The relaxation term -beta(x)
// (v - v_target) added to the momentum equation is the classical absorbing layer of Israeli &
// Orszag (1981, J. Comput. Phys. 41:115-135); it is applied here after each step, exactly
// integrated over the step, v <- v_t + (v - v_t) exp(-beta dt), which is stable for any rate.
// The rate grows as beta = rate s^2 across the zone (s = 0 at `from`, 1 at `to`, rate beyond):
// a gradual start reflects little of the wave itself. One definition for the CPU and the device
// step.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct DampingZone {
  double from = 0;   ///< x where the damping starts, m
  double to = 0;     ///< x where it reaches `rate`, m (to < from: the zone faces -x)
  double rate = 0;   ///< 1/s
  Vec3f velocity{};  ///< the velocity relaxed towards, m/s
};

/// The relaxation rate at x, 1/s.
NETSPH_HD double damping_rate(const DampingZone& z, double x) {
  const double s = (x - z.from) / (z.to - z.from);
  if (!(s > 0)) return 0;
  return s >= 1 ? z.rate : z.rate * s * s;
}

/// Relaxes v (a fluid particle's at x) over a step of dt, in place.
NETSPH_HD void damp_velocity(const DampingZone& z, double x, double dt, Vec3f& v) {
  const double beta = damping_rate(z, x);
  if (!(beta > 0)) return;
  const auto keep = static_cast<Real>(std::exp(-beta * dt));
  v = z.velocity + (v - z.velocity) * keep;
}

}  // namespace netsph
