#pragma once
// Solid shapes in their own (local) frame, centred at the origin, for rigid bodies: inside
// test, the nearest point of the surface (for mDBC ghost nodes), volume and inertia.
// Conventions of the local frame:
//   box        lengths (lx, ly, lz) along x, y, z (plates: the thickness along x)
//   cylinder   axis along local x (discs: a short cylinder, face normal x)
//   sphere     radius
//   cruciform  two cylinders of the same radius crossing at the origin, arms along local y
//              and z, each `length` long: a net's cruciform element seen by a flow along x
// In 2D the shapes are cut by the plane y = 0 (the simulation plane is x-z).
#include <vector>

#include "netsph/core/vec3.hpp"

namespace netsph {

enum class ShapeType { Box, Cylinder, Sphere, Cruciform };

struct Shape {
  ShapeType type = ShapeType::Box;
  Vec3d half{};  ///< box: half lengths; cylinder: half length in x; cruciform: half arm length in
                 ///< y, z
  double radius = 0;  ///< cylinder, sphere, cruciform

  static Shape box(const Vec3d& lengths) { return {ShapeType::Box, lengths * 0.5, 0}; }
  static Shape cylinder(double diameter, double length) {
    return {ShapeType::Cylinder, {0.5 * length, 0, 0}, 0.5 * diameter};
  }
  static Shape sphere(double diameter) { return {ShapeType::Sphere, {}, 0.5 * diameter}; }
  static Shape cruciform(double twine_length, double twine_diameter) {
    return {
        ShapeType::Cruciform, {0, 0.5 * twine_length, 0.5 * twine_length}, 0.5 * twine_diameter};
  }

  bool inside(const Vec3d& p) const;
  /// The point of the surface nearest to p (p inside the shape, or near it).
  Vec3d nearest_surface_point(const Vec3d& p) const;
  /// Distance from an inside point to the surface.
  double depth(const Vec3d& p) const { return norm(nearest_surface_point(p) - p); }
  /// Half extents of the bounding box.
  Vec3d bounding_half() const;
  /// Volume, m^3 (3D) or area of the local y = 0 section, m^2 (2D; see plane_section_shape).
  double measure(int dims) const;
  /// Principal moments of inertia per unit density about the centre (local axes are principal
  /// for every shape here), kg m^2 / (kg/m^3); in 2D only the y component (about the normal
  /// of the plane) is meaningful, per unit depth.
  Vec3d inertia_per_density(int dims) const;
};

/// 2D: whether the simulation plane cuts s in a disc: a sphere, or a cylinder whose axis (local
/// x) is normal to the plane. `plane`: the local-frame directions of world x and z.
bool round_section_2d(const Shape& s, const std::vector<Vec3d>& plane);

/// 2D: a shape whose y = 0 section (the one measure(2) and inertia_per_density(2) take) is the
/// simulation plane's section of s: a sphere of s's radius where that section is a disc (a
/// cylinder across the plane), s itself otherwise.
Shape plane_section_shape(const Shape& s, const std::vector<Vec3d>& plane);

/// The shape as SPH particles resolve it: every dimension at least 2 dp (box half lengths,
/// cylinder half length and radius, sphere and twine radius at least dp). A body thinner than
/// that would be one particle layer thick, and mDBC gives each boundary particle one ghost
/// node, on one side: the fluid on the other side would then feel the far side's pressure,
/// and the pressure drag of a thin plate would be about halved. Two layers give each face its
/// own. (dims = 2: the y extent is left alone.)
Shape resolvable_shape(const Shape& s, double dp, int dims);

/// Body particles in the local frame: a dp lattice along the given local-frame unit axes (3 in
/// 3D: the local axes, body-fitted; 2 in 2D: the local directions of world x and z, so the
/// lattice lies in the simulation plane), centred on the shape and offset by dp/2 along axes
/// with an even number of layers. Keeps every point inside the shape, so a box of L along an
/// axis holds max(1, round(L / dp)) layers: exactly n for L = n dp, with its faces dp/2 beyond
/// the outer layers (the mDBC convention), and the nearest whole number of layers otherwise (a
/// plate 1.6 dp thick gets two, not none). When shell_layers > 0 only points at most
/// shell_layers dp deep are kept (deeper ones never meet the fluid).
std::vector<Vec3d> body_lattice(const Shape& s, double dp, int shell_layers,
                                const std::vector<Vec3d>& axes);

}  // namespace netsph
