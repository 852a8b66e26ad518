// Micro-benchmarks of the neighbour search (neighbours/cell_grid.hpp): the counting sort by
// cell, and the walk over the candidate ranges of every occupied cell that the interaction
// loop makes (the fluid pass's candidate scan, which compacts the pairs within the support
// into batches, without computing their rates).
//
// The particles are a lattice water column of a 3D dam break (aspect 0.4 x 0.67 x 0.3, dp =
// 0.3 m / nz) in a tank four times as long and 4/3 as high, so most cells of the grid are
// empty, as in the real case. h = 1.5 dp, support 2h = 3 dp, skin 0.05 (the solver's values).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "netsph/backend/cpu/neighbour_batch.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {
namespace {

constexpr double kHOverDp = 1.5;
constexpr double kSkin = 0.05;

struct Column {
  std::vector<Vec3d> pos;
  CellGrid grid;
  double support = 0;
};

/// The water column of nz layers, sorted by cell as it is in a running simulation.
Column dam_column(int nz) {
  Column col;
  const int nx = static_cast<int>(std::lround(nz * 4.0 / 3.0));
  const int ny = static_cast<int>(std::lround(nz * 6.7 / 3.0));
  const double dp = 0.3 / nz;
  col.support = 2 * kHOverDp * dp;
  col.pos.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        col.pos.push_back({(i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp});
  const double pad = 4 * dp;
  col.grid.configure({-pad, -pad, -pad},
                     {4 * nx * dp + pad, ny * dp + pad, 4.0 / 3.0 * nz * dp + pad}, col.support,
                     kSkin, 3);
  std::vector<std::uint32_t> order;
  std::vector<Vec3d> scratch;
  col.grid.sort(col.pos, order);
  gather_into(col.pos, order, scratch);
  return col;
}

/// state.range(0): nz; state.range(1): 0 = input already in cell order (every step of a run),
/// 1 = shuffled input (the first sort).
void BM_CellGridSort(benchmark::State& state) {
  Column col = dam_column(static_cast<int>(state.range(0)));
  const bool shuffled = state.range(1) != 0;
  if (shuffled) {
    std::mt19937_64 rng(1);
    std::shuffle(col.pos.begin(), col.pos.end(), rng);
  }
  std::vector<std::uint32_t> order;
  col.grid.sort(col.pos, order);  // sizes the scratch arrays, as after the first step
  for (auto _ : state) {
    col.grid.sort(col.pos, order);
    benchmark::DoNotOptimize(order.data());
    benchmark::ClobberMemory();
  }
  const auto n = static_cast<std::int64_t>(col.pos.size());
  state.SetItemsProcessed(state.iterations() * n);
  state.SetLabel(shuffled ? "shuffled" : "cell order");
  state.counters["particles"] = static_cast<double>(n);
  state.counters["cells"] = static_cast<double>(col.grid.cell_count());
  state.counters["occupied"] = static_cast<double>(col.grid.occupied_cells().size());
}

/// The neighbour search proper: for every particle, the candidates of its cell's ranges and
/// the test r < support, in float relative to the grid origin as InteractionView holds them,
/// with the same OpenMP schedule as the interaction loop (backend/cpu/rates.cpp).
void BM_NeighbourSearch(benchmark::State& state) {
  const Column col = dam_column(static_cast<int>(state.range(0)));
  const CellGrid& grid = col.grid;
  const std::size_t n = col.pos.size();
  std::vector<float> xs(n), ys(n), zs(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d r = col.pos[i] - grid.origin();
    xs[i] = static_cast<float>(r.x), ys[i] = static_cast<float>(r.y),
    zs[i] = static_cast<float>(r.z);
  }
  const float support2 = static_cast<float>(col.support * col.support);
  const auto& cells = grid.occupied_cells();
  const auto ncells = static_cast<std::int64_t>(cells.size());
  const float* __restrict x = xs.data();
  const float* __restrict y = ys.data();
  const float* __restrict z = zs.data();

  std::int64_t pairs = 0, candidates = 0;
  for (auto _ : state) {
    pairs = 0, candidates = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : pairs, candidates)
    for (std::int64_t k = 0; k < ncells; ++k) {
      const std::int64_t c = cells[static_cast<std::size_t>(k)];
      const IndexRange own = grid.cell_range(c);
      NeighbourRanges ranges;
      const int nranges = grid.neighbour_ranges(c, ranges);
      for (std::uint32_t a = own.begin; a < own.end; ++a) {
        // The fluid pass's scan (backend/cpu/neighbour_batch.hpp): test and compact.
        NeighbourBatch batch;
        std::int64_t found = 0;
        const auto sum = [&](const NeighbourBatch&) { found += NeighbourBatch::kCapacity; };
        for (int r = 0; r < nranges; ++r) {
          const NeighbourRange& range = ranges[static_cast<std::size_t>(r)];
          candidates += range.end - range.begin;
          const CandidateScan scan{x[a] - range.shift.x,
                                   y[a] - range.shift.y,
                                   z[a] - range.shift.z,
                                   x,
                                   y,
                                   z,
                                   a,
                                   support2};
          scan_range(scan, range.begin, range.end, batch, sum);
        }
        pairs += found + batch.n;
      }
    }
    benchmark::DoNotOptimize(pairs);
  }
  const double np = static_cast<double>(n);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
  state.counters["particles"] = np;
  state.counters["nbrs/part"] = static_cast<double>(pairs) / np;
  state.counters["cand/part"] = static_cast<double>(candidates) / np;
}

BENCHMARK(BM_CellGridSort)
    ->ArgNames({"nz", "shuffled"})
    ->ArgsProduct({{32, 70}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

BENCHMARK(BM_NeighbourSearch)
    ->ArgNames({"nz"})
    ->Arg(32)
    ->Arg(70)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace
}  // namespace netsph
