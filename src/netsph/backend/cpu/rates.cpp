#include "netsph/backend/cpu/rates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "netsph/sph/pair_interaction.hpp"

namespace netsph {
namespace {

struct FluidResult {
  RateSums rates;
  Vec3f grad_c{};
  Real div_r = 0;
};

/// Sums over the neighbours of fluid particle a. The loop body is branch-free apart from the
/// range test so that the compiler vectorises it (omp simd with explicit reductions).
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
inline FluidResult fluid_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                              const NeighbourRanges& ranges, int nranges) {
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const Real rho_a = v.rho[a], press_a = v.press[a];
  const Real* __restrict x = v.x.data();
  const Real* __restrict y = v.y.data();
  const Real* __restrict z = v.z.data();
  const Real* __restrict vx = v.vx.data();
  const Real* __restrict vy = v.vy.data();
  const Real* __restrict vz = v.vz.data();
  const Real* __restrict cvx = v.cvx.data();
  const Real* __restrict cvy = v.cvy.data();
  const Real* __restrict cvz = v.cvz.data();
  const Real* __restrict rho = v.rho.data();
  const Real* __restrict press = v.press.data();
  const Real* __restrict fluid = v.fluid.data();
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0;
  Real gx = 0, gy = 0, gz = 0, div = 0;
  for (int k = 0; k < nranges; ++k) {
    const std::uint32_t b0 = ranges[k].begin, b1 = ranges[k].end;
    // The neighbour's position is x[b] + shift: shifting a instead keeps the loop body plain.
    const Real xs = xa - ranges[k].shift.x, ys = ya - ranges[k].shift.y,
               zs = za - ranges[k].shift.z;
#pragma omp simd reduction(+ : ax, ay, az, dr, gx, gy, gz, div) reduction(max : vdt)
    for (std::uint32_t b = b0; b < b1; ++b) {
      const Real dx = xs - x[b], dy = ys - y[b], dz = zs - z[b];
      const Real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < m.support2 && b != a) {
        const Neighbour nb{{dx, dy, dz},
                           r2,
                           {vxa - vx[b], vya - vy[b], vza - vz[b]},
                           {vxa - cvx[b], vya - cvy[b], vza - cvz[b]},
                           rho[b],
                           press[b],
                           m.mass,
                           fluid[b]};
        RateSums s;
        fluid_pair_rates<Kernel, Visc, Diff>(m, rho_a, press_a, nb, s);
        ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
        vdt = std::max(vdt, s.visc_dt);
        if constexpr (Shift) {
          // grad_a W = F r_ab; V_b = m / rho_b (Lind et al. 2012).
          const Real vf = m.mass / rho[b] * kernel_grad_factor<Kernel>(m.kernel, std::sqrt(r2));
          gx += vf * dx, gy += vf * dy, gz += vf * dz;
          div -= vf * r2;
        }
      }
    }
  }
  FluidResult out;
  out.rates.acc = {ax, ay, az};
  out.rates.drho = dr;
  out.rates.visc_dt = vdt;
  out.grad_c = {gx, gy, gz};
  out.div_r = div;
  return out;
}

