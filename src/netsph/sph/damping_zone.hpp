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
//
// The same zone with a moving target is a relaxation wavemaker (the relaxation-zone generation
// of Jacobsen et al. 2012, Int. J. Numer. Meth. Fluids 70:1073-1088, brought to SPH by
// Altomare et al. 2018, Appl. Ocean Res. 81:15-33): the target is the current plus a regular
// wave's orbital velocity at the particle's place and time (waves/wave_kinematics.hpp), so the
// fluid in the zone is driven into the wave, which leaves the zone's weak end as a free wave.
// It needs no moving wall, so it makes waves on a current coming from an inlet.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/waves/wave_kinematics.hpp"

namespace netsph {

/// The wave a relaxation wavemaker's zone drives the fluid into, in the wave's own frame:
/// x' = direction (x - origin_x) along its travel, z' = z - still_level.
struct ZoneWave {
  RegularWave wave{};      ///< height 0: no wave (a plain damping zone)
  double origin_x = 0;     ///< m: where the wave's phase is wave.phase at t = 0
  double still_level = 0;  ///< m: z of the still-water surface
  double ramp = 0;         ///< s: the wave's ramp from rest (wave_ramp)
  int direction = 1;       ///< +1: the wave travels in +x; -1: in -x
};

struct DampingZone {
  double from = 0;   ///< x where the damping starts, m
  double to = 0;     ///< x where it reaches `rate`, m (to < from: the zone faces -x)
  double rate = 0;   ///< 1/s
  Vec3f velocity{};  ///< the velocity relaxed towards (zero, or the current), m/s
  ZoneWave wave{};   ///< a relaxation wavemaker's wave, added to `velocity` (none by default)
};

/// The velocity relaxed towards at p, time t: `velocity`, plus the zone's wave's orbital
/// velocity (ramped) when it has one.
NETSPH_HD Vec3f damping_target(const DampingZone& z, const Vec3d& p, double t) {
  if (!(z.wave.wave.height > 0)) return z.velocity;
  const ZoneWave& zw = z.wave;
  const double along = zw.direction * (p.x - zw.origin_x);
  double u = 0, w = 0;
  wave_velocity(zw.wave, along, p.z - zw.still_level, t, u, w);
  const double r = wave_ramp(t, zw.ramp);
  // wave_velocity includes the current the wave rides; `velocity` already holds it.
  const double orbital = (u - zw.wave.current) * r;
  return z.velocity + Vec3f(Vec3d{zw.direction * orbital, 0, w * r});
}

/// The relaxation rate at x, 1/s.
NETSPH_HD double damping_rate(const DampingZone& z, double x) {
  const double s = (x - z.from) / (z.to - z.from);
  if (!(s > 0)) return 0;
  return s >= 1 ? z.rate : z.rate * s * s;
}

/// Relaxes v (a fluid particle's at p) over a step of dt ending at time t, in place.
NETSPH_HD void damp_velocity(const DampingZone& z, const Vec3d& p, double t, double dt, Vec3f& v) {
  const double beta = damping_rate(z, p.x);
  if (!(beta > 0)) return;
  const auto keep = static_cast<Real>(std::exp(-beta * dt));
  const Vec3f target = damping_target(z, p, t);
  v = target + (v - target) * keep;
}

}  // namespace netsph
