#include <algorithm>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/setup/scene_builders.hpp"

// The domain of a scene: the case's, checked against every particle, or the default around
// them.
namespace netsph::scene_build {

std::pair<Vec3d, Vec3d> set_domain(const CaseSpec& spec, Scene& scene,
                                   const WholeBounds& whole_bounds) {
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;
  const ParticleSet& p = scene.particles;
  // Bounding box of the particles, for the default domain and the overlap search (of the
  // part near the region; the particles past it are the whole scene's too, so the
  // processes' boxes make up the whole scene's).
  const double inf = std::numeric_limits<double>::infinity();
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (const auto& x : p.pos)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], x[a]), hi[a] = std::max(hi[a], x[a]);
  Vec3d whole_lo = lo, whole_hi = hi;
  if (whole_bounds) whole_bounds(whole_lo, whole_hi);
  if (!(whole_lo.x <= whole_hi.x)) throw Error(spec.source, "the case creates no particles");

  const double h = spec.simulation.h_over_dp * dp;
  if (spec.domain.given) {
    scene.domain_min = spec.domain.min;
    scene.domain_max = spec.domain.max;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3d& x = p.pos[i];
      const bool inside = x.x >= scene.domain_min.x && x.x < scene.domain_max.x &&
                          x.z >= scene.domain_min.z && x.z < scene.domain_max.z &&
                          (dims == 2 || (x.y >= scene.domain_min.y && x.y < scene.domain_max.y));
      if (!inside) {
        // Name the wall or body (its table's line) and the extent the domain must hold: a
        // [domain] equal to a tank's box leaves the wall layers outside it.
        std::string where = spec.source, what{name_of(kParticleKindSources, p.kind[i])};
        if (p.kind[i] == ParticleKind::Wall && p.group[i] < spec.walls.size()) {
          where = spec.walls[p.group[i]].where.str();
          what = "wall '" + spec.walls[p.group[i]].name + "'";
        } else if (p.kind[i] == ParticleKind::Body && p.group[i] < spec.bodies.size()) {
          where = spec.bodies[p.group[i]].where.str();
          what = "body '" + spec.bodies[p.group[i]].name + "'";
        }
        throw Error(where,
                    fmt::format("a particle of {} at ({:.4g}, {:.4g}, {:.4g}) m lies outside "
                                "[domain] ({:.4g}, {:.4g}, {:.4g}) .. ({:.4g}, {:.4g}, {:.4g}) m; "
                                "the case's particles (wall layers included) span ({:.4g}, "
                                "{:.4g}, {:.4g}) .. ({:.4g}, {:.4g}, {:.4g}) m: enlarge the "
                                "domain to hold them, or move the {}",
                                what, x.x, x.y, x.z, scene.domain_min.x, scene.domain_min.y,
                                scene.domain_min.z, scene.domain_max.x, scene.domain_max.y,
                                scene.domain_max.z, whole_lo.x, whole_lo.y, whole_lo.z, whole_hi.x,
                                whole_hi.y, whole_hi.z, name_of(kParticleKindSources, p.kind[i])));
      }
    }
  } else {
    // Default: the particles' bounding box plus 2h around it, and as much again above it so
    // that splashes are not cut off.
    scene.domain_min = whole_lo - Vec3d(2 * h, 2 * h, 2 * h);
    scene.domain_max = whole_hi + Vec3d(2 * h, 2 * h, 2 * h);
    scene.domain_max.z += whole_hi.z - whole_lo.z;
    if (dims == 2) scene.domain_min.y = scene.domain_max.y = 0;
  }
  return {lo, hi};
}

}  // namespace netsph::scene_build
