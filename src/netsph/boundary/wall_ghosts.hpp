#pragma once
// Ghost-node offsets of mDBC wall particles built on a box: the wall surface is the box face,
// dp/2 beyond the first particle layer. A particle's closest point on the surface is its
// position clamped into the box, so behind a face the ghost is the mirror through the face and
// in an edge or corner region the mirror through the edge or corner point (as DualSPHysics'
// geometric normals give).
#include <span>
#include <vector>

#include "netsph/core/vec3.hpp"

namespace netsph {

/// r_g - r_b = 2 (clamp(r_b, box) - r_b) for each position; y is ignored in 2D.
std::vector<Vec3f> box_wall_ghost_offsets(std::span<const Vec3d> positions, const Vec3d& box_min,
                                          const Vec3d& box_max, int dims);

}  // namespace netsph
