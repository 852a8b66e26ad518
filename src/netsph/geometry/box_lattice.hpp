#pragma once
// Particles on the dp lattice of a box: the fluid that fills it and the wall layers around it.
// A box of length L holds n = round(L/dp) particles per axis at min + (i + 1/2) dp, so the
// particles tile exactly the box [min, min + n dp] and a wall built on the same box sits one
// dp from the fluid on every face (the wall surface is the box face, midway between the last
// fluid particle and the first wall particle, as mDBC expects).
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "netsph/core/vec3.hpp"

namespace netsph {

struct LatticeBox {
  Vec3d min{}, max{};
  int dims = 3;  ///< 2: the x-z plane, y = 0
};

/// Particles per axis for the box (1 on y in 2D); throws netsph::Error if an axis holds none.
std::array<int, 3> lattice_counts(const LatticeBox& box, double dp);

/// Box extent actually covered by the lattice: min + counts * dp.
Vec3d lattice_max(const LatticeBox& box, double dp);

/// The fluid lattice points inside the box, x fastest, then y, then z.
std::vector<Vec3d> fill_box(const LatticeBox& box, double dp);

/// Coordinates in [lo, hi) along one axis (either end may be infinite).
struct AxisRange {
  int axis = 0;
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();

  bool contains(const Vec3d& p) const { return p[axis] >= lo && p[axis] < hi; }
  bool everything() const {
    return lo == -std::numeric_limits<double>::infinity() &&
           hi == std::numeric_limits<double>::infinity();
  }
  /// The range that contains no position.
  static AxisRange nothing() { return {0, 0, 0}; }
};

/// The fill lattice points within `range`, each with its index in fill_box's order, without
/// generating the others (one process of a distributed run builds its part of a fill that
/// may hold 1e8 points).
struct LatticePart {
  std::vector<Vec3d> points;
  std::vector<std::uint64_t> index;  ///< in fill_box(box, dp)
  std::uint64_t total = 0;           ///< points in the whole box
};
LatticePart fill_box_part(const LatticeBox& box, double dp, const AxisRange& range);

/// wall_box_layers' points within `range`, each with its index in wall_box_layers' order.
LatticePart wall_box_layers_part(const LatticeBox& box, double dp, const std::array<bool, 6>& faces,
                                 int layers, const AxisRange& range);

/// Wall particle positions: lattice points outside the box, up to `layers` spacings beyond
/// each chosen face (order xmin, xmax, ymin, ymax, zmin, zmax); edges and corners between two
/// chosen faces are filled so that no fluid particle sees a gap.
std::vector<Vec3d> wall_box_layers(const LatticeBox& box, double dp,
                                   const std::array<bool, 6>& faces, int layers);

}  // namespace netsph
