#pragma once
// Ghost-node interpolation (sph/ghost_interpolation.hpp) on the CPU, for the ghost nodes of
// mDBC wall and body particles and of open-boundary buffer particles, over the interaction
// view (interaction_view.hpp): the particles near each ghost node are found with the rates
// pass's candidate scan (neighbour_batch.hpp: float positions, 16 candidates a vector), their
// kernel values are evaluated a batch at a time in vector lanes, and the sums are accumulated
// by the shared ghost_accumulate. The sources are the particles whose fluid flag is set in the
// view: fluid and buffer particles for mDBC (English et al. 2022 include the buffer); an open
// boundary clears its buffer's flags while it sums (Tafuni et al. 2018: the fluid only).
//
// The earlier version read the ParticleSet one candidate at a time in double: 44% of the
// reduced Bi 2014 net's run time (28,416 mDBC wall particles, 9,216 buffer particles against
// 63,936 fluid ones; docs/PERFORMANCE.md). The view must hold the current state of the
// sources: the step builds it before the open boundaries and mDBC, and they refresh the
// entries they set (Simulation::apply_open_boundary_state, apply_mdbc).
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/backend/cpu/neighbour_batch.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/fluid_model.hpp"
#include "netsph/sph/ghost_interpolation.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph {

/// The candidate ranges of the cell asked for last, kept for the next node. The ghost nodes of
/// consecutive wall particles (sorted by cell) mostly fall in one cell, and building a cell's
/// ranges for every node took 9% of the default case's run time (perf, 2026-12-02). Valid for
/// one sort of the grid: one memo per pass (and thread).
struct CellRangesMemo {
  std::int64_t cell = -1;
  int count = 0;
  NeighbourRanges ranges;

  int of(const CellGrid& grid, std::int64_t c) {
    if (c != cell) count = grid.neighbour_ranges(c, ranges), cell = c;
    return count;
  }
};

/// The sums at `point` (wrapped into periodic axes first) over the view's particles with the
/// fluid flag set within the support; empty outside the grid.
template <class Kernel>
GhostSums ghost_sums_at(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                        const Vec3d& point, CellRangesMemo& memo) {
  GhostSums sums;
  const Vec3d x = grid.wrapped(point);
  const std::int64_t c = grid.cell_of(x);
  if (c < 0) return sums;
  const int nranges = memo.of(grid, c);
  const NeighbourRanges& ranges = memo.ranges;
  const Vec3d& o = grid.origin();
  // A ghost node is no particle: no candidate is excluded as "itself".
  constexpr std::uint32_t kNoParticle = std::numeric_limits<std::uint32_t>::max();
  CandidateScan scan{static_cast<Real>(x.x - o.x),
                     static_cast<Real>(x.y - o.y),
                     static_cast<Real>(x.z - o.z),
                     v.x.data(),
                     v.y.data(),
                     v.z.data(),
                     kNoParticle,
                     m.support2,
                     v.fluid.data()};
  // The sources' density and velocity come along with each neighbour (no gathers below).
  enum { kRho, kVx, kVy, kVz };
  scan.ncarry = 4;
  scan.carry[kRho] = v.rho.data();
  scan.carry[kVx] = v.vx.data(), scan.carry[kVy] = v.vy.data(), scan.carry[kVz] = v.vz.data();
  const KernelScale ks = m.kernel;
  scan_ranges(scan, ranges, nranges, [&](const NeighbourBatch& b, int n) {
    // The terms of the whole batch in vector lanes first, then their sum: four broadcast
    // multiply-adds of 8 doubles per neighbour (the sums are an outer product).
    alignas(64) double weight[NeighbourBatch::kCapacity][4];
    alignas(64) double u[NeighbourBatch::kCapacity][8];
#pragma omp simd
    for (int k = 0; k < n; ++k) {
      const Real r = std::sqrt(b.r2[k]);
      // The batch holds point - neighbour; the interpolation takes neighbour - point.
      const GhostTerms t =
          ghost_terms(Vec3f(-b.dx[k], -b.dy[k], -b.dz[k]), kernel_value<Kernel>(ks, r),
                      kernel_grad_factor<Kernel>(ks, r), m.mass, b.carried[kRho][k],
                      Vec3f(b.carried[kVx][k], b.carried[kVy][k], b.carried[kVz][k]));
      for (int q = 0; q < 4; ++q) weight[k][q] = t.weight[q];
      for (int q = 0; q < 8; ++q) u[k][q] = t.u[q];
    }
    for (int k = 0; k < n; ++k) ghost_add(sums, weight[k], u[k]);
  });
  return sums;
}

/// Calls on_value(k, value) for every points[k], in parallel: the callback must only write
/// state that belongs to point k.
template <class OnValue>
void for_each_ghost_value(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                          std::span<const Vec3d> points, OnValue&& on_value) {
  const auto n = static_cast<std::int64_t>(points.size());
  with_kernel(m.kernel_type, [&](auto k) {
    using K = decltype(k);
#pragma omp parallel
    {
      CellRangesMemo memo;
#pragma omp for schedule(dynamic, 256)
      for (std::int64_t i = 0; i < n; ++i) {
        const GhostSums sums = ghost_sums_at<K>(m, grid, v, points[i], memo);
        on_value(static_cast<std::size_t>(i), ghost_solve(sums, m.dims));
      }
    }
    return 0;
  });
}

}  // namespace netsph
