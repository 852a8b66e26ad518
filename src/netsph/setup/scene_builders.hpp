#pragma once
// The steps of build_scene_part (scene.cpp), one per thing it builds, in the files named:
// the fluid's model and fills (scene_fluid.cpp), the open boundaries' zones
// (scene_zones.cpp), the walls (scene_walls.cpp), the bodies (scene_bodies.cpp), the domain
// (scene_domain.cpp), the damping zones and the wave checks (scene_waves.cpp).
// Internal to setup/: other modules call build_scene or build_scene_part.
#include <utility>

#include "netsph/case/case_spec.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/geometry/box_lattice.hpp"
#include "netsph/setup/scene.hpp"
#include "netsph/sph/equation_of_state.hpp"

namespace netsph::scene_build {

LatticeBox lattice_box(const BoxSpec& b, int dims);
/// Free-surface height of a fill: given, or the top of its particle lattice.
double surface_of(const FillSpec& f, double dp, int dims);
/// Hydrostatic density at height z below a surface (Tait inverted), rho0 above it.
Real hydrostatic_density(const TaitEos& eos, double gz, double surface, double z);

/// Sets the scene's fluid depth, sound speed and fluid model, with the warnings on the sound
/// speed and the hydrostatic start; returns the highest free surface of the fills.
double set_fluid_model(const CaseSpec& spec, Scene& scene);
/// The warning on a background pressure with gravity (a free surface needs zero pressure).
void add_background_pressure_warning(const CaseSpec& spec, Scene& scene);
/// The fills' particles near `near` (fluid, or buffer where they start in an open boundary).
void add_fills(const CaseSpec& spec, Scene& scene, const AxisRange& near);

/// The inlets' then the outlets' zones; `top_surface` is a zone's default free surface.
void add_open_boundary_zones(const CaseSpec& spec, Scene& scene, double top_surface);

/// The warnings on the walls' settings (no-slip mDBC with artificial viscosity; a wall that
/// closes a periodic axis).
void add_wall_warnings(const CaseSpec& spec, Scene& scene);
/// The walls' particles near `near`, hydrostatic below `top_surface`.
void add_walls(const CaseSpec& spec, Scene& scene, const AxisRange& near, double top_surface);

/// The damping zones the step applies (scene_waves.cpp).
void add_damping_zones(const CaseSpec& spec, Scene& scene);
/// The [waves] checks that need the fluid model: an error for fewer than 20 time steps per
/// period, warnings for a wave height of fewer than 6 particles and a damping zone shorter
/// than half a wavelength.
void check_waves(const CaseSpec& spec, Scene& scene);

/// Sets the scene's domain: the case's (checking that every particle lies in it) or the
/// default around the whole scene's particles (`whole_bounds` makes one process's bounding
/// box the whole scene's). Returns the bounding box of this scene's own particles.
std::pair<Vec3d, Vec3d> set_domain(const CaseSpec& spec, Scene& scene,
                                   const WholeBounds& whole_bounds);

}  // namespace netsph::scene_build
