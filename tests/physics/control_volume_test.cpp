// Control volume around a fixed body (cases/cylinder_control_volume2d.toml): in a steady 2D
// flow between free-slip walls, the drag per unit depth on the cylinder equals the drop of the
// momentum-and-pressure flux between a plane upstream and a plane downstream of it,
//
//   F_x = M(x1) - M(x2),   M(x) = integral_0^H (p + rho u_x^2) dz
//
// (momentum balance of the box x1 < x < x2 spanning the channel; free-slip walls take no
// x-momentum, and the viscous normal stress 2 mu du/dx is negligible on planes 1.5 D from
// the body). The body force comes from the pairwise SPH forces on its particles; M comes
// from the fluid particles alone, Shepard-interpolated on the two planes: two independent
// measurements that must agree within 5%.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_runs.hpp"

namespace netsph {
namespace {

/// M(x) = integral over z of (p + rho u_x^2), with p, rho and u_x Shepard-interpolated from the
/// fluid particles at points dp/2 apart along the plane x.
double momentum_flux(const Simulation& sim, const std::vector<float>& press, double x,
                     double height) {
  const ParticleSet& p = sim.particles();
  const FluidModel& m = sim.model();
  std::vector<std::size_t> strip;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (is_fluid(p.kind[i]) && std::fabs(p.pos[i].x - x) < m.support) strip.push_back(i);
  const double dz = 0.5 * sim.spec().simulation.dp;
  const int n = static_cast<int>(std::lround(height / dz));
  double flux = 0;
  for (int k = 0; k <= n; ++k) {
    const Vec3d point{x, 0, k * dz};
    double w_sum = 0, f_sum = 0;
    for (std::size_t i : strip) {
      const double r = norm(p.pos[i] - point);
      if (r >= m.support) continue;
      const double w = static_cast<double>(m.mass) / p.rho[i] *
                       kernel_value<WendlandC2>(m.kernel, static_cast<Real>(r));
      const double u = p.vel[i].x;
      w_sum += w;
      f_sum += w * (press[i] + p.rho[i] * u * u);
    }
    const double weight = (k == 0 || k == n) ? 0.5 : 1.0;  // trapezoidal rule
    if (w_sum > 0) flux += weight * dz * f_sum / w_sum;
  }
  return flux;
}

TEST(ControlVolume, CylinderDragEqualsMomentumFluxDrop) {
  Simulation sim(test::load_case("cylinder_control_volume2d.toml"));
  const double height = 0.41, x_body = 0.3, diameter = 0.1;
  const double x1 = x_body - 1.5 * diameter, x2 = x_body + 3.0 * diameter;
  const double t0 = 4.0, t1 = sim.spec().simulation.end_time;
  test::run_until(sim, t0);
  double drag = 0, flux_drop = 0;
  int samples = 0;
  while (sim.time() < t1) {
    sim.step();
    if (sim.steps() % 25 != 0) continue;
    const std::vector<float> press = sim.pressures();
    drag += sim.bodies()[0].fluid_force.x;
    flux_drop += momentum_flux(sim, press, x1, height) - momentum_flux(sim, press, x2, height);
    ++samples;
  }
  ASSERT_GT(samples, 20);
  drag /= samples, flux_drop /= samples;
  const double cd = drag / (0.5 * 1000.0 * 0.2 * 0.2 * diameter);
  RecordProperty("drag_N_per_m", std::to_string(drag));
  RecordProperty("flux_drop_N_per_m", std::to_string(flux_drop));
  std::printf("drag %.4f N/m (Cd %.3f), momentum-flux drop %.4f N/m, ratio %.4f\n", drag, cd,
              flux_drop, drag / flux_drop);
  // A real drag: an unbounded cylinder at Re = 20 has Cd = 2.0-2.1 (Tritton 1959), and the
  // channel's blockage D/H = 0.24 raises it.
  EXPECT_GT(cd, 2.0);
  EXPECT_NEAR(drag / flux_drop, 1.0, 0.05);
}

}  // namespace
}  // namespace netsph