template <class Kernel>
inline RateSums wall_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                          const NeighbourRanges& ranges, int nranges) {
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const Real cxa = v.cvx[a], cya = v.cvy[a], cza = v.cvz[a];  // the solid's own velocity
  Real dr = 0, vdt = 0;
  for (int k = 0; k < nranges; ++k) {
    const std::uint32_t b0 = ranges[k].begin, b1 = ranges[k].end;
    const Real xs = xa - ranges[k].shift.x, ys = ya - ranges[k].shift.y,
               zs = za - ranges[k].shift.z;
#pragma omp simd reduction(+ : dr) reduction(max : vdt)
    for (std::uint32_t b = b0; b < b1; ++b) {
      const Real dx = xs - v.x[b], dy = ys - v.y[b], dz = zs - v.z[b];
      const Real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < m.support2 && v.fluid[b] > Real(0)) {
        const Neighbour nb{{dx, dy, dz},
                           r2,
                           {vxa - v.vx[b], vya - v.vy[b], vza - v.vz[b]},
                           {cxa - v.vx[b], cya - v.vy[b], cza - v.vz[b]},
                           v.rho[b],
                           v.press[b],
                           m.mass,
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

/// Body particle a: pressure and viscous force from fluid and buffer neighbours only (the
/// body's share of the pairwise forces), and continuity from them. Walls and other bodies act
/// through contact (backend/cpu/contact).
/// The body sees gauge pressures (the EOS background removed): a uniform pressure has no net
/// force on a closed body, but the SPH sum only cancels it where the fluid covers the body
/// evenly, and a wake never does, so the background would add a spurious drag (+2.5% of Cd
/// per 100 Pa in the DFG case at D/dp = 10; docs/VALIDATION.md). The fluid keeps the full
/// pressures (its repulsion from the body); the two differ by that spurious force only.
template <class Kernel, ViscosityModel Visc>
inline RateSums body_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                          const NeighbourRanges& ranges, int nranges) {
  const Real xa = v.x[a], ya = v.y[a], za = v.z[a];
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const Real cxa = v.cvx[a], cya = v.cvy[a], cza = v.cvz[a];  // the solid's own velocity
  const Real p_bg = m.eos.p_background;
  const Real rho_a = v.rho[a], press_a = v.press[a] - p_bg;
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0;
  for (int k = 0; k < nranges; ++k) {
    const std::uint32_t b0 = ranges[k].begin, b1 = ranges[k].end;
    const Real xs = xa - ranges[k].shift.x, ys = ya - ranges[k].shift.y,
               zs = za - ranges[k].shift.z;
#pragma omp simd reduction(+ : ax, ay, az, dr) reduction(max : vdt)
    for (std::uint32_t b = b0; b < b1; ++b) {
      const Real dx = xs - v.x[b], dy = ys - v.y[b], dz = zs - v.z[b];
      const Real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < m.support2 && v.fluid[b] > Real(0)) {
        const Neighbour nb{{dx, dy, dz},
                           r2,
                           {vxa - v.vx[b], vya - v.vy[b], vza - v.vz[b]},
                           {cxa - v.vx[b], cya - v.vy[b], cza - v.vz[b]},
                           v.rho[b],
                           v.press[b] - p_bg,
                           m.mass,
                           v.fluid[b]};
        RateSums s;
        fluid_pair_rates<Kernel, Visc, DensityDiffusion::None>(m, rho_a, press_a, nb, s);
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

template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
RateReductions rates_loop(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                          std::span<const ParticleKind> kind, std::vector<Vec3f>& acc,
                          std::vector<Real>& drho, ShiftingSums* shifting) {
  const auto& cells = grid.occupied_cells();
  const auto ncells = static_cast<std::int64_t>(cells.size());
  double max_acc2 = 0, max_visc = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(max : max_acc2, max_visc)
  for (std::int64_t k = 0; k < ncells; ++k) {
    const std::int64_t c = cells[k];
    const IndexRange own = grid.cell_range(c);
    NeighbourRanges ranges;
    const int nranges = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t a = own.begin; a < own.end; ++a) {
      switch (kind[a]) {
        case ParticleKind::Fluid: {
          const FluidResult r = fluid_sums<Kernel, Visc, Diff, Shift>(m, v, a, ranges, nranges);
          const Vec3f total = r.rates.acc + m.gravity;
          acc[a] = total;
          drho[a] = r.rates.drho;
          max_acc2 = std::max(max_acc2, static_cast<double>(norm2(total)));
          max_visc = std::max(max_visc, static_cast<double>(r.rates.visc_dt));
          if constexpr (Shift) shifting->grad_c[a] = r.grad_c, shifting->div_r[a] = r.div_r;
          break;
        }
        case ParticleKind::Wall: {
          const RateSums s = wall_sums<Kernel>(m, v, a, ranges, nranges);
          acc[a] = {};
          drho[a] = s.drho;
          max_visc = std::max(max_visc, static_cast<double>(s.visc_dt));
          break;
        }
        case ParticleKind::Buffer:
          acc[a] = {};
          drho[a] = 0;
          break;
        case ParticleKind::Body: {
          const RateSums s = body_sums<Kernel, Visc>(m, v, a, ranges, nranges);
          acc[a] = s.acc;  // no gravity: the body's weight acts on its centre of mass
          drho[a] = s.drho;
          max_visc = std::max(max_visc, static_cast<double>(s.visc_dt));
          break;
        }
      }
    }
  }
  return {std::sqrt(max_acc2), max_visc};
}

template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff>
RateReductions dispatch_shifting(const FluidModel& m, const CellGrid& g, const InteractionView& v,
                                 std::span<const ParticleKind> k, std::vector<Vec3f>& acc,
                                 std::vector<Real>& drho, ShiftingSums* sh) {
  if (sh) return rates_loop<Kernel, Visc, Diff, true>(m, g, v, k, acc, drho, sh);
  return rates_loop<Kernel, Visc, Diff, false>(m, g, v, k, acc, drho, sh);
}

template <class Kernel, ViscosityModel Visc>
RateReductions dispatch_diffusion(const FluidModel& m, const CellGrid& g, const InteractionView& v,
                                  std::span<const ParticleKind> k, std::vector<Vec3f>& acc,
                                  std::vector<Real>& drho, ShiftingSums* sh) {
  switch (m.diffusion) {
    case DensityDiffusion::None:
      return dispatch_shifting<Kernel, Visc, DensityDiffusion::None>(m, g, v, k, acc, drho, sh);
    case DensityDiffusion::Molteni:
      return dispatch_shifting<Kernel, Visc, DensityDiffusion::Molteni>(m, g, v, k, acc, drho, sh);
    case DensityDiffusion::Fourtakas:
      return dispatch_shifting<Kernel, Visc, DensityDiffusion::Fourtakas>(m, g, v, k, acc, drho,
                                                                          sh);
  }
  return {};
}

}  // namespace

RateReductions compute_rates(const FluidModel& m, const CellGrid& grid, const InteractionView& v,
                             std::span<const ParticleKind> kind, std::vector<Vec3f>& acc,
                             std::vector<Real>& drho, ShiftingSums* shifting) {
  acc.resize(v.x.size());
  drho.resize(v.x.size());
  if (shifting) shifting->grad_c.resize(v.x.size()), shifting->div_r.resize(v.x.size());
  return with_kernel(m.kernel_type, [&](auto k) {
    using K = decltype(k);
    if (m.viscosity == ViscosityModel::Laminar)
      return dispatch_diffusion<K, ViscosityModel::Laminar>(m, grid, v, kind, acc, drho, shifting);
    return dispatch_diffusion<K, ViscosityModel::Artificial>(m, grid, v, kind, acc, drho, shifting);
  });
}

}  // namespace netsph
