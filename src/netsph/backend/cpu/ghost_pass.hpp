#pragma once
// Ghost-node interpolation (sph/ghost_interpolation.hpp) for a list of points on the CPU:
// the ghost nodes of mDBC wall particles and of open-boundary buffer particles. The value at
// each point is handed to a callback instead of being stored, so the pass needs no per-point
// scratch (a GhostValue is ~140 bytes).
#include <cmath>
#include <cstdint>
#include <span>

#include "netsph/backend/cpu/point_neighbours.hpp"
#include "netsph/neighbors/cell_grid.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/kernels.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

/// Which particles a ghost node sums over.
enum class GhostSources : std::uint8_t {
  FluidAndBuffer,  ///< mDBC (English et al. 2022 include buffer particles)
  FluidOnly,       ///< open boundaries (buffer particles take their state from the fluid)
};

/// The interpolation at one point (wrapped into periodic axes first); any == false outside
/// the grid or with no source particle in reach.
template <class Kernel>
GhostValue ghost_value_at(const FluidModel& m, const CellGrid& grid, const ParticleSet& p,
                          const Vec3d& point, GhostSources sources) {
  GhostSums sums;
  visit_point_neighbours(m, grid, p, point, [&](std::uint32_t j, const Vec3f& d, Real r) {
    if (sources == GhostSources::FluidOnly && p.kind[j] != ParticleKind::Fluid) return;
    ghost_accumulate(sums, d, kernel_value<Kernel>(m.kernel, r),
                     kernel_grad_factor<Kernel>(m.kernel, r), m.mass, p.rho[j], p.vel[j]);
  });
  return ghost_solve(sums, m.dims);
}

/// Calls on_value(k, value) for every points[k], in parallel: the callback must only write
/// state that belongs to point k.
template <class OnValue>
void for_each_ghost_value(const FluidModel& m, const CellGrid& grid, const ParticleSet& p,
                          std::span<const Vec3d> points, GhostSources sources, OnValue&& on_value) {
  const auto n = static_cast<std::int64_t>(points.size());
  with_kernel(m.kernel_type, [&](auto k) {
    using K = decltype(k);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      on_value(static_cast<std::size_t>(i), ghost_value_at<K>(m, grid, p, points[i], sources));
    }
    return 0;
  });
}

}  // namespace netsph
