#pragma once
// The SPH interaction of particle a with one neighbour b, in the DualSPHysics formulation
// (Crespo et al. 2015, Domínguez et al. 2022), written once for both backends.
//
//   dv_a/dt   = - sum_b m_b ((P_a + P_b) / (rho_a rho_b) + Pi_ab) grad_a W_ab + g
//   drho_a/dt =   sum_b m_b v_ab . grad_a W_ab  +  D_a
//
// with grad_a W_ab = F(r) r_ab, F = (1/r) dW/dr < 0, r_ab = r_a - r_b, v_ab = v_a - v_b.
//
// Artificial viscosity (Monaghan 1992), only for approaching pairs (v_ab . r_ab < 0):
//   Pi_ab = -alpha c0 mu_ab / rho_ab_mean,  mu_ab = h v_ab . r_ab / (r^2 + eta^2)
// Laminar viscosity (Lo & Shao 2002), instead of Pi_ab:
//   dv_a/dt += sum_b m_b 4 nu (r_ab . grad_a W_ab) / ((rho_a + rho_b)(r^2 + eta^2)) v_ab
// Density diffusion D_a (delta-SPH), over fluid neighbours only (boundary densities under
// DBC are not a smooth field, so diffusing towards them would leak mass into walls):
//   Molteni & Colagrossi (2009): D_a = 2 delta h c0 sum_b (rho_a - rho_b) F m_b / rho_b
//   Fourtakas et al. (2019):     (rho_a - rho_b) is replaced by (rho_a - rho_b) - rho^H_ab,
//     the hydrostatic part, rho^H_ab = rho0 ((1 + rho0 g.r_ab / B)^(1/gamma) - 1)
//     ~= rho0^2 g.r_ab / (gamma B) = (rho0 g / c0^2) . r_ab (first order; the neglected
//     term is (g.r_ab/c0^2)^2 ~ 1e-7 relative for pairs within 2h, below float round-off).
// The term drives rho_a towards rho_b: F < 0, so rho_a < rho_b gives a positive rate.
//
// The viscous time-step criterion needs max_b |h v_ab . r_ab / (r^2 + eta^2)| (Monaghan &
// Kos 1999, as DualSPHysics): collected in `visc_dt`.
#include "netsph/core/host_device.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/fluid_model.hpp"

namespace netsph {

/// Running sums of particle a's rates over its neighbours.
struct RateSums {
  Vec3f acc{};       ///< m/s^2, without gravity
  Real drho = 0;     ///< kg/m^3/s
  Real visc_dt = 0;  ///< max |h v_ab.r_ab / (r^2 + eta^2)|, 1/s
};

/// Neighbour b as particle a sees it.
struct Neighbour {
  Vec3f rab;  ///< r_a - r_b, m
  Real r2;    ///< |r_ab|^2 (> 0, < support^2)
  Vec3f vab;  ///< v_a - v_b in the viscous terms, m/s
  /// v_a - v_b in continuity. They differ for a solid b under a mirror slip condition:
  /// continuity sees the solid's own velocity, viscosity the mirrored one (as DualSPHysics'
  /// mDBC2); mirroring in continuity too compresses the fluid along curved no-slip walls.
  Vec3f vab_c;
  Real rho_b;
  Real press_b;
  Real mass_b;
  Real fluid_b;  ///< 1 when b is fluid, 0 otherwise (multiplies the delta-SPH term)
};

/// What one neighbour b adds to particle a's rates.
struct PairRates {
  Vec3f acc;     ///< m/s^2
  Real drho;     ///< kg/m^3/s
  Real visc_dt;  ///< |h v_ab.r_ab / (r^2 + eta^2)|, 1/s (the sums keep the maximum)
};

// The pair functions take the neighbour by value, return by value and use no Vec3 member
// operators (they take `this`): inside an `omp simd` loop any local whose address is taken
// becomes a per-lane array in memory, and that stopped
// GCC 12 from vectorising the pair loops at all (docs/PERFORMANCE.md, "Where the time goes").

/// Fluid particle a: continuity, momentum, viscosity and density diffusion from neighbour b.
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff>
NETSPH_HD PairRates fluid_pair_rates(const FluidModel& m, Real rho_a, Real press_a,
                                     const Neighbour b) {
  const Real r = std::sqrt(b.r2);
  const Real fac = kernel_grad_factor<Kernel>(m.kernel, r);  // grad W = fac * r_ab
  const Real dot_vr = dot(b.vab, b.rab);
  const Real dot_vr_c = dot(b.vab_c, b.rab);
  const Real inv_r2_eta = Real(1) / (b.r2 + m.eta2);

  // Continuity: m_b v_ab . grad W.
  Real drho = b.mass_b * fac * dot_vr_c;

  // Pressure, plus artificial viscosity for approaching pairs.
  Real p_term = (press_a + b.press_b) / (rho_a * b.rho_b);
  const Real mu = m.kernel.h * dot_vr * inv_r2_eta;
  if constexpr (Visc == ViscosityModel::Artificial) {
    const Real pi_ab = -m.alpha * m.eos.c0 * mu * Real(2) / (rho_a + b.rho_b);
    p_term += dot_vr < Real(0) ? pi_ab : Real(0);
  }
  const Real f_p = -b.mass_b * p_term * fac;
  Real ax = b.rab.x * f_p, ay = b.rab.y * f_p, az = b.rab.z * f_p;
  if constexpr (Visc == ViscosityModel::Laminar) {
    const Real lam =
        b.mass_b * Real(4) * m.nu * fac * b.r2 / ((b.r2 + m.eta2_laminar) * (rho_a + b.rho_b));
    ax += b.vab.x * lam, ay += b.vab.y * lam, az += b.vab.z * lam;
  }

  // Density diffusion towards fluid neighbours.
  if constexpr (Diff != DensityDiffusion::None) {
    Real drho_ab = rho_a - b.rho_b;
    if constexpr (Diff == DensityDiffusion::Fourtakas) drho_ab -= dot(m.hydro_grad, b.rab);
    drho += b.fluid_b * m.delta_coef * drho_ab * fac * b.mass_b / b.rho_b;
  }
  return {{ax, ay, az}, drho, mu < Real(0) ? -mu : mu};
}

/// Boundary particle a under DBC (Crespo et al. 2007): only continuity, from fluid neighbours.
template <class Kernel>
NETSPH_HD PairRates boundary_pair_rates(const FluidModel& m, const Neighbour b) {
  const Real r = std::sqrt(b.r2);
  const Real fac = kernel_grad_factor<Kernel>(m.kernel, r);
  const Real dot_vr = dot(b.vab, b.rab);
  const Real dot_vr_c = dot(b.vab_c, b.rab);
  const Real drho = b.fluid_b * b.mass_b * fac * dot_vr_c;
  const Real mu = m.kernel.h * dot_vr / (b.r2 + m.eta2);
  return {{Real(0), Real(0), Real(0)}, drho, (mu < Real(0) ? -mu : mu) * b.fluid_b};
}

}  // namespace netsph
