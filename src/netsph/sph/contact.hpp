#pragma once
// Contact between a body particle and a particle of another solid (a wall or another body):
// a spring-dashpot acting when two particles come closer than dp, i.e. when the two solids'
// surfaces (dp/2 beyond their outer particle layers) touch. SPH pressure does not do this job:
// mDBC walls take their density from the fluid, so they cannot push back on a body lying on
// them once the fluid between has been squeezed out.
//
//   a = (k (dp - r) - c (v_ab . n)) n,   n = r_ab / r,   for r < dp
//
// Acceleration of the body particle per unit of its SPH mass. The stiffness k = c0^2 / dp^2
// is that of the fluid itself (a pressure rho0 c0^2 times the strain (dp - r)/dp on an area
// dp^(d-1), divided by the particle mass rho0 dp^d), so contact is resolved at the fluid's
// acoustic time step; the damping is half of critical for one particle, c = c0 / dp.
#include <cmath>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct ContactModel {
  Real distance = 0;   ///< dp, m
  Real stiffness = 0;  ///< c0^2 / dp^2, 1/s^2
  Real damping = 0;    ///< c0 / dp, 1/s

  static ContactModel make(double dp, double c0) {
    return {static_cast<Real>(dp), static_cast<Real>(c0 * c0 / (dp * dp)),
            static_cast<Real>(c0 / dp)};
  }
};

/// rab = r_a - r_b, vab = v_a - v_b; zero beyond dp.
NETSPH_HD Vec3f contact_acceleration(const ContactModel& c, const Vec3f& rab, const Vec3f& vab) {
  const Real r2 = norm2(rab);
  if (!(r2 < c.distance * c.distance) || !(r2 > Real(0))) return {};
  const Real r = std::sqrt(r2);
  const Vec3f n = rab / r;
  return n * (c.stiffness * (c.distance - r) - c.damping * dot(vab, n));
}

}  // namespace netsph
