#include "netsph/setup/scene.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "netsph/core/periodic_image.hpp"
#include "netsph/setup/half_spacing_search.hpp"
#include "netsph/setup/scene_builders.hpp"
#include "netsph/setup/solid_overlaps.hpp"

namespace netsph {
namespace {

/// Body particles past a periodic end moved into the period by whole periods, as the solver
/// keeps them (a body may straddle the end; its centre of mass stays where the case put it).
void wrap_body_particles(const CaseSpec& spec, ParticleSet& p) {
  for (int a = 0; a < 3; ++a) {
    const double lo = spec.domain.min[a], period = spec.domain.period(a);
    if (!(period > 0)) continue;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.kind[i] != ParticleKind::Body) continue;
      p.pos[i][a] = wrapped_into_period(p.pos[i][a], lo, period);
    }
  }
}

/// Drops fluid particles closer than dp/2 to a kept particle created before them (walls first,
/// then earlier fills): overlapping boxes must not double the mass. In creation order, so the
/// result is the same whatever the grid: a particle removed removes nothing after it.
std::size_t remove_overlaps(ParticleSet& p, const HalfSpacingSearch& search) {
  const auto overlaps_earlier = [&](std::uint32_t a, const std::vector<char>* keep) {
    return search.find(a, [&](std::uint32_t b) { return b < a && (!keep || (*keep)[b]); }) >= 0;
  };
  // Whose fate can depend on others: fluid particles with an earlier particle within dp/2.
  // Finding them is the O(n) part, independent per particle, so it runs in parallel (a set-up
  // of 1e8 particles spent seconds here on one thread).
  const auto n = static_cast<std::int64_t>(p.size());
  std::vector<char> maybe(p.size(), 0);
#pragma omp parallel for schedule(dynamic, 4096)
  for (std::int64_t a = 0; a < n; ++a) {
    const auto au = static_cast<std::uint32_t>(a);
    maybe[au] = is_fluid(p.kind[au]) && overlaps_earlier(au, nullptr);
  }
  // Then those few in creation order, against the particles still kept.
  std::vector<char> keep(p.size(), 1);
  for (std::uint32_t a = 0; a < p.size(); ++a)
    if (maybe[a] && overlaps_earlier(a, &keep)) keep[a] = 0;
  const auto removed = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 0));
  if (removed == 0) return 0;
  p.keep_only(keep);
  return removed;
}

}  // namespace

Scene build_scene(const CaseSpec& spec) {
  return build_scene_part(spec, AxisRange{}, {});
}

Scene build_scene_part(const CaseSpec& spec, const AxisRange& region,
                       const WholeBounds& whole_bounds) {
  using namespace scene_build;
  Scene scene;
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;

  const double top_surface = set_fluid_model(spec, scene);

  add_wall_warnings(spec, scene);
  add_background_pressure_warning(spec, scene);
  add_open_boundary_zones(spec, scene, top_surface);
  add_damping_zones(spec, scene);
  check_waves(spec, scene);

  ParticleSet& p = scene.particles;
  // The particles near the region too: whether a fluid particle overlaps an earlier one
  // (remove_overlaps) depends on particles within dp/2, whose own fate depends on earlier
  // sources within dp/2 of them, a chain at most as long as the fills are many (walls and
  // bodies are never removed; one fill's lattice never overlaps itself).
  const double margin = static_cast<double>(spec.fills.size() + 1) * dp;
  const AxisRange near{region.axis, region.lo - margin, region.hi + margin};
  add_walls(spec, scene, near, top_surface);
  add_bodies(spec, scene);
  add_fills(spec, scene, near);
  // The removals counted in the region only (a part's margin belongs to its neighbours).
  const auto fluid_in_region = [&p, &region] {
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      n += is_fluid(p.kind[i]) && region.contains(p.pos[i]);
    return n;
  };
  const std::size_t fluid_generated = fluid_in_region();
  remove_fluid_in_bodies(spec, scene);
  const std::size_t fluid_outside_bodies = fluid_in_region();
  scene.removed_in_bodies = fluid_generated - fluid_outside_bodies;
  wrap_body_particles(spec, p);

  const auto [lo, hi] = set_domain(spec, scene, whole_bounds);

  if (p.size() > 0) {
    const Vec3d glo = lo - Vec3d(dp, dp, dp), ghi = hi + Vec3d(dp, dp, dp);
    const HalfSpacingSearch search(p, dp, glo, ghi, dims);
    if (!scene.bodies.empty()) {
      scene.solid_overlaps = find_solid_overlaps(
          p, search, scene.bodies, [&](const Vec3d& x) { return region.contains(x); });
    }
    remove_overlaps(p, search);
    scene.removed_overlaps = fluid_outside_bodies - fluid_in_region();
  }
  if (!region.everything()) {
    std::vector<char> keep(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keep[i] = region.contains(p.pos[i]);
    p.keep_only(keep);
  }
  p.shrink_to_fit();
  scene.buffer_counts.assign(scene.zones.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.kind[i] == ParticleKind::Buffer) ++scene.buffer_counts[p.group[i]];
  if (region.everything()) report_particle_counts(scene, spec);
  return scene;
}

void report_particle_counts(Scene& scene, const CaseSpec& spec) {
  for (std::string& w : solid_overlap_warnings(scene.solid_overlaps, spec, scene.bodies))
    scene.warnings.push_back(std::move(w));
  for (std::size_t z = 0; z < scene.zones.size(); ++z) {
    if (scene.buffer_counts.at(z) == 0) {
      scene.warnings.push_back(
          fmt::format("{} '{}' starts with no buffer particles: no fill reaches its face",
                      scene.zones[z].inlet ? "inlet" : "outlet", scene.zones[z].name));
    }
    scene.sources.push_back({scene.zones[z].name + " (buffer)", scene.buffer_counts[z]});
  }
  if (scene.removed_overlaps > 0) {
    scene.warnings.push_back(fmt::format(
        "{} fluid particles overlapped walls or earlier fills (closer than dp/2) and were removed",
        scene.removed_overlaps));
  }
}

Scene Scene::without_particles() const {
  Scene s;
  s.particles.next_id = particles.next_id;
  s.model = model;
  s.sound_speed = sound_speed;
  s.fluid_depth = fluid_depth;
  s.domain_min = domain_min, s.domain_max = domain_max;
  s.zones = zones;
  s.bodies = bodies;
  s.damping = damping;
  s.sources = sources;
  s.removed_overlaps = removed_overlaps;
  s.removed_in_bodies = removed_in_bodies;
  s.buffer_counts = buffer_counts;
  s.thickened_bodies = thickened_bodies;
  s.solid_overlaps = solid_overlaps;
  s.warnings = warnings;
  return s;
}

}  // namespace netsph
