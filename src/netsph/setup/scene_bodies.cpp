// [[body]] -> body particles and rigid-body state (setup/scene.hpp).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/geometry/body_particles.hpp"
#include "netsph/geometry/box_bins.hpp"
#include "netsph/geometry/shapes.hpp"
#include "netsph/setup/periodic_body_check.hpp"
#include "netsph/setup/scene.hpp"

namespace netsph {
namespace {

Shape nominal_shape(const BodySpec& b) {
  switch (b.shape) {
    case BodyShape::Box:
      return Shape::box(b.lengths);
    case BodyShape::Cylinder:
      return Shape::cylinder(b.diameter, b.length);
    case BodyShape::Sphere:
      return Shape::sphere(b.diameter);
    case BodyShape::Cruciform:
      return Shape::cruciform(b.length, b.diameter);
  }
  return {};
}

/// The shape the particles resolve (geometry/shapes.hpp: every dimension at least 2 dp).
Shape shape_of(const BodySpec& b, const CaseSpec& spec) {
  return resolvable_shape(nominal_shape(b), spec.simulation.dp, spec.simulation.dimensions);
}

int shell_layers(const BodySpec& b, const CaseSpec& spec) {
  if (b.layers < 0) return 0;  // solid
  if (b.layers > 0) return b.layers;
  return static_cast<int>(std::ceil(2 * spec.simulation.h_over_dp - 1e-9));
}

}  // namespace

void add_bodies(const CaseSpec& spec, Scene& scene) {
  const int dims = spec.simulation.dimensions;
  const double dp = spec.simulation.dp;
  ParticleSet& p = scene.particles;
  std::string first_thickened;
  for (std::size_t bi = 0; bi < spec.bodies.size(); ++bi) {
    const BodySpec& b = spec.bodies[bi];
    const Shape nominal = nominal_shape(b);
    const Shape shape = shape_of(b, spec);
    if (shape.half != nominal.half || shape.radius != nominal.radius) {
      if (scene.thickened_bodies++ == 0) first_thickened = b.name + " (" + b.where.str() + ")";
    }
    // 2D: the particles must lie in the x-z plane; body_particles needs its local directions.
    const std::vector<Vec3d> plane{rotate_inverse(b.orientation, {1, 0, 0}),
                                   rotate_inverse(b.orientation, {0, 0, 1})};
    const std::vector<Vec3d> local = body_particles(shape, dp, shell_layers(b, spec), dims, plane);
    if (local.empty()) {
      throw Error(b.where.str(), fmt::format("body '{}' ({}) holds no particle at dp = {} m: it is "
                                             "thinner than dp; lower dp or enlarge the body",
                                             b.name, b.shape_name, dp));
    }
    RigidBody body;
    body.name = b.name;
    body.group = b.group;
    body.motion = b.motion;
    body.model = b.model;
    body.slip = b.slip;
    body.inertia.dims = dims;
    // Mass and inertia are those of the body as given, not as resolved (a thickened plate
    // keeps its mass and radius of gyration), and in 2D those of its section by the plane (a
    // cylinder across the plane: a disc). Fixed and prescribed bodies never use their mass;
    // give them the fluid's so that reports stay meaningful.
    const Shape physical = dims == 2 ? plane_section_shape(nominal, plane) : nominal;
    const double measure = physical.measure(dims);
    const double density =
        b.mass ? *b.mass / measure : (b.density > 0 ? b.density : spec.fluid.density);
    body.inertia.mass = density * measure;
    body.inertia.principal = physical.inertia_per_density(dims) * density;
    body.state.com = b.center;
    if (dims == 2) body.state.com.y = 0;
    body.state.q = b.orientation;
    body.state.vel = b.motion == BodyMotion::Floating ? b.initial_velocity : b.velocity.at(0.0);
    if (b.angular_velocity.moving()) {  // a flap: turning about its hinge from the start
      body.state.omega = b.angular_velocity.at(0.0);
      body.state.vel = cross(body.state.omega, body.state.com - b.hinge);
    }
    body.start = body.state;
    // A fluid without gravity gives no buoyancy: structure_gravity acts on the body's weight
    // less the fluid it displaces.
    if (spec.fluid.structure_gravity && b.motion == BodyMotion::Floating) {
      body.external_force =
          *spec.fluid.structure_gravity * (body.inertia.mass - spec.fluid.density * measure);
    }
    body.first_id = p.next_id;
    body.count = static_cast<std::uint32_t>(local.size());
    body.offsets.reserve(local.size());
    body.ghosts.reserve(local.size());
    p.reserve_more(local.size());
    for (const Vec3d& x : local) {
      body.offsets.push_back(Vec3f(x));
      const Vec3d ghost = (shape.nearest_surface_point(x) - x) * 2.0;
      body.ghosts.push_back(b.model == WallModel::Mdbc ? Vec3f(ghost) : Vec3f{});
      const Vec3d r = rotate(body.state.q, x);
      p.add(body.state.com + r, Vec3f(rigid_point_velocity(body.state, r)),
            static_cast<Real>(spec.fluid.density), ParticleKind::Body,
            static_cast<std::uint32_t>(bi), Vec3f(rotate(body.state.q, Vec3d(body.ghosts.back()))));
    }
    if (const std::string why = body_wider_than_half_period(spec, body); !why.empty())
      throw Error(b.where.str(), why + "; make the body smaller or lengthen the domain");
    scene.sources.push_back({b.name, local.size()});
    scene.bodies.push_back(std::move(body));
  }
  if (scene.thickened_bodies > 0) {
    scene.warnings.push_back(fmt::format(
        "{} bod{} thinner than 2 dp = {} m somewhere (first: {}): resolved 2 dp thick there, one "
        "particle layer per face, so that mDBC sees the pressure on both faces",
        scene.thickened_bodies, scene.thickened_bodies == 1 ? "y is" : "ies are", 2 * dp,
        first_thickened));
  }
}

std::size_t remove_fluid_in_bodies(const CaseSpec& spec, Scene& scene) {
  if (spec.bodies.empty()) return 0;
  const double dp = spec.simulation.dp;
  ParticleSet& p = scene.particles;
  std::vector<Shape> shapes;
  // Each body's bounding box in the world, dp wider on every side, and, where it reaches past
  // a periodic end, its images a period away on the other side, which hold fluid the body
  // covers there: box k is body image_of[k].body's, centred at its centre + image_of[k].shift.
  struct BodyImage {
    std::uint32_t body;
    Vec3d shift;
  };
  std::vector<Aabb> boxes;
  std::vector<BodyImage> image_of;
  for (std::size_t bi = 0; bi < spec.bodies.size(); ++bi) {
    shapes.push_back(shape_of(spec.bodies[bi], spec));
    const RigidBody& body = scene.bodies[bi];
    const Vec3d h = shapes.back().bounding_half();
    Vec3d half{dp, dp, dp};
    for (const Vec3d& axis : {Vec3d{h.x, 0, 0}, Vec3d{0, h.y, 0}, Vec3d{0, 0, h.z}}) {
      const Vec3d e = rotate(body.state.q, axis);
      half += Vec3d{std::abs(e.x), std::abs(e.y), std::abs(e.z)};
    }
    const Aabb box{body.state.com - half, body.state.com + half};
    std::vector<Vec3d> shifts{Vec3d{}};
    for (int a = 0; a < 3; ++a) {
      const double period = spec.domain.period(a);
      if (!(period > 0)) continue;
      const std::size_t before = shifts.size();
      for (const double side : {-1.0, 1.0}) {
        const bool past =
            side < 0 ? box.lo[a] < spec.domain.min[a] : box.hi[a] > spec.domain.max[a];
        if (!past) continue;
        for (std::size_t k = 0; k < before; ++k) {
          Vec3d s = shifts[k];
          s[a] -= side * period;
          shifts.push_back(s);
        }
      }
    }
    for (const Vec3d& s : shifts) {
      boxes.push_back({box.lo + s, box.hi + s});
      image_of.push_back({static_cast<std::uint32_t>(bi), s});
    }
  }
  // Each particle is tested against the body images whose bin holds it only.
  const BoxBins bins(boxes);
  std::vector<char> keep(p.size(), 1);
  std::size_t removed = 0;
  const auto n = static_cast<std::int64_t>(p.size());
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : removed)
  for (std::int64_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (!carries_fluid(p.kind[i])) continue;
    const Vec3d& x = p.pos[i];
    for (const std::uint32_t k : bins.candidates(x)) {
      if (!boxes[k].contains(x)) continue;
      const std::uint32_t bi = image_of[k].body;
      const RigidBody& body = scene.bodies[bi];
      const Vec3d local = rotate_inverse(body.state.q, x - (body.state.com + image_of[k].shift));
      // Inside, or within dp/2 of the surface (the fluid keeps dp/2 off it, as off walls).
      if (shapes[bi].inside(local) || shapes[bi].depth(local) < 0.5 * dp * (1 - 1e-6)) {
        keep[i] = 0, ++removed;
        break;
      }
    }
  }
  if (removed == 0) return 0;
  p.keep_only(keep);
  return removed;
}

}  // namespace netsph
