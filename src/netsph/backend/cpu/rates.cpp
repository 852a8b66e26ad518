#include "netsph/backend/cpu/rates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "netsph/sph/pair_interaction.hpp"

namespace netsph {
namespace {

/// Sums over the neighbours of fluid particle a. The loop body is branch-free apart from the
/// range test so that the compiler vectorises it (omp simd with explicit reductions).
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff>
inline RateSums fluid_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                           const std::array<IndexRange, 25>& ranges, int nranges) {
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const Real rho_a = v.rho[a], press_a = v.press[a];
  const Real* __restrict x = v.x.data();
  const Real* __restrict y = v.y.data();
  const Real* __restrict z = v.z.data();
  const Real* __restrict vx = v.vx.data();
  const Real* __restrict vy = v.vy.data();
  const Real* __restrict vz = v.vz.data();
  const Real* __restrict rho = v.rho.data();
  const Real* __restrict press = v.press.data();
  const Real* __restrict fluid = v.fluid.data();
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0;
  for (int k = 0; k < nranges; ++k) {
    const std::uint32_t b0 = ranges[k].begin, b1 = ranges[k].end;
#pragma omp simd reduction(+ : ax, ay, az, dr) reduction(max : vdt)
    for (std::uint32_t b = b0; b < b1; ++b) {
      const Real dx = xa - x[b], dy = ya - y[b], dz = za - z[b];
      const Real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < m.support2 && b != a) {
        const Neighbour nb{{dx, dy, dz}, r2,       {vxa - vx[b], vya - vy[b], vza - vz[b]},
                           rho[b],       press[b], m.mass,
                           fluid[b]};
        RateSums s;
        fluid_pair_rates<Kernel, Visc, Diff>(m, rho_a, press_a, nb, s);
        ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
        vdt = std::max(vdt, s.visc_dt);
      }
    }
  }
  RateSums out;
  out.acc = {ax, ay, az};
  out.drho = dr;
  out.visc_dt = vdt;
  return out;
}

template <class Kernel>
inline RateSums boundary_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                              const std::array<IndexRange, 25>& ranges, int nranges) {
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  Real dr = 0, vdt = 0;
  for (int k = 0; k < nranges; ++k) {
    const std::uint32_t b0 = ranges[k].begin, b1 = ranges[k].end;
#pragma omp simd reduction(+ : dr) reduction(max : vdt)
    for (std::uint32_t b = b0; b < b1; ++b) {
      const Real dx = xa - v.x[b], dy = ya - v.y[b], dz = za - v.z[b];
      const Real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < m.support2 && v.fluid[b] > Real(0)) {
        const Neighbour nb{{dx, dy, dz}, r2,         {vxa - v.vx[b], vya - v.vy[b], vza - v.vz[b]},
                           v.rho[b],     v.press[b], m.mass,
                           v.fluid[b]};
        RateSums s;
        boundary_pair_rates<Kernel>(m, nb, s);
        dr += s.drho;
        vdt = std::max(vdt, s.visc_dt);
      }
    }
  }
  RateSums out;
  out.drho = dr;
  out.visc_dt = vdt;
  return out;
}

template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff>
RateReductions rates_loop(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                          std::span<const ParticleKind> kind, std::vector<Vec3f>& acc,
                          std::vector<Real>& drho) {
  const auto& cells = grid.occupied_cells();
  const auto ncells = static_cast<std::int64_t>(cells.size());
  double max_acc2 = 0, max_visc = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(max : max_acc2, max_visc)
  for (std::int64_t k = 0; k < ncells; ++k) {
    const std::int64_t c = cells[k];
    const IndexRange own = grid.cell_range(c);
    std::array<IndexRange, 25> ranges;
    const int nranges = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t a = own.begin; a < own.end; ++a) {
      if (is_fluid(kind[a])) {
        const RateSums s = fluid_sums<Kernel, Visc, Diff>(m, v, a, ranges, nranges);
        const Vec3f total = s.acc + m.gravity;
        acc[a] = total;
        drho[a] = s.drho;
        max_acc2 = std::max(max_acc2, static_cast<double>(norm2(total)));
        max_visc = std::max(max_visc, static_cast<double>(s.visc_dt));
      } else {
        const RateSums s = boundary_sums<Kernel>(m, v, a, ranges, nranges);
        acc[a] = {};
        drho[a] = s.drho;
        max_visc = std::max(max_visc, static_cast<double>(s.visc_dt));
      }
    }
  }
  return {std::sqrt(max_acc2), max_visc};
}

template <class Kernel, ViscosityModel Visc>
RateReductions dispatch_diffusion(const FluidModel& m, const CellGrid& g, const InteractionView& v,
                                  std::span<const ParticleKind> k, std::vector<Vec3f>& acc,
                                  std::vector<Real>& drho) {
  switch (m.diffusion) {
    case DensityDiffusion::None:
      return rates_loop<Kernel, Visc, DensityDiffusion::None>(m, g, v, k, acc, drho);
    case DensityDiffusion::Molteni:
      return rates_loop<Kernel, Visc, DensityDiffusion::Molteni>(m, g, v, k, acc, drho);
    case DensityDiffusion::Fourtakas:
      return rates_loop<Kernel, Visc, DensityDiffusion::Fourtakas>(m, g, v, k, acc, drho);
  }
  return {};
}

}  // namespace

RateReductions compute_rates(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                             std::span<const ParticleKind> kind, std::vector<Vec3f>& acc,
                             std::vector<Real>& drho) {
  acc.resize(v.x.size());
  drho.resize(v.x.size());
  return with_kernel(m.kernel_type, [&](auto k) {
    using K = decltype(k);
    if (m.viscosity == ViscosityModel::Laminar)
      return dispatch_diffusion<K, ViscosityModel::Laminar>(m, grid, v, kind, acc, drho);
    return dispatch_diffusion<K, ViscosityModel::Artificial>(m, grid, v, kind, acc, drho);
  });
}

}  // namespace netsph
