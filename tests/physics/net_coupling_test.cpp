// Two-way net-fluid coupling: one knot on one twine in a steady current
// (cases/net_tethered_knot.toml). The fluid pushes the knot downstream, the twine holds it;
// once it has settled, the time-averaged forces on it balance and the twine points along
// their sum; the stiff twine does not shorten the fluid time step. (cases/net_panel_channel.toml,
// a 3 x 3-knot panel, is the larger demonstration of the same coupling.)
#include <gtest/gtest.h>

#include <cmath>

#include "case_runs.hpp"
#include "netsph/backend/cpu/probe_pass.hpp"
#include "netsph/net/current_loads.hpp"
#include "netsph/net/knot_spring_solver.hpp"

namespace netsph {
namespace {

// One knot on one twine (cases/net_tethered_knot.toml): over the second half of the run the
// time averages of the forces on the free knot balance, fluid + twine + weight less buoyancy
// = 0 within 2% of the fluid force, and the twine points where they say: its angle from the
// vertical is atan(drag / (submerged weight - lift)). The fluid force is the resolved one on
// the knot plus the modelled drag of its sinker bar (0.1 m x 10 mm): cylinder drag on the
// water's velocity sampled along the bar, which is the fluid's there (sampled again with the
// probes' sampler at the end), and which beside the plate runs faster than the current.
TEST(NetCoupling, TetheredKnotSettlesWhereTwineBalancesFluidForce) {
  Simulation sim(test::load_case("net_tethered_knot.toml"));
  ASSERT_EQ(sim.nets().size(), 1u);
  const CoupledNet& net = sim.nets()[0];
  ASSERT_EQ(net.model.knots.size(), 2u);
  ASSERT_EQ(net.model.twines.size(), 1u);
  const int free_knot = net.model.knots[0].fixed ? 1 : 0;
  const int anchor = 1 - free_knot;
  ASSERT_TRUE(net.model.knots[anchor].fixed);
  const Vec3d weight = net.model.knots[free_knot].constant_force;
  ASSERT_LT(weight.z, -0.5);  // knot and sinker, less buoyancy: about 0.61 N

  const double t0 = 1.25, t1 = sim.spec().simulation.end_time;
  // The fluid sets dt (c0 = 3 m/s, h = 15 mm: about 1e-3 s); the twine (k = 3.8e6 N/m on a
  // 0.13 kg knot, a period of 1.2e-3 s) is sub-cycled instead and must not shorten it.
  sim.step();
  const double dt_first = sim.last_dt();
  double dt_smallest = dt_first;
  while (sim.time() < t0) {
    sim.step();
    dt_smallest = std::min(dt_smallest, sim.last_dt());
  }
  EXPECT_GT(dt_smallest, 0.9 * dt_first);
  const Vec3d v0 = sim.bodies()[net.first_body + free_knot].state.vel;
  Vec3d fluid{}, twine{}, offset{}, sinker{};
  double weight_sum = 0;
  std::vector<Vec3d> twine_now;
  while (sim.time() < t1) {
    sim.step();
    const double dt = sim.last_dt();
    NetModel model = sim.nets()[0].model;  // the knots as the corrector left them
    KnotSpringSolver solver(model);
    solver.twine_forces(twine_now);
    const RigidBody& knot = sim.bodies()[net.first_body + free_knot];
    fluid += (knot.fluid_force + knot.modelled_force) * dt;
    sinker += knot.modelled_force * dt;
    twine += twine_now[free_knot] * dt;
    offset += (model.knots[free_knot].position - model.knots[anchor].position) * dt;
    weight_sum += dt;
  }
  fluid = fluid / weight_sum, twine = twine / weight_sum, offset = offset / weight_sum;
  sinker = sinker / weight_sum;
  const double bar_drag = 0.5 * 1000 * 1.2 * 0.01 * 0.1 * 0.3 * 0.3;  // 0.054 N
  std::printf("sinker drag (%.4f, %.4f, %.4f) N; at the current %.4f N\n", sinker.x, sinker.y,
              sinker.z, bar_drag);
  EXPECT_GT(sinker.x, bar_drag);  // the water passes the plate faster than the current
  EXPECT_LT(sinker.x, 3 * bar_drag);
  EXPECT_NEAR(sinker.y, 0, 0.02 * bar_drag);
  {
    // The flow the bar took in the last stage is the fluid's at its sample points (sampled
    // again half a step later, at the step's end, by the probes' sampler).
    const NetModel& model = sim.nets()[0].model;
    SinkerSamples at;
    const int n = sinker_sample_points(model, model.knots[free_knot], at);
    std::vector<ShepardValue> values(n);
    sample_points(sim.model(), sim.grid(), sim.particles(), std::span<const Vec3d>(at.points, n),
                  values);
    Vec3d mean{};
    for (int i = 0; i < n; ++i) mean += values[i].velocity * at.weights[i];
    const Vec3d taken = sim.nets()[0].sinker_flow[free_knot];
    std::printf("flow at the bar (%.4f, %.4f, %.4f) m/s, sampled again (%.4f, %.4f, %.4f) m/s\n",
                taken.x, taken.y, taken.z, mean.x, mean.y, mean.z);
    EXPECT_NEAR(norm(taken - mean), 0, 0.02 * norm(mean));
    const RigidBody& knot = sim.bodies()[net.first_body + free_knot];
    EXPECT_NEAR(
        norm(knot.modelled_force - sinker_drag(model, model.knots[free_knot], taken, 1000.0)), 0,
        1e-12);
  }
  const Vec3d residual = fluid + twine + weight;
  // What is left of the residual is the knot's change of momentum over the window.
  const Vec3d v1 = sim.bodies()[net.first_body + free_knot].state.vel;
  const Vec3d inertia = (v1 - v0) * (net.model.knots[free_knot].mass / weight_sum);
  std::printf("change of momentum over the window / its length: %.2e N\n", norm(inertia));
  std::printf("mean fluid force (%.4f, %.4f, %.4f) N, twine (%.4f, %.4f, %.4f) N, weight %.4f N\n",
              fluid.x, fluid.y, fluid.z, twine.x, twine.y, twine.z, weight.z);
  const double angle = std::atan2(offset.x, -offset.z);
  const double expected = std::atan2(fluid.x, -(weight.z + fluid.z));
  std::printf(
      "residual %.2e N (%.3f%% of the fluid force); twine angle %.3f deg, force angle "
      "%.3f deg\n",
      norm(residual), 100 * norm(residual) / norm(fluid), angle * 180 / 3.14159265,
      expected * 180 / 3.14159265);
  EXPECT_GT(fluid.x, 0.1);  // a real drag: a 63 mm plate at 0.3 m/s takes about 0.25 N
  EXPECT_LT(norm(residual), 0.02 * norm(fluid));
  // What remains is the knot's change of momentum: the forces that moved it are exactly these
  // three (the coupling loses nothing between the fluid, the twine and the knot).
  std::printf("residual less the change of momentum: %.2e N\n", norm(residual - inertia));
  EXPECT_LT(norm(residual - inertia), 0.005 * norm(fluid));
  EXPECT_NEAR(angle, expected, 0.02 * expected);
  // The twine is taut and stretched by the load it carries, as its law says.
  EXPECT_NEAR(norm(offset), net.model.twines[0].rest, 0.01 * net.model.twines[0].rest);
}

}  // namespace
}  // namespace netsph
