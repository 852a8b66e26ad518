#pragma once
// Open boundaries after Tafuni et al. (2018): a buffer of particle layers inside the domain
// along one face. The buffer-fluid interface is a plane `width` = layers * dp inside the face.
//
// Each step (before the sort):
//   - a buffer particle that crossed the interface into the fluid becomes fluid; at an inlet a
//     new buffer particle takes its place one buffer width behind it (below the free surface);
//   - a buffer particle deeper than the buffer width has left the domain: it is removed;
//   - a fluid particle that enters a buffer becomes a buffer particle of that zone (this is
//     how outlets take the outflow; at an inlet it catches backflow).
// After the sort the buffer particles get their state: imposed velocity at inlets (uniform or
// a profile over z), extrapolated velocity at outlets unless imposed; density hydrostatic or
// extrapolated from the ghost node mirrored across the interface (sph/ghost_interpolation.hpp).
// Within the step buffer particles move with that velocity and keep their state.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "netsph/core/physics_options.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

struct OpenBoundaryZone {
  std::string name;
  bool inlet = true;
  int axis = 0;       ///< 0 x, 1 y, 2 z
  double inward = 1;  ///< +1: the zone is on the min face (flow into +axis), -1: max face
  double plane = 0;   ///< coordinate of the buffer-fluid interface along axis, m
  double width = 0;   ///< buffer width, m
  bool velocity_imposed = true;
  double speed = 0;                          ///< m/s, normal speed (into the domain at inlets)
  std::vector<double> profile_z, profile_u;  ///< inlet profile over z, piecewise linear
  BufferDensity density = BufferDensity::Extrapolated;
  double surface_z = std::numeric_limits<double>::infinity();  ///< no particles created above

  /// Depth of p into the buffer: 0 at the interface, `width` at the domain face, < 0 in the fluid.
  double depth(const Vec3d& p) const { return (plane - p[axis]) * inward; }
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

/// Applies the conversions, creations and removals above. Removed particles get a NaN
/// position, so the next sort drops them; created particles are appended with new ids.
OpenBoundaryCounts update_open_boundary_particles(ParticleSet& p,
                                                  const std::vector<OpenBoundaryZone>& zones);

/// The zone whose buffer contains p (0 <= depth <= width), or -1.
int zone_containing(const std::vector<OpenBoundaryZone>& zones, const Vec3d& p);

}  // namespace netsph
