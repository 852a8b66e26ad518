// Two-way net-fluid coupling (cases/net_panel_channel.toml: a 3 x 3-knot panel anchored at
// top and bottom in a 0.3 m/s duct flow). The fluid pushes the free middle row downstream;
// the twines hold it: at every moment the free knots' twine force balances the fluid force
// (the knots are light and the twines stiff, so they follow the flow quasi-statically), and
// the stiff twines do not shorten the fluid time step.
#include <gtest/gtest.h>

#include <cmath>

#include "case_runs.hpp"
#include "netsph/net/knot_spring_solver.hpp"

namespace netsph {
namespace {

TEST(NetCoupling, FreeKnotsBalanceFluidAndTwines) {
  Simulation sim(test::load_case("net_panel_channel.toml"));
  ASSERT_EQ(sim.nets().size(), 1u);
  ASSERT_EQ(sim.nets()[0].model.knots.size(), 9u);
  sim.step();
  const double dt_first = sim.last_dt();
  double dt_smallest = dt_first;
  while (sim.time() < 0.3) {
    sim.step();
    dt_smallest = std::min(dt_smallest, sim.last_dt());
  }
  // The fluid sets dt (c0 = 3 m/s, h = 0.015 m): the twines, k ~ 6e6 N/m on 0.1 kg knots
  // (a period of 1e-3 s, the fluid dt itself), are sub-cycled instead.
  EXPECT_GT(dt_smallest, 0.95 * dt_first);

  const CoupledNet& net = sim.nets()[0];
  NetModel model = net.model;
  KnotSpringSolver solver(model);
  std::vector<Vec3d> twine;
  solver.twine_forces(twine);
  int free = 0;
  for (std::size_t k = 0; k < model.knots.size(); ++k) {
    const NetKnot& knot = model.knots[k];
    if (knot.fixed) continue;
    ++free;
    const RigidBody& body = sim.bodies()[net.first_body + k];
    const Vec3d fluid = body.fluid_force;
    const double dx = knot.position.x - net.initial[k].x;
    std::printf("knot %zu: fluid Fx %.4f N, twine Fx %.4f N, moved %.3f mm\n", k, fluid.x,
                twine[k].x, 1e3 * dx);
    EXPECT_GT(fluid.x, 0.05);  // pushed downstream
    EXPECT_GT(dx, 0.0);
    EXPECT_NEAR(twine[k].x / -fluid.x, 1.0, 0.15);
  }
  EXPECT_EQ(free, 3);
}

}  // namespace
}  // namespace netsph
