#include "netsph/boundary/open_boundary.hpp"

#include <cmath>

namespace netsph {

Vec3f OpenBoundaryZone::imposed_velocity(const Vec3d& p) const {
  double u = speed;
  if (!profile_z.empty()) {
    const double z = p.z;
    if (z <= profile_z.front()) {
      u = profile_u.front();
    } else if (z >= profile_z.back()) {
      u = profile_u.back();
    } else {
      for (std::size_t k = 1; k < profile_z.size(); ++k) {
        if (z <= profile_z[k]) {
          const double w = (z - profile_z[k - 1]) / (profile_z[k] - profile_z[k - 1]);
          u = profile_u[k - 1] * (1 - w) + profile_u[k] * w;
          break;
        }
      }
    }
  }
  // Inlets push into the domain, outlets draw out of it.
  return Vec3f(inward_normal() * (inlet ? u : -u));
}

int zone_containing(const std::vector<OpenBoundaryZone>& zones, const Vec3d& p) {
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const double d = zones[z].depth(p);
    if (d >= 0 && d <= zones[z].width) return static_cast<int>(z);
  }
  return -1;
}

OpenBoundaryCounts update_open_boundary_particles(ParticleSet& p,
                                                  const std::vector<OpenBoundaryZone>& zones) {
  OpenBoundaryCounts counts;
  if (zones.empty()) return counts;
  const std::size_t n = p.size();  // particles appended below are not revisited
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    if (p.kind[i] == ParticleKind::Buffer) {
      const OpenBoundaryZone& z = zones[p.group[i]];
      const double d = z.depth(p.pos[i]);
      if (d < 0) {
        const std::uint32_t zone = p.group[i];
        p.kind[i] = ParticleKind::Fluid;
        p.group[i] = 0;
        ++counts.entered_fluid;
        if (z.inlet && p.pos[i].z <= z.surface_z) {
          // Copies, not references: add() may reallocate the arrays.
          const Vec3d behind = p.pos[i] - z.inward_normal() * z.width;
          const Vec3f v = p.vel[i];
          const Real rho = p.rho[i];
          p.add(behind, v, rho, ParticleKind::Buffer, zone);
          ++counts.created;
        }
      } else if (d > z.width) {
        p.pos[i] = {nan, nan, nan};
        ++counts.removed;
      }
    } else if (p.kind[i] == ParticleKind::Fluid) {
      const int z = zone_containing(zones, p.pos[i]);
      if (z >= 0) {
        p.kind[i] = ParticleKind::Buffer;
        p.group[i] = static_cast<std::uint32_t>(z);
        ++counts.absorbed;
      }
    }
  }
  return counts;
}

}  // namespace netsph
