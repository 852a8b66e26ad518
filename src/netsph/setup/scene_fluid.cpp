#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/setup/hydrostatic_check.hpp"
#include "netsph/setup/mach_check.hpp"
#include "netsph/setup/scene_builders.hpp"

// The fluid of a scene: its model (sound speed from the depth) and the fills' particles.
namespace netsph {
namespace scene_build {
namespace {

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

}  // namespace

LatticeBox lattice_box(const BoxSpec& b, int dims) {
  return {b.min, b.max, dims};
}

double surface_of(const FillSpec& f, double dp, int dims) {
  return f.surface_z ? *f.surface_z : lattice_max(lattice_box(f.box, dims), dp).z;
}

Real hydrostatic_density(const TaitEos& eos, double gz, double surface, double z) {
  const double p = -static_cast<double>(eos.rho0) * gz * (surface - z);
  return static_cast<Real>(p > 0 ? eos.density(p) : static_cast<double>(eos.rho0));
}

double set_fluid_model(const CaseSpec& spec, Scene& scene) {
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
  return top_surface;
}

void add_background_pressure_warning(const CaseSpec& spec, Scene& scene) {
  if (spec.fluid.background_pressure > 0 && norm2(spec.fluid.gravity) > 0) {
    scene.warnings.push_back(fmt::format(
        "fluid.background_pressure = {} Pa with gravity: a free surface must have zero "
        "pressure, and with a background its particles push apart. Use a background only when "
        "the fluid fills a closed duct",
        spec.fluid.background_pressure));
  }
}

void add_fills(const CaseSpec& spec, Scene& scene, const AxisRange& near) {
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;
  const TaitEos& eos = scene.model.eos;
  const double gz = spec.fluid.gravity.z;
  ParticleSet& p = scene.particles;
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
}

}  // namespace scene_build

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

}  // namespace netsph
