#pragma once
// Open boundaries after Tafuni et al. (2018): a buffer of particle layers inside the domain
// along one face. The buffer-fluid interface is a plane `width` = layers * dp inside the face.
//
// Each step (before the sort):
//   - a buffer particle that crossed the interface into the fluid becomes fluid; at an inlet a
//     new buffer particle takes its place one buffer width behind it (below the free surface);
//   - a buffer particle deeper than the buffer width has left the domain: it is removed (at an
//     outlet also one exactly on the face);
//   - a fluid particle that enters a buffer becomes a buffer particle of that zone (this is
//     how outlets take the outflow; at an inlet it catches backflow).
// After the sort the buffer particles get their state: imposed velocity at inlets (uniform or
// a profile over z), extrapolated velocity at outlets unless imposed; density hydrostatic or
// extrapolated from the ghost node mirrored across the interface (sph/ghost_interpolation.hpp).
// Within the step buffer particles move with that velocity and keep their state.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "netsph/core/host_device.hpp"
#include "netsph/core/physics_options.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/equation_of_state.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

// The formulas of the buffers, for both backends.

/// Depth of p into a buffer whose interface lies at `plane` on `axis`, the buffer on the side
/// `inward` points away from: 0 at the interface, the buffer width at the domain face, < 0 in
/// the fluid.
NETSPH_HD double buffer_depth(int axis, double inward, double plane, const Vec3d& p) {
  return (plane - p[axis]) * inward;
}

/// Speed at height z of a piecewise-linear inflow profile (n points, z increasing; constant
/// beyond the ends), or `speed` when there is no profile (n == 0).
NETSPH_HD double inflow_speed(double speed, const double* pz, const double* pu, std::size_t n,
                              double z) {
  if (n == 0) return speed;
  if (z <= pz[0]) return pu[0];
  if (z >= pz[n - 1]) return pu[n - 1];
  for (std::size_t k = 1; k < n; ++k) {
    if (z <= pz[k]) {
      const double w = (z - pz[k - 1]) / (pz[k] - pz[k - 1]);
      return pu[k - 1] * (1 - w) + pu[k] * w;
    }
  }
  return pu[n - 1];
}

/// Density of a buffer particle at height z under a free surface at surface_z in hydrostatic
/// equilibrium with gravity gz (< 0); rho0 above the surface.
NETSPH_HD Real hydrostatic_buffer_density(const TaitEos& eos, double gz, double surface_z,
                                          double z) {
  const double pressure = -static_cast<double>(eos.rho0) * gz * (surface_z - z);
  return static_cast<Real>(pressure > 0 ? eos.density(pressure) : eos.rho0);
}

/// Velocity imposed in a buffer: `u` into the domain at an inlet, out of it at an outlet.
NETSPH_HD Vec3f buffer_velocity(int axis, double inward, bool inlet, double u) {
  Vec3d v{};
  v[axis] = inward * (inlet ? u : -u);
  return Vec3f(v);
}

/// The numbers of a zone the transitions need, as a plain struct a kernel can take.
struct ZoneGeometry {
  bool inlet = true;
  int axis = 0;
  double inward = 1, plane = 0, width = 0;
  double surface_z = 0;
  /// the domain's face on axis: plane - inward * width up to round-off (NaN: not set, only
  /// the depth rule applies)
  double face = std::numeric_limits<double>::quiet_NaN();
};

/// What happens to a particle at the start of a step (the rules above).
enum class BufferTransition : std::uint8_t {
  None,
  ToFluid,           ///< a buffer particle crossed into the fluid
  ToFluidAndCreate,  ///< ... at an inlet, below its surface: a new buffer particle behind it
  Remove,            ///< a buffer particle left through the domain face
  ToBuffer,          ///< a fluid particle entered a buffer
};

