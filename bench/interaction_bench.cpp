// Micro-benchmarks of the interaction pass (backend/cpu/rates.hpp) on a 3D fluid block, and of
// one full symplectic step (solver/simulation.hpp) of the built-in 3D dam break.
//
// The block is a lattice water column (aspect 0.4 x 0.67 x 0.3, dp = 0.3 m / nz) with a
// hydrostatic density and small random velocities: the parameters of cases/dambreak3d.toml
// (Wendland, h = 1.5 dp, artificial viscosity 0.01, delta-SPH 0.1, c0 = 20 sqrt(g 0.3)).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/backend/cpu/rates.hpp"
#include "netsph/case/builtin_cases.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph {
namespace {

struct FluidBlock {
  ParticleSet p;
  FluidModel m;
  CellGrid grid;
  InteractionView view;
  std::vector<Vec3f> acc;
  std::vector<Real> drho;
};

FluidBlock fluid_block(int nz, DensityDiffusion diffusion) {
  FluidBlock b;
  const int nx = static_cast<int>(std::lround(nz * 4.0 / 3.0));
  const int ny = static_cast<int>(std::lround(nz * 6.7 / 3.0));
  const double height = 0.3, dp = height / nz;
  FluidModelInput in;
  in.dims = 3;
  in.dp = dp;
  in.h_over_dp = 1.5;
  in.kernel = KernelType::Wendland;
  in.c0 = 20 * std::sqrt(9.81 * height);
  in.viscosity = ViscosityModel::Artificial;
  in.alpha = 0.01;
  in.diffusion = diffusion;
  in.delta = 0.1;
  b.m = make_fluid_model(in);

  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f);  // m/s, ~0.15% of c0
  b.p.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k) {
    const double zk = (k + 0.5) * dp;
    const auto rho = static_cast<Real>(b.m.eos.density(-in.rho0 * in.gravity.z * (height - zk)));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        b.p.add({(i + 0.5) * dp, (j + 0.5) * dp, zk}, {u(rng), u(rng), u(rng)}, rho,
                ParticleKind::Fluid);
  }
  const double pad = 4 * dp;
  b.grid.configure({-pad, -pad, -pad}, {nx * dp + pad, ny * dp + pad, height + pad}, b.m.support,
                   0.05, 3);

  std::vector<std::uint32_t> order;
  b.grid.sort(b.p.pos, order);
  std::vector<Vec3d> s3;
  std::vector<Vec3f> f3;
  std::vector<Real> f;
  std::vector<ParticleKind> k;
  std::vector<std::uint32_t> u32;
  gather_into(b.p.pos, order, s3), gather_into(b.p.vel, order, f3), gather_into(b.p.rho, order, f);
  gather_into(b.p.kind, order, k), gather_into(b.p.id, order, u32);
  b.view.build(b.p, b.m, b.grid.origin());
  return b;
}

/// Mean number of neighbours (r < support, self excluded) per particle: untimed, for the counter.
double mean_neighbours(const FluidBlock& b) {
  const auto& v = b.view;
  std::int64_t pairs = 0;
  for (const std::int64_t c : b.grid.occupied_cells()) {
    const IndexRange own = b.grid.cell_range(c);
    NeighbourRanges ranges;
    const int nranges = b.grid.neighbour_ranges(c, ranges);
    for (std::uint32_t a = own.begin; a < own.end; ++a)
      for (int r = 0; r < nranges; ++r)
        for (std::uint32_t j = ranges[static_cast<std::size_t>(r)].begin;
             j < ranges[static_cast<std::size_t>(r)].end; ++j) {
          const Real dx = v.x[a] - v.x[j], dy = v.y[a] - v.y[j], dz = v.z[a] - v.z[j];
          pairs += (dx * dx + dy * dy + dz * dz < b.m.support2 && j != a) ? 1 : 0;
        }
  }
  return static_cast<double>(pairs) / static_cast<double>(v.x.size());
}

const char* diffusion_name(DensityDiffusion d) {
  switch (d) {
    case DensityDiffusion::None:
      return "no diffusion";
    case DensityDiffusion::Molteni:
      return "molteni";
    case DensityDiffusion::Fourtakas:
      return "fourtakas";
  }
  return "?";
}

/// state.range(0): nz; state.range(1): DensityDiffusion (0 none, 1 Molteni, 2 Fourtakas).
void BM_ComputeRates(benchmark::State& state) {
  const auto diffusion = static_cast<DensityDiffusion>(state.range(1));
  FluidBlock b = fluid_block(static_cast<int>(state.range(0)), diffusion);
  compute_rates(b.m, b.grid, b.view, b.p.kind, b.acc, b.drho);  // sizes acc and drho
  for (auto _ : state) {
    RateReductions red = compute_rates(b.m, b.grid, b.view, b.p.kind, b.acc, b.drho);
    benchmark::DoNotOptimize(red);
    benchmark::DoNotOptimize(b.acc.data());
    benchmark::DoNotOptimize(b.drho.data());
    benchmark::ClobberMemory();
  }
  const auto n = static_cast<std::int64_t>(b.p.size());
  const double nbrs = mean_neighbours(b);
  state.SetItemsProcessed(state.iterations() * n);
  state.SetLabel(diffusion_name(diffusion));
  state.counters["particles"] = static_cast<double>(n);
  state.counters["nbrs/part"] = nbrs;
  state.counters["pairs/s"] =
      benchmark::Counter(nbrs * static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

/// One Simulation::step() (sort, two interaction passes, predictor and corrector) of the
/// built-in 3D dam break at dp = 12.5 mm, starting from rest.
void BM_SimulationStep(benchmark::State& state) {
  const CaseSpec spec = read_case_string(builtin_case_text("dambreak3d"), "builtin:dambreak3d",
                                         {"simulation.dp=0.0125"});
  Simulation sim(spec);
  std::int64_t particles = 0;
  try {
    sim.step();  // the first step allocates the work arrays
    for (auto _ : state) {
      sim.step();
      particles += static_cast<std::int64_t>(sim.particles().size());
    }
  } catch (const SimulationUnstable& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.SetItemsProcessed(particles);
  state.counters["particles"] = static_cast<double>(sim.particles().size());
  state.counters["dt_us"] = 1e6 * sim.time() / static_cast<double>(sim.steps());
  state.counters["resorts"] = sim.diagnostics().resorts;
  state.counters["threads"] = omp_get_max_threads();
}

BENCHMARK(BM_ComputeRates)
    ->ArgNames({"nz", "diffusion"})
    ->Args({32, static_cast<std::int64_t>(DensityDiffusion::None)})
    ->Args({32, static_cast<std::int64_t>(DensityDiffusion::Molteni)})
    ->Args({32, static_cast<std::int64_t>(DensityDiffusion::Fourtakas)})
    ->Args({43, static_cast<std::int64_t>(DensityDiffusion::Fourtakas)})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

BENCHMARK(BM_SimulationStep)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace netsph
