#pragma once
// The fluid-carrying particles within the kernel support of an arbitrary point (a probe
// point), found through the cell grid: the loop of the probe sampling (probe_pass.hpp), which
// runs between steps on the particles themselves.
#include <cmath>
#include <cstdint>

#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// Calls visit(j, d, r) for every non-solid particle j within the support of `point`, with
/// d = x_j - point (periodic images included) and r = |d|; the point is wrapped into the
/// periodic axes first. Returns false when the point lies outside the grid.
template <class Visit>
bool visit_point_neighbours(const FluidModel& m, const CellGrid& grid, const ParticleSet& p,
                            const Vec3d& point, Visit&& visit) {
  const Vec3d x = grid.wrapped(point);
  const std::int64_t c = grid.cell_of(x);
  if (c < 0) return false;
  NeighbourRanges ranges;
  const int nr = grid.neighbour_ranges(c, ranges);
  for (int k = 0; k < nr; ++k) {
    const Vec3d shift(ranges[k].shift);
    for (std::uint32_t j = ranges[k].begin; j < ranges[k].end; ++j) {
      if (is_solid(p.kind[j])) continue;
      const Vec3f d(p.pos[j] + shift - x);
      const Real r2 = norm2(d);
      if (!(r2 < m.support2)) continue;
      visit(j, d, std::sqrt(r2));
    }
  }
  return true;
}

}  // namespace netsph