/// The transition of a particle of kind k at p; a buffer particle's zone is `group`. For
/// ToBuffer, `zone` receives the zone entered (the first of `zones` whose buffer holds p).
NETSPH_HD BufferTransition buffer_transition(const ZoneGeometry* zones, std::size_t nzones,
                                             ParticleKind k, std::uint32_t group, const Vec3d& p,
                                             std::uint32_t& zone) {
  if (k == ParticleKind::Buffer) {
    const ZoneGeometry& z = zones[group];
    const double d = buffer_depth(z.axis, z.inward, z.plane, p);
    if (d < 0) {
      return z.inlet && p.z <= z.surface_z ? BufferTransition::ToFluidAndCreate
                                           : BufferTransition::ToFluid;
    }
    // A particle outside the domain's half-open range [min, max) along the axis has left, as
    // the step start's periodic wrap sees it (it compares with the faces themselves, not with
    // plane and width, which round): also one exactly on a max face, which the wrap would
    // carry to the far face and into the fluid there. created_buffer_position keeps new inlet
    // particles inside the range.
    const bool outside = z.inward > 0 ? p[z.axis] < z.face : p[z.axis] >= z.face;
    return d > z.width || outside ? BufferTransition::Remove : BufferTransition::None;
  }
  if (k == ParticleKind::Fluid) {
    for (std::size_t i = 0; i < nzones; ++i) {
      const double d = buffer_depth(zones[i].axis, zones[i].inward, zones[i].plane, p);
      if (d >= 0 && d <= zones[i].width) {
        zone = static_cast<std::uint32_t>(i);
        return BufferTransition::ToBuffer;
      }
    }
  }
  return BufferTransition::None;
}

/// Where an inlet creates the buffer particle that replaces one entering the fluid at p: one
/// buffer width behind it, inside the domain's half-open range [min, max) along the axis (p
/// only just across the interface can put it on the face by round-off).
NETSPH_HD Vec3d created_buffer_position(const ZoneGeometry& z, const Vec3d& p) {
  Vec3d q = p;
  q[z.axis] -= z.inward * z.width;
  if (z.inward > 0 && q[z.axis] < z.face) q[z.axis] = z.face;
  if (z.inward < 0 && q[z.axis] >= z.face) q[z.axis] = std::nextafter(z.face, -INFINITY);
  return q;
}

struct OpenBoundaryZone {
  std::string name;
  bool inlet = true;
  int axis = 0;       ///< 0 x, 1 y, 2 z
  double inward = 1;  ///< +1: the zone is on the min face (flow into +axis), -1: max face
  double plane = 0;   ///< coordinate of the buffer-fluid interface along axis, m
  double width = 0;   ///< buffer width, m
  double face = std::numeric_limits<double>::quiet_NaN();  ///< the domain face the buffer is on, m
  bool velocity_imposed = true;
  double speed = 0;                          ///< m/s, normal speed (into the domain at inlets)
  std::vector<double> profile_z, profile_u;  ///< inlet profile over z, piecewise linear
  BufferDensity density = BufferDensity::Extrapolated;
  double surface_z = std::numeric_limits<double>::infinity();  ///< no particles created above

  /// Depth of p into the buffer: 0 at the interface, `width` at the domain face, < 0 in the fluid.
  double depth(const Vec3d& p) const { return buffer_depth(axis, inward, plane, p); }
  ZoneGeometry geometry() const { return {inlet, axis, inward, plane, width, surface_z, face}; }
  /// Unit vector into the domain.
  Vec3d inward_normal() const {
    Vec3d n{};
    n[axis] = inward;
    return n;
  }
  /// Ghost node of a buffer particle: its mirror across the interface.
  Vec3d ghost_of(const Vec3d& p) const { return p + inward_normal() * (2 * depth(p)); }
  /// The imposed velocity at p (inlets: into the domain; outlets: out of it).
  Vec3f imposed_velocity(const Vec3d& p) const;
};

struct OpenBoundaryCounts {
  std::size_t entered_fluid = 0;  ///< buffer -> fluid
  std::size_t created = 0;        ///< new inlet buffer particles
  std::size_t removed = 0;        ///< buffer particles that left through the face
  std::size_t absorbed = 0;       ///< fluid -> buffer
};

/// For a process of a distributed run, which holds copies of other processes' particles:
/// which particles' events count, and what became of them.
struct OpenBoundaryEvents {
  const std::uint8_t* counted = nullptr;    ///< in: per particle, whose events count (null: all)
  std::vector<std::uint32_t> created_from;  ///< out: the parent's id of each created particle
  std::vector<std::uint32_t> removed;       ///< out: ids of counted particles removed
};

/// Applies the conversions, creations and removals above. Removed particles get a NaN
/// position, so the next sort drops them; created particles are appended with new ids.
/// `events` (may be null) limits the counts and reports parents and removals.
OpenBoundaryCounts update_open_boundary_particles(ParticleSet& p,
                                                  const std::vector<OpenBoundaryZone>& zones,
                                                  OpenBoundaryEvents* events = nullptr);

/// The zone whose buffer contains p (0 <= depth <= width), or -1.
int zone_containing(const std::vector<OpenBoundaryZone>& zones, const Vec3d& p);

}  // namespace netsph
