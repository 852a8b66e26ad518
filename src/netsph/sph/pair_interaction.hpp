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

/// Particle a's own fields in its pair terms: 1/rho_a is taken once a particle, not once a pair.
struct PairCentre {
  Real rho;      ///< kg/m^3
  Real press;    ///< Pa
  Real inv_rho;  ///< 1 / rho, m^3/kg
};

NETSPH_HD PairCentre pair_centre(Real rho, Real press) {
  return {rho, press, Real(1) / rho};
}

/// What one neighbour b adds to particle a's rates.
struct PairRates {
  Vec3f acc;     ///< m/s^2
  Real drho;     ///< kg/m^3/s
  Real visc_dt;  ///< |h v_ab.r_ab / (r^2 + eta^2)|, 1/s (the sums keep the maximum)
  /// V_b F = (m_b / rho_b) (1/r) dW/dr, 1/m^2: grad_a W_ab weighted by b's volume, for the
  /// shifting sums (Lind et al. 2012) grad C_a = sum V_b F r_ab and div r_a = -sum V_b F r^2.
  Real vol_grad;
};

// The pair functions take the neighbour by value, return by value and use no Vec3 member
// operators (they take `this`): inside an `omp simd` loop any local whose address is taken
// becomes a per-lane array in memory, and that stopped
// GCC 12 from vectorising the pair loops at all (docs/PERFORMANCE.md, "Where the time goes").

/// Fluid particle a: continuity, momentum, viscosity and density diffusion from neighbour b.
///
/// One division a pair. The terms divide by rho_b (pressure, diffusion, V_b), by
/// r^2 + eta^2 (mu) and by the viscosity's density mean; an IEEE float division costs a GPU
/// thread about ten instructions and a slow-path test, a multiplication one. So the three
/// denominators are multiplied together, inverted once, and each reciprocal is recovered by
/// multiplying the inverse by the other two: 1/x = (1/(x y z)) y z. Each reciprocal is then a
/// few ulps from the divided one, far inside float's round-off of the sums; the product stays
/// well within float's range (1e-16 to 1e12 for h from 0.1 mm to 10 m, rho ~ 1e3).
template <class Kernel, ViscosityModel Visc, DensityDiffusion Diff>
NETSPH_HD PairRates fluid_pair_rates(const FluidModel& m, const PairCentre a, const Neighbour b) {
  const Real r = std::sqrt(b.r2);
  const Real fac = kernel_grad_factor<Kernel>(m.kernel, r);  // grad W = fac * r_ab
  const Real dot_vr = dot(b.vab, b.rab);
  const Real dot_vr_c = dot(b.vab_c, b.rab);

  // The viscosity's denominator besides r^2 + eta^2: rho_a + rho_b (artificial, twice the
  // mean) or (rho_a + rho_b)(r^2 + eta_laminar^2) (laminar).
  Real visc_den = a.rho + b.rho_b;
  if constexpr (Visc == ViscosityModel::Laminar) visc_den *= b.r2 + m.eta2_laminar;
  const Real r2_eta = b.r2 + m.eta2;
  const Real both = r2_eta * visc_den;
  const Real inv_all = Real(1) / (both * b.rho_b);
  const Real inv_rho_b = inv_all * both;
  const Real inv_both = inv_all * b.rho_b;
  const Real inv_r2_eta = inv_both * visc_den;
  const Real inv_visc_den = inv_both * r2_eta;

  // Continuity: m_b v_ab . grad W.
  Real drho = b.mass_b * fac * dot_vr_c;
  const Real vol_grad = b.mass_b * inv_rho_b * fac;

  // Pressure, plus artificial viscosity for approaching pairs.
  Real p_term = (a.press + b.press_b) * (a.inv_rho * inv_rho_b);
  const Real mu = m.kernel.h * dot_vr * inv_r2_eta;
  if constexpr (Visc == ViscosityModel::Artificial) {
    const Real pi_ab = -m.alpha * m.eos.c0 * mu * Real(2) * inv_visc_den;
    p_term += dot_vr < Real(0) ? pi_ab : Real(0);
  }
  const Real f_p = -b.mass_b * p_term * fac;
  Real ax = b.rab.x * f_p, ay = b.rab.y * f_p, az = b.rab.z * f_p;
  if constexpr (Visc == ViscosityModel::Laminar) {
    const Real lam = b.mass_b * Real(4) * m.nu * fac * b.r2 * inv_visc_den;
    ax += b.vab.x * lam, ay += b.vab.y * lam, az += b.vab.z * lam;
  }

  // Density diffusion towards fluid neighbours: delta_coef (rho_a - rho_b) F m_b / rho_b.
  if constexpr (Diff != DensityDiffusion::None) {
    Real drho_ab = a.rho - b.rho_b;
    if constexpr (Diff == DensityDiffusion::Fourtakas) drho_ab -= dot(m.hydro_grad, b.rab);
    drho += b.fluid_b * m.delta_coef * drho_ab * vol_grad;
  }
  return {{ax, ay, az}, drho, mu < Real(0) ? -mu : mu, vol_grad};
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
  return {{Real(0), Real(0), Real(0)}, drho, (mu < Real(0) ? -mu : mu) * b.fluid_b, Real(0)};
}

}  // namespace netsph
