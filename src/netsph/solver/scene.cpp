#include "netsph/solver/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "netsph/boundary/wall_ghosts.hpp"
#include "netsph/core/error.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/geometry/box_lattice.hpp"
#include "netsph/neighbors/cell_grid.hpp"
#include "netsph/solver/half_spacing_search.hpp"
#include "netsph/solver/hydrostatic_check.hpp"
#include "netsph/solver/mach_check.hpp"
#include "netsph/solver/solid_overlaps.hpp"

namespace netsph {
namespace {

LatticeBox lattice_box(const BoxSpec& b, int dims) {
  return {b.min, b.max, dims};
}

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

const char* kind_name(ParticleKind k) {
  switch (k) {
    case ParticleKind::Fluid:
      return "fill";
    case ParticleKind::Wall:
      return "wall";
    case ParticleKind::Buffer:
      return "open-boundary buffer";
    case ParticleKind::Body:
      return "body";
  }
  return "particle";
}

/// Free-surface height of a fill: given, or the top of its particle lattice.
double surface_of(const FillSpec& f, double dp, int dims) {
  return f.surface_z ? *f.surface_z : lattice_max(lattice_box(f.box, dims), dp).z;
}

/// Hydrostatic density at height z below a surface (Tait inverted), rho0 above it.
Real hydrostatic_density(const TaitEos& eos, double gz, double surface, double z) {
  const double p = -static_cast<double>(eos.rho0) * gz * (surface - z);
  return static_cast<Real>(p > 0 ? eos.density(p) : static_cast<double>(eos.rho0));
}

double sound_speed_of(const CaseSpec& spec, double depth) {
  if (spec.fluid.sound_speed > 0) return spec.fluid.sound_speed;
  const double g = norm(spec.fluid.gravity);
  if (!(g > 0) || !(depth > 0)) {
    throw Error(spec.source,
                "fluid.sound_speed_coef needs gravity and a fluid depth to set c0 = "
                "coef * sqrt(|g| H); give fluid.sound_speed (m/s) instead");
  }
  return spec.fluid.sound_speed_coef * std::sqrt(g * depth);
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

/// A wall face across a periodic axis that spans the water's whole cross-section (the fills'
/// extent on the other axes): no water can cross the period there, which a periodic axis is
/// for (a tank's end walls left in after making its axis periodic). A wall across part of it
/// is an obstacle, and fine.
std::optional<std::string> periodic_barrier(const CaseSpec& spec, const WallSpec& w) {
  const DomainSpec& d = spec.domain;
  if (!d.given || spec.fills.empty()) return std::nullopt;
  const double dp = spec.simulation.dp;
  Vec3d lo = spec.fills[0].box.min, hi = spec.fills[0].box.max;
  for (const FillSpec& f : spec.fills) {
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], f.box.min[a]), hi[a] = std::max(hi[a], f.box.max[a]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!d.periodic[static_cast<std::size_t>(axis)]) continue;
    const int face = 2 * axis;
    if (!w.faces[static_cast<std::size_t>(face)] && !w.faces[static_cast<std::size_t>(face + 1)])
      continue;
    bool spans = true;
    for (int b = 0; b < 3; ++b) {
      if (b == axis || (spec.simulation.dimensions == 2 && b == 1)) continue;
      spans &= w.box.min[b] <= lo[b] + dp && w.box.max[b] >= hi[b] - dp;
    }
    if (!spans) continue;
    const char name = "xyz"[axis];
    return fmt::format(
        "wall '{}' closes the periodic axis {} with its face{} across all the water: none "
        "crosses the period there. Take the {}min/{}max faces out of the wall, or {} out of "
        "domain.periodic",
        w.name, name,
        w.faces[static_cast<std::size_t>(face)] && w.faces[static_cast<std::size_t>(face + 1)]
            ? fmt::format("s {0}min and {0}max", name)
            : fmt::format(" {}{}", name, w.faces[static_cast<std::size_t>(face)] ? "min" : "max"),
        name, name, name);
  }
  return std::nullopt;
}

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

FluidModel fluid_model_for(const CaseSpec& spec, double sound_speed) {
  FluidModelInput in;
  in.dims = spec.simulation.dimensions;
  in.dp = spec.simulation.dp;
  in.h_over_dp = spec.simulation.h_over_dp;
  in.kernel = spec.simulation.kernel;
  in.rho0 = spec.fluid.density;
  in.c0 = sound_speed;
  in.gamma = spec.fluid.gamma;
  in.p_background = spec.fluid.background_pressure;
  in.gravity = spec.fluid.gravity;
  in.viscosity = spec.fluid.viscosity;
  in.alpha = spec.fluid.alpha;
  in.nu = spec.fluid.kinematic_viscosity;
  in.diffusion = spec.fluid.density_diffusion;
  in.delta = spec.fluid.delta;
  return make_fluid_model(in);
}

Scene build_scene(const CaseSpec& spec) {
  return build_scene_part(spec, AxisRange{}, {});
}

Scene build_scene_part(const CaseSpec& spec, const AxisRange& region,
                       const WholeBounds& whole_bounds) {
  Scene scene;
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;

  double top_surface = -std::numeric_limits<double>::infinity();
  double water_top = top_surface, water_bottom = std::numeric_limits<double>::infinity();
  for (const auto& f : spec.fills) {
    const double s = surface_of(f, dp, dims);
    top_surface = std::max(top_surface, s);
    scene.fluid_depth = std::max(scene.fluid_depth, s - f.box.min.z);
    water_top = std::max(water_top, lattice_max(lattice_box(f.box, dims), dp).z);
    water_bottom = std::min(water_bottom, f.box.min.z);
  }
  scene.sound_speed = sound_speed_of(spec, scene.fluid_depth);
  scene.model = fluid_model_for(spec, scene.sound_speed);
  if (auto w = sound_speed_warning(spec, scene.fluid_depth, scene.sound_speed))
    scene.warnings.push_back(std::move(*w));
  for (std::string& w : hydrostatic_warnings(spec, water_top, water_bottom))
    scene.warnings.push_back(std::move(w));
  const TaitEos& eos = scene.model.eos;
  const double gz = spec.fluid.gravity.z;

  for (const auto& w : spec.walls) {
    if (w.model == WallModel::Mdbc && w.slip == WallSlip::NoSlip &&
        spec.fluid.viscosity == ViscosityModel::Artificial) {
      scene.warnings.push_back(fmt::format(
          "wall '{}': slip = \"no_slip\" with artificial viscosity; artificial viscosity acts only "
          "on approaching pairs, so the mirrored wall velocities drag the fluid next to the wall "
          "backwards and particles can leak into the wall. Use slip = \"wall_velocity\" (the "
          "default) or laminar viscosity",
          w.name));
    }
    if (auto barrier = periodic_barrier(spec, w)) scene.warnings.push_back(std::move(*barrier));
  }
  if (spec.fluid.background_pressure > 0 && norm2(spec.fluid.gravity) > 0) {
    scene.warnings.push_back(fmt::format(
        "fluid.background_pressure = {} Pa with gravity: a free surface must have zero "
        "pressure, and with a background its particles push apart. Use a background only when "
        "the fluid fills a closed duct",
        spec.fluid.background_pressure));
  }
  for (const auto& o : spec.inlets) scene.zones.push_back(make_zone(o, true, spec, top_surface));
  for (const auto& o : spec.outlets) scene.zones.push_back(make_zone(o, false, spec, top_surface));

  ParticleSet& p = scene.particles;
  // The particles near the region too: whether a fluid particle overlaps an earlier one
  // (remove_overlaps) depends on particles within dp/2, whose own fate depends on earlier
  // sources within dp/2 of them, a chain at most as long as the fills are many (walls and
  // bodies are never removed; one fill's lattice never overlaps itself).
  const double margin = static_cast<double>(spec.fills.size() + 1) * dp;
  const AxisRange near{region.axis, region.lo - margin, region.hi + margin};
  for (std::size_t wi = 0; wi < spec.walls.size(); ++wi) {
    const auto& w = spec.walls[wi];
    const LatticeBox box = lattice_box(w.box, dims);
    // Only the part near the region (a process's share of the walls in a distributed run).
    const LatticePart part = wall_box_layers_part(box, dp, w.faces, w.layers, near);
    const std::vector<Vec3d>& pts = part.points;
    std::vector<Vec3f> ghosts(pts.size());
    if (w.model == WallModel::Mdbc) {
      ghosts = box_wall_ghost_offsets(pts, box.min, lattice_max(box, dp), dims);
    }
    const Vec3f v0(w.motion.at(0.0));
    const std::uint32_t first_id = p.next_id;
    p.reserve_more(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) {
      // The id the whole scene gives it.
      p.next_id = first_id + static_cast<std::uint32_t>(part.index[k]);
      // Walls start hydrostatic with the highest free surface so that DBC does not need a
      // transient to build the pressure that holds the fluid up.
      p.add(pts[k], v0, hydrostatic_density(eos, gz, top_surface, pts[k].z), ParticleKind::Wall,
            static_cast<std::uint32_t>(wi), ghosts[k]);
    }
    p.next_id = first_id + static_cast<std::uint32_t>(part.total);
    scene.sources.push_back({w.name, part.total});
  }
  add_bodies(spec, scene);
  for (std::size_t i = 0; i < spec.fills.size(); ++i) {
    const auto& f = spec.fills[i];
    const LatticePart part = fill_box_part(lattice_box(f.box, dims), dp, near);
    const double surface = surface_of(f, dp, dims);
    const std::uint32_t first_id = p.next_id;
    p.reserve_more(part.points.size());
    for (std::size_t k = 0; k < part.points.size(); ++k) {
      const Vec3d& x = part.points[k];
      p.next_id = first_id + static_cast<std::uint32_t>(part.index[k]);
      const Real rho = hydrostatic_density(eos, gz, surface, x.z);
      const int z = zone_containing(scene.zones, x);
      if (z < 0) {
        p.add(x, Vec3f(f.velocity), rho, ParticleKind::Fluid);
      } else {
        // Fill particles that start inside an open boundary's buffer belong to it.
        const OpenBoundaryZone& zone = scene.zones[static_cast<std::size_t>(z)];
        const Vec3f v = zone.velocity_imposed ? zone.imposed_velocity(x) : Vec3f(f.velocity);
        p.add(x, v, rho, ParticleKind::Buffer, static_cast<std::uint32_t>(z));
      }
    }
    p.next_id = first_id + static_cast<std::uint32_t>(part.total);
    scene.sources.push_back({fmt::format("fill{}", i + 1), part.total});
  }
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
        std::string where = spec.source, what = kind_name(p.kind[i]);
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
                                whole_hi.y, whole_hi.z, kind_name(p.kind[i])));
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
