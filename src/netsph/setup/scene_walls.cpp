#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "netsph/boundary/wall_ghosts.hpp"
#include "netsph/setup/scene_builders.hpp"

// The walls of a scene: their particles (a process's share, near its region) and the warnings
// on their settings.
namespace netsph::scene_build {
namespace {

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

}  // namespace

void add_wall_warnings(const CaseSpec& spec, Scene& scene) {
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
}

void add_walls(const CaseSpec& spec, Scene& scene, const AxisRange& near, double top_surface) {
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;
  const TaitEos& eos = scene.model.eos;
  const double gz = spec.fluid.gravity.z;
  ParticleSet& p = scene.particles;
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
}

}  // namespace netsph::scene_build
