#include "netsph/setup/scene_builders.hpp"

// The open boundaries' zones of a scene (their buffer particles come from the fills).
namespace netsph::scene_build {
namespace {

OpenBoundaryZone make_zone(const OpenBoundarySpec& o, bool inlet, const CaseSpec& spec,
                           double default_surface) {
  OpenBoundaryZone z;
  z.name = o.name;
  z.inlet = inlet;
  z.axis = static_cast<int>(o.face) / 2;
  const bool min_face = static_cast<int>(o.face) % 2 == 0;
  z.inward = min_face ? 1.0 : -1.0;
  z.width = o.layers * spec.simulation.dp;
  z.face = min_face ? spec.domain.min[z.axis] : spec.domain.max[z.axis];
  z.plane = z.face + z.inward * z.width;
  z.velocity_imposed = inlet || o.velocity.has_value();
  z.speed = o.velocity.value_or(0.0);
  z.profile_z = o.profile_z;
  z.profile_u = o.profile_u;
  z.density = o.density;
  z.surface_z = o.surface_z.value_or(default_surface);
  return z;
}

}  // namespace

void add_open_boundary_zones(const CaseSpec& spec, Scene& scene, double top_surface) {
  for (const auto& o : spec.inlets) scene.zones.push_back(make_zone(o, true, spec, top_surface));
  for (const auto& o : spec.outlets) scene.zones.push_back(make_zone(o, false, spec, top_surface));
}

}  // namespace netsph::scene_build
