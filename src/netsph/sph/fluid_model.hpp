#pragma once
// The constants of one run's fluid model, as a plain struct both backends receive by value.
#include "netsph/core/physics_options.hpp"
#include "netsph/core/real.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/equation_of_state.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph {

struct FluidModel {
  int dims = 3;
  KernelType kernel_type = KernelType::Wendland;
  ViscosityModel viscosity = ViscosityModel::Artificial;
  DensityDiffusion diffusion = DensityDiffusion::Molteni;

  KernelScale kernel;
  TaitEos eos;
  Real support = 0;  ///< kernel support radius 2h, m
  Real support2 = 0;
  Real eta2 = 0;  ///< 0.01 h^2: keeps the 1/r^2 terms finite for close pairs
  /// 1e-4 h^2 for the laminar term: 0.01 h^2 there lowers the effective viscosity by 1.3%
  /// on a lattice (r^2/(r^2+eta^2) at the nearest neighbours), a bias that does not converge
  /// with dp; particles never come closer than ~dp/2 in practice, so the smaller value is safe.
  Real eta2_laminar = 0;
  Real mass = 0;        ///< particle mass rho0 dp^dims, kg (fluid and boundary alike)
  Real alpha = 0;       ///< artificial viscosity coefficient
  Real nu = 0;          ///< laminar kinematic viscosity, m^2/s
  Real delta_coef = 0;  ///< 2 delta h c0, the delta-SPH prefactor
  Vec3f gravity{};      ///< m/s^2
  Vec3f hydro_grad{};   ///< rho0 g / c0^2: hydrostatic density gradient (Fourtakas et al. 2019)
};

struct FluidModelInput {
  int dims = 3;
  double dp = 0;
  double h_over_dp = 1.5;
  KernelType kernel = KernelType::Wendland;
  double rho0 = 1000;
  double c0 = 0;
  double gamma = 7;
  double p_background = 0;  ///< Pa
  Vec3d gravity{0, 0, -9.81};
  ViscosityModel viscosity = ViscosityModel::Artificial;
  double alpha = 0.01;
  double nu = 1e-6;
  DensityDiffusion diffusion = DensityDiffusion::Molteni;
  double delta = 0.1;
};

inline FluidModel make_fluid_model(const FluidModelInput& in) {
  FluidModel m;
  const double h = in.h_over_dp * in.dp;
  m.dims = in.dims;
  m.kernel_type = in.kernel;
  m.viscosity = in.viscosity;
  m.diffusion = in.diffusion;
  m.kernel =
      with_kernel(in.kernel, [&](auto k) { return make_kernel_scale<decltype(k)>(in.dims, h); });
  m.eos = TaitEos::make(in.rho0, in.c0, in.gamma, in.p_background);
  m.support = static_cast<Real>(2 * h);
  m.support2 = static_cast<Real>(4 * h * h);
  m.eta2 = static_cast<Real>(0.01 * h * h);
  m.eta2_laminar = static_cast<Real>(1e-4 * h * h);
  m.mass = static_cast<Real>(in.rho0 * (in.dims == 2 ? in.dp * in.dp : in.dp * in.dp * in.dp));
  m.alpha = static_cast<Real>(in.alpha);
  m.nu = static_cast<Real>(in.nu);
  m.delta_coef = static_cast<Real>(2 * in.delta * h * in.c0);
  m.gravity = Vec3f(in.gravity);
  m.hydro_grad = Vec3f(in.gravity * (in.rho0 / (in.c0 * in.c0)));
  return m;
}

}  // namespace netsph
