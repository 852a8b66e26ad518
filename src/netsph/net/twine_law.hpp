#pragma once
// The axial law of a twine: a tension-only spring T(eps) = c1 eps + c2 eps^2 for eps > 0 and no
// force when slack (MoorDyn's "a cable cannot push", Hall & Goupee 2015), with Kelvin-Voigt
// damping c dL/dt while taut. A linear twine has c1 = EA, c2 = 0; REEF3D's nylon law is
// c1 = 1160 N, c2 = 37300 N. Host and device share these definitions.
#include <algorithm>

#include "netsph/core/host_device.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

struct TwineLaw {
  double c1 = 0;  ///< N (EA for a linear twine)
  double c2 = 0;  ///< N
};

/// Tension, N, at strain eps = (L - L0) / L0; zero when slack.
NETSPH_HD double twine_tension(const TwineLaw& law, double strain) {
  return strain > 0 ? strain * (law.c1 + law.c2 * strain) : 0.0;
}

/// dT/dL, N/m, at strain eps for rest length L0 (the slack branch counts as taut so that time
/// steps stay safe when a twine is about to tighten).
NETSPH_HD double twine_tangent_stiffness(const TwineLaw& law, double strain, double rest) {
  const double e = strain > 0 ? strain : 0.0;
  return (law.c1 + 2 * law.c2 * e) / rest;
}

/// Strain energy, J: the integral of T dL from L0 to L.
NETSPH_HD double twine_energy(const TwineLaw& law, double strain, double rest) {
  if (strain <= 0) return 0.0;
  return rest * strain * strain * (law.c1 / 2 + law.c2 * strain / 3);
}

/// Force on end a of a twine from a to b, N: tension plus damping along the twine, never
/// pushing. `damping` in N s/m.
NETSPH_HD Vec3d twine_force_on_a(const TwineLaw& law, double rest, double damping, const Vec3d& xa,
                                 const Vec3d& xb, const Vec3d& va, const Vec3d& vb) {
  const Vec3d d = xb - xa;
  const double length = norm(d);
  const double strain = (length - rest) / rest;
  if (strain <= 0 || length <= 0) return {};
  const Vec3d e = d / length;
  const double tension = twine_tension(law, strain) + damping * dot(vb - va, e);
  return e * (tension > 0 ? tension : 0.0);
}

}  // namespace netsph
