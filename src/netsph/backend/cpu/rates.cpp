#include "netsph/backend/cpu/rates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "netsph/backend/cpu/neighbour_batch.hpp"
#include "netsph/core/growth.hpp"
#include "netsph/sph/pair_interaction.hpp"

namespace netsph {
namespace {

struct FluidResult {
  RateSums rates;
  Vec3f grad_c{};
  Real div_r = 0;
};

/// The neighbours' fields the scans carry into their batches (CandidateScan::carry), in this
/// order: walls and bodies take the first five, the fluid pass the fluid flag too, and the
/// continuity velocity when it has arrays of its own.
enum Carried { kVx, kVy, kVz, kRho, kPress, kFluid, kCvx, kCvy, kCvz };

inline void carry_fields(const InteractionView& v, int count, CandidateScan& scan) {
  const Real* fields[] = {v.vx.data(),       v.vy.data(),       v.vz.data(),
                          v.rho.data(),      v.press.data(),    v.fluid.data(),
                          v.continuity_vx(), v.continuity_vy(), v.continuity_vz()};
  scan.ncarry = count;
  for (int c = 0; c < count; ++c) scan.carry[c] = fields[c];
}

/// The solids' passes: the neighbours' velocity, density and pressure.
inline void carry_solid_fields(const InteractionView& v, CandidateScan& scan) {
  carry_fields(v, kPress + 1, scan);
}

/// The fluid pass: also the fluid flag, and the continuity velocity where it differs.
inline void carry_fluid_fields(const InteractionView& v, CandidateScan& scan) {
  carry_fields(v, v.has_continuity_velocity() ? kCvz + 1 : kFluid + 1, scan);
}

/// The pair sums of fluid particle a over the first n neighbours of a batch (omp simd: the
/// body is branch-free and reads the neighbours' fields the scan carried, contiguously).
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
inline FluidResult fluid_batch_sums(const FluidModel& model, const InteractionView& v,
                                    std::uint32_t a, const NeighbourBatch& batch, int n) {
  // A local copy: the loop then reads the constants from registers; loads through the
  // reference stay in the loop as masked loads that GCC 12 cannot vectorise.
  const FluidModel m = model;
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  const PairCentre centre = pair_centre(v.rho[a], v.press[a]);
  const Real* __restrict vx = batch.carried[kVx];
  const Real* __restrict vy = batch.carried[kVy];
  const Real* __restrict vz = batch.carried[kVz];
  // Read only, so restrict holds even when these alias vx, vy, vz (no mirrored solid).
  const bool own_cv = v.has_continuity_velocity();
  const Real* __restrict cvx = batch.carried[own_cv ? kCvx : kVx];
  const Real* __restrict cvy = batch.carried[own_cv ? kCvy : kVy];
  const Real* __restrict cvz = batch.carried[own_cv ? kCvz : kVz];
  const Real* __restrict rho = batch.carried[kRho];
  const Real* __restrict press = batch.carried[kPress];
  const Real* __restrict fluid = batch.carried[kFluid];
  const Real* __restrict bdx = batch.dx;
  const Real* __restrict bdy = batch.dy;
  const Real* __restrict bdz = batch.dz;
  const Real* __restrict br2 = batch.r2;
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0;
  Real gx = 0, gy = 0, gz = 0, div = 0;
#pragma omp simd reduction(+ : ax, ay, az, dr, gx, gy, gz, div) reduction(max : vdt)
  for (int k = 0; k < n; ++k) {
    const Real dx = bdx[k], dy = bdy[k], dz = bdz[k], r2 = br2[k];
    const Neighbour nb{{dx, dy, dz},
                       r2,
                       {vxa - vx[k], vya - vy[k], vza - vz[k]},
                       {vxa - cvx[k], vya - cvy[k], vza - cvz[k]},
                       rho[k],
                       press[k],
                       m.mass,
                       fluid[k]};
    const PairRates s = fluid_pair_rates<Kernel, Visc, Diff>(m, centre, nb);
    ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
    vdt = vdt > s.visc_dt ? vdt : s.visc_dt;  // not std::max: its references defeat omp simd
    if constexpr (Shift) {
      const Real vf = s.vol_grad;
      gx += vf * dx, gy += vf * dy, gz += vf * dz;
      div -= vf * r2;
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

inline void accumulate(FluidResult& sum, const FluidResult& part) {
  sum.rates.acc += part.rates.acc;
  sum.rates.drho += part.rates.drho;
  sum.rates.visc_dt = std::max(sum.rates.visc_dt, part.rates.visc_dt);
  sum.grad_c += part.grad_c;
  sum.div_r += part.div_r;
}

/// Sums over the neighbours of fluid particle a: the candidate scan (neighbour_batch.hpp)
/// compacts the neighbours into batches, and fluid_batch_sums sums each batch.
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff, bool Shift>
inline FluidResult fluid_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                              const NeighbourRanges& ranges, int nranges) {
  NeighbourBatch batch;
  FluidResult out;
  const auto sum_full = [&](const NeighbourBatch& b) {
    accumulate(out,
               fluid_batch_sums<Kernel, Visc, Diff, Shift>(m, v, a, b, NeighbourBatch::kCapacity));
  };
  CandidateScan scan{0, 0, 0, v.x.data(), v.y.data(), v.z.data(), a, m.support2};
  carry_fluid_fields(v, scan);
  for (int k = 0; k < nranges; ++k) {
    // The neighbour's position is x[b] + shift: shifting a instead keeps the loop body plain.
    scan.xs = v.x[a] - ranges[k].shift.x;
    scan.ys = v.y[a] - ranges[k].shift.y;
    scan.zs = v.z[a] - ranges[k].shift.z;
    scan_range(scan, ranges[k].begin, ranges[k].end, batch, sum_full);
  }
  if (batch.n > 0)
    accumulate(out, fluid_batch_sums<Kernel, Visc, Diff, Shift>(m, v, a, batch, batch.n));
  return out;
}

/// The continuity sums of wall particle a (DBC, Crespo et al. 2007) over the first n fluid
/// neighbours of a batch.
template <class Kernel>
inline RateSums wall_batch_sums(const FluidModel& model, const InteractionView& v, std::uint32_t a,
                                const NeighbourBatch& batch, int n) {
  // A local copy: the loop then reads the constants from registers; loads through the
  // reference stay in the loop as masked loads that GCC 12 cannot vectorise.
  const FluidModel m = model;
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  // the solid's own velocity
  const Real cxa = v.continuity_vx()[a], cya = v.continuity_vy()[a], cza = v.continuity_vz()[a];
  const Real* __restrict vx = batch.carried[kVx];
  const Real* __restrict vy = batch.carried[kVy];
  const Real* __restrict vz = batch.carried[kVz];
  const Real* __restrict rho = batch.carried[kRho];
  const Real* __restrict press = batch.carried[kPress];
  Real dr = 0, vdt = 0;
#pragma omp simd reduction(+ : dr) reduction(max : vdt)
  for (int k = 0; k < n; ++k) {
    const Neighbour nb{{batch.dx[k], batch.dy[k], batch.dz[k]},
                       batch.r2[k],
                       {vxa - vx[k], vya - vy[k], vza - vz[k]},
                       {cxa - vx[k], cya - vy[k], cza - vz[k]},
                       rho[k],
                       press[k],
                       m.mass,
                       Real(1)};
    const PairRates s = boundary_pair_rates<Kernel>(m, nb);
    dr += s.drho;
    vdt = vdt > s.visc_dt ? vdt : s.visc_dt;  // not std::max: its references defeat omp simd
  }
  return {{}, dr, vdt};
}

/// Wall particle a: the scan keeps its fluid (and buffer) neighbours only.
template <class Kernel>
inline RateSums wall_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                          const NeighbourRanges& ranges, int nranges) {
  RateSums out;
  CandidateScan scan{v.x[a],     v.y[a], v.z[a],     v.x.data(),    v.y.data(),
                     v.z.data(), a,      m.support2, v.fluid.data()};
  carry_solid_fields(v, scan);
  scan_ranges(scan, ranges, nranges, [&](const NeighbourBatch& b, int n) {
    const RateSums s = wall_batch_sums<Kernel>(m, v, a, b, n);
    out.drho += s.drho;
    out.visc_dt = std::max(out.visc_dt, s.visc_dt);
  });
  return out;
}

/// Body particle a: pressure and viscous force from fluid and buffer neighbours only (the
/// body's share of the pairwise forces), and continuity from them, over the first n of a
/// batch. Walls and other bodies act through contact (backend/cpu/contact).
/// The body sees gauge pressures (the EOS background removed): a uniform pressure has no net
/// force on a closed body, but the SPH sum only cancels it where the fluid covers the body
/// evenly, and a wake never does, so the background would add a spurious drag (+2.5% of Cd
/// per 100 Pa in the DFG case at D/dp = 10; docs/VALIDATION.md). The fluid keeps the full
/// pressures (its repulsion from the body); the two differ by that spurious force only.
template <class Kernel, ViscosityModel Visc>
inline RateSums body_batch_sums(const FluidModel& model, const InteractionView& v, std::uint32_t a,
                                const NeighbourBatch& batch, int n) {
  // A local copy: the loop then reads the constants from registers; loads through the
  // reference stay in the loop as masked loads that GCC 12 cannot vectorise.
  const FluidModel m = model;
  const Real vxa = v.vx[a], vya = v.vy[a], vza = v.vz[a];
  // the solid's own velocity
  const Real cxa = v.continuity_vx()[a], cya = v.continuity_vy()[a], cza = v.continuity_vz()[a];
  const Real p_bg = m.eos.p_background;
  const PairCentre centre = pair_centre(v.rho[a], v.press[a] - p_bg);
  const Real* __restrict vx = batch.carried[kVx];
  const Real* __restrict vy = batch.carried[kVy];
  const Real* __restrict vz = batch.carried[kVz];
  const Real* __restrict rho = batch.carried[kRho];
  const Real* __restrict press = batch.carried[kPress];
  Real ax = 0, ay = 0, az = 0, dr = 0, vdt = 0;
#pragma omp simd reduction(+ : ax, ay, az, dr) reduction(max : vdt)
  for (int k = 0; k < n; ++k) {
    const Neighbour nb{{batch.dx[k], batch.dy[k], batch.dz[k]},
                       batch.r2[k],
                       {vxa - vx[k], vya - vy[k], vza - vz[k]},
                       {cxa - vx[k], cya - vy[k], cza - vz[k]},
                       rho[k],
                       press[k] - p_bg,
                       m.mass,
                       Real(1)};
    const PairRates s = fluid_pair_rates<Kernel, Visc, DensityDiffusion::None>(m, centre, nb);
    ax += s.acc.x, ay += s.acc.y, az += s.acc.z, dr += s.drho;
    vdt = vdt > s.visc_dt ? vdt : s.visc_dt;  // not std::max: its references defeat omp simd
  }
  return {{ax, ay, az}, dr, vdt};
}

template <class Kernel, ViscosityModel Visc>
inline RateSums body_sums(const FluidModel& m, const InteractionView& v, std::uint32_t a,
                          const NeighbourRanges& ranges, int nranges) {
  RateSums out;
  CandidateScan scan{v.x[a],     v.y[a], v.z[a],     v.x.data(),    v.y.data(),
                     v.z.data(), a,      m.support2, v.fluid.data()};
  carry_solid_fields(v, scan);
  scan_ranges(scan, ranges, nranges, [&](const NeighbourBatch& b, int n) {
    const RateSums s = body_batch_sums<Kernel, Visc>(m, v, a, b, n);
    out.acc += s.acc;
    out.drho += s.drho;
    out.visc_dt = std::max(out.visc_dt, s.visc_dt);
  });
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
          if (!v.reduce_mask || v.reduce_mask[a]) {
            max_acc2 = std::max(max_acc2, static_cast<double>(norm2(total)));
            max_visc = std::max(max_visc, static_cast<double>(r.rates.visc_dt));
          }
          if constexpr (Shift) shifting->grad_c[a] = r.grad_c, shifting->div_r[a] = r.div_r;
          break;
        }
        case ParticleKind::Wall: {
          const RateSums s = wall_sums<Kernel>(m, v, a, ranges, nranges);
          acc[a] = {};
          drho[a] = s.drho;
          if (!v.reduce_mask || v.reduce_mask[a])
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
          if (!v.reduce_mask || v.reduce_mask[a])
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
  resize_for(acc, v.x.size());
  resize_for(drho, v.x.size());
  if (shifting) resize_for(shifting->grad_c, v.x.size()), resize_for(shifting->div_r, v.x.size());
  return with_kernel(m.kernel_type, [&](auto k) {
    using K = decltype(k);
    if (m.viscosity == ViscosityModel::Laminar)
      return dispatch_diffusion<K, ViscosityModel::Laminar>(m, grid, v, kind, acc, drho, shifting);
    return dispatch_diffusion<K, ViscosityModel::Artificial>(m, grid, v, kind, acc, drho, shifting);
  });
}

}  // namespace netsph
