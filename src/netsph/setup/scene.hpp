#pragma once
// Scene: the initial particles of a case and the quantities derived from the case as a whole
// (sound speed, domain, fluid model). Built once from a validated CaseSpec.
#include <functional>
#include <string>
#include <vector>

#include "netsph/bodies/rigid_body.hpp"
#include "netsph/boundary/open_boundary.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/geometry/box_lattice.hpp"
#include "netsph/setup/solid_overlaps.hpp"
#include "netsph/sph/damping_zone.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

struct SceneSource {
  std::string name;  ///< "fill1", or the wall's name
  std::size_t particles = 0;
};

struct Scene {
  ParticleSet particles;
  FluidModel model;
  double sound_speed = 0;  ///< c0, m/s
  double fluid_depth = 0;  ///< deepest fill, m (used for c0 = coef sqrt(g H))
  Vec3d domain_min{}, domain_max{};
  std::vector<OpenBoundaryZone> zones;  ///< inlets, then outlets (buffer particles' group)
  std::vector<RigidBody> bodies;        ///< body particles' group indexes this
  std::vector<DampingZone> damping;     ///< [[damping]] zones, in case order
  std::vector<SceneSource> sources;
  // Counts of the particles in the scene (a part's: in its region).
  std::size_t removed_overlaps = 0;   ///< fluid particles dropped for sitting on another particle
  std::size_t removed_in_bodies = 0;  ///< fluid particles dropped for lying inside a body
  std::vector<std::size_t> buffer_counts;  ///< buffer particles per zone at the start
  std::size_t thickened_bodies = 0;        ///< bodies resolved thicker than given (2 dp at least)
  SolidOverlaps solid_overlaps;  ///< floating bodies' particles inside walls or other bodies
  std::vector<std::string> warnings;

  /// Everything but the particles (the outputs' view of a distributed run). Copies every
  /// other member: a member added above must be added there too.
  Scene without_particles() const;
};

/// Adds to `scene` the sources and warnings that rest on the counts of its particles (the
/// buffers' sources, zones without buffer particles, bodies starting inside solids, fluid
/// removed for overlapping): for the whole case `spec`, from build_scene's counts or from a
/// distributed run's parts' summed.
void report_particle_counts(Scene& scene, const CaseSpec& spec);

/// Builds the particles (walls first, then fills in file order) with hydrostatic density.
/// Throws netsph::Error naming the case item when something cannot be built.
Scene build_scene(const CaseSpec& spec);

/// Turns the bounding box of one process's particles into that of every process's (a
/// reduction in a distributed run): the default domain is derived from it.
using WholeBounds = std::function<void(Vec3d& lo, Vec3d& hi)>;

/// One process's part of the scene of a distributed run, so that no process needs the memory
/// of the whole case: the particles whose coordinate along region.axis lies in the region,
/// with the ids, positions, densities and kinds build_scene gives them, and the whole
/// scene's domain (through `whole_bounds`, called once on every process). The parts of
/// regions that tile the axis make up build_scene's particles exactly. The fills and walls
/// are generated only near the region; the bodies' particles (a few surfaces) in full and
/// then trimmed. `sources` count the whole case's walls, fills and bodies as generated; the
/// counts of removed fluid and buffer particles and of bodies' overlapping particles are those
/// in the region, to be summed over the parts (report_particle_counts, which a part leaves
/// out).
Scene build_scene_part(const CaseSpec& spec, const AxisRange& region,
                       const WholeBounds& whole_bounds);

/// Adds the [[body]] particles (setup/scene_bodies.cpp) and fills in scene.bodies.
void add_bodies(const CaseSpec& spec, Scene& scene);

/// Removes fluid particles inside a body or closer than dp/2 to its surface; returns how many.
std::size_t remove_fluid_in_bodies(const CaseSpec& spec, Scene& scene);

/// The fluid model of a case for a given sound speed.
FluidModel fluid_model_for(const CaseSpec& spec, double sound_speed);

}  // namespace netsph
