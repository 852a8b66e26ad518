#pragma once
// Shepard-corrected sampling of the fluid at probe points on the CPU (sph/shepard.hpp): the
// velocity, pressure and density at each point from the fluid particles (not the buffers,
// which hold imposed states, nor walls and bodies) within the kernel support.
#include <cstdint>
#include <span>
#include <vector>

#include "netsph/backend/cpu/point_neighbours.hpp"
#include "netsph/sph/kernels.hpp"
#include "netsph/sph/shepard.hpp"

namespace netsph {

/// sums[k] = the Shepard sums at points[k] over the fluid particles j of `p` (those with
/// keep[j] != 0 when `keep` is given: one process's own particles in a distributed run, whose
/// sums over all processes are the whole run's).
inline void point_sums(const FluidModel& m, const CellGrid& grid, const ParticleSet& p,
                       std::span<const Vec3d> points, std::span<ShepardSums> sums,
                       std::span<const std::uint8_t> keep = {}) {
  const auto n = static_cast<std::int64_t>(points.size());
  const bool all = keep.empty();
  with_kernel(m.kernel_type, [&](auto kernel) {
    using K = decltype(kernel);
#pragma omp parallel for schedule(dynamic, 64)
    for (std::int64_t i = 0; i < n; ++i) {
      ShepardSums s;
      visit_point_neighbours(m, grid, p, points[i], [&](std::uint32_t j, const Vec3f&, Real r) {
        if (p.kind[j] != ParticleKind::Fluid || (!all && !keep[j])) return;
        shepard_accumulate_fluid(s, kernel_value<K>(m.kernel, r), m.mass, p.rho[j], p.vel[j],
                                 m.eos);
      });
      sums[i] = s;
    }
    return 0;
  });
}

/// values[k] = the interpolation at points[k] (coverage 0 outside the grid or with no fluid in
/// reach). Pressures are gauge (the background pressure removed).
inline void sample_points(const FluidModel& m, const CellGrid& grid, const ParticleSet& p,
                          std::span<const Vec3d> points, std::span<ShepardValue> values) {
  std::vector<ShepardSums> sums(points.size());
  point_sums(m, grid, p, points, sums);
  for (std::size_t k = 0; k < points.size(); ++k) values[k] = shepard_value(sums[k]);
}

}  // namespace netsph
