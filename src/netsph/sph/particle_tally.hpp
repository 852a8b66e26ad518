#pragma once
// The global measures of a run's particles (series rows, the summary's final state) as a
// reduction: what one particle contributes and how two partial tallies combine. The CPU's
// OpenMP loop (run/output_particles.cpp) and the device step's block reduction
// (backend/device/device_stepper.hpp) both reduce with these two functions, so the device
// backends measure a run without copying its particles back.
#include <cstdint>
#include <limits>

#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// The empty tally's density bounds: any fluid particle's density replaces them.
inline constexpr double kTallyNoDensity = std::numeric_limits<double>::infinity();

struct ParticleTally {
  std::uint64_t fluid = 0, walls = 0, buffer = 0;  ///< particles of each kind (bodies apart)
  double kinetic_energy = 0;                       ///< J (J/m in 2D), fluid only
  double max_speed2 = 0;                           ///< m^2/s^2, fluid only
  double min_density = kTallyNoDensity;            ///< kg/m^3, fluid only
  double max_density = -kTallyNoDensity;
};

/// The tally of one particle of mass `mass`: kinetic energy 1/2 m |v|^2 (Monaghan 2005,
/// section 2.4, the SPH sum of the continuum's 1/2 rho |v|^2) and the extremes of the fluid.
NETSPH_HD ParticleTally tally_particle(ParticleKind k, const Vec3f& v, Real rho, double mass) {
  ParticleTally t;
  t.walls = k == ParticleKind::Wall;
  t.buffer = k == ParticleKind::Buffer;
  if (!is_fluid(k)) return t;
  const double v2 = norm2(Vec3d(v));
  t.fluid = 1;
  t.kinetic_energy = 0.5 * mass * v2;
  t.max_speed2 = v2;
  t.min_density = t.max_density = rho;
  return t;
}

/// The larger of a and b, passing over a NaN (as std::max(a, b) does when b is the NaN, and
/// whichever side a reduction tree puts it on): a NaN particle shows in the kinetic energy's
/// sum, the finite-state check reports it.
NETSPH_HD double tally_max(double a, double b) {
  if (!(a == a)) return b;
  if (!(b == b)) return a;
  return a < b ? b : a;
}

NETSPH_HD ParticleTally merge_tallies(const ParticleTally& a, const ParticleTally& b) {
  ParticleTally t;
  t.fluid = a.fluid + b.fluid;
  t.walls = a.walls + b.walls;
  t.buffer = a.buffer + b.buffer;
  t.kinetic_energy = a.kinetic_energy + b.kinetic_energy;
  t.max_speed2 = tally_max(a.max_speed2, b.max_speed2);
  t.min_density = -tally_max(-a.min_density, -b.min_density);
  t.max_density = tally_max(a.max_density, b.max_density);
  return t;
}

/// merge_tallies as a function object (the device reduction's operator).
struct MergeTallies {
  NETSPH_HD ParticleTally operator()(const ParticleTally& a, const ParticleTally& b) const {
    return merge_tallies(a, b);
  }
};

}  // namespace netsph
