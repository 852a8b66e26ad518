#include "netsph/boundary/open_boundary.hpp"

#include <cmath>

namespace netsph {

Vec3f OpenBoundaryZone::imposed_velocity(const Vec3d& p) const {
  const double u = inflow_speed(speed, profile_z.data(), profile_u.data(), profile_z.size(), p.z);
  // Inlets push into the domain, outlets draw out of it.
  return buffer_velocity(axis, inward, inlet, u);
}

int zone_containing(const std::vector<OpenBoundaryZone>& zones, const Vec3d& p) {
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const double d = zones[z].depth(p);
    if (d >= 0 && d <= zones[z].width) return static_cast<int>(z);
  }
  return -1;
}

OpenBoundaryCounts update_open_boundary_particles(ParticleSet& p,
                                                  const std::vector<OpenBoundaryZone>& zones,
                                                  OpenBoundaryEvents* events) {
  OpenBoundaryCounts counts;
  if (events) events->created_from.clear(), events->removed.clear();
  if (zones.empty()) return counts;
  std::vector<ZoneGeometry> geo;
  for (const OpenBoundaryZone& z : zones) geo.push_back(z.geometry());
  const std::size_t n = p.size();  // particles appended below are not revisited
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t entered = 0;
    const std::size_t counted = !events || !events->counted || events->counted[i];
    switch (buffer_transition(geo.data(), geo.size(), p.kind[i], p.group[i], p.pos[i], entered)) {
      case BufferTransition::None:
        break;
      case BufferTransition::ToFluidAndCreate: {
        // Copies, not references: add() may reallocate the arrays.
        const Vec3d behind = created_buffer_position(geo[p.group[i]], p.pos[i]);
        const Vec3f v = p.vel[i];
        const Real rho = p.rho[i];
        p.add(behind, v, rho, ParticleKind::Buffer, p.group[i]);
        counts.created += counted;
        if (events) events->created_from.push_back(p.id[i]);
        [[fallthrough]];
      }
      case BufferTransition::ToFluid:
        p.kind[i] = ParticleKind::Fluid;
        p.group[i] = 0;
        counts.entered_fluid += counted;
        break;
      case BufferTransition::Remove:
        p.pos[i] = {nan, nan, nan};
        counts.removed += counted;
        if (events && counted) events->removed.push_back(p.id[i]);
        break;
      case BufferTransition::ToBuffer:
        p.kind[i] = ParticleKind::Buffer;
        p.group[i] = entered;
        counts.absorbed += counted;
        break;
    }
  }
  return counts;
}

}  // namespace netsph
