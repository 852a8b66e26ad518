#include "netsph/boundary/wall_ghosts.hpp"

#include <algorithm>

namespace netsph {

std::vector<Vec3f> box_wall_ghost_offsets(std::span<const Vec3d> positions, const Vec3d& box_min,
                                          const Vec3d& box_max, int dims) {
  std::vector<Vec3f> out;
  out.reserve(positions.size());
  for (const Vec3d& r : positions) {
    Vec3d q = r;
    for (int a = 0; a < 3; ++a) {
      if (dims == 2 && a == 1) continue;
      q[a] = std::clamp(r[a], box_min[a], box_max[a]);
    }
    out.push_back(Vec3f((q - r) * 2.0));
  }
  return out;
}

}  // namespace netsph
