// One coupled stage of a net without the SPH fluid (solver/net_coupling.hpp): the sinker bar
// takes its drag in every knot-spring sub-step, and the water gets back exactly the momentum
// the net got from it. A free net (no anchored edge) has only internal twine forces besides
// its weight and the bar's drag, so its momentum changes by stage_dt (weight + the stage's
// drag) to round-off; the reaction on the water, spread along the bar one kernel support
// downstream where the water is, adds up to minus that drag.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "net_test_specs.hpp"
#include "netsph/net/net_generator.hpp"
#include "netsph/solver/net_coupling.hpp"

namespace netsph {
namespace {

CoupledNet free_net_with_sinker() {
  NetSpec s = test::net_with_sinker(KnotLayout::Inset);
  s.fixed_edges = {};
  s.youngs_modulus = 1e8;
  CoupledNet c;
  c.model = generate_net(s, {});
  for (const NetKnot& k : c.model.knots) c.initial.push_back(k.position);
  const std::size_t n = c.model.knots.size();
  c.sinker_flow.assign(n, Vec3d{});
  c.sinker_wet.assign(n, 0);
  c.sinker_stage_drag.assign(n, Vec3d{});
  return c;
}

TEST(NetStage, TheWaterTakesBackTheMomentumTheSinkerDragGaveTheNet) {
  std::vector<CoupledNet> nets{free_net_with_sinker()};
  CoupledNet& c = nets[0];
  const NetModel& net = c.model;
  const std::size_t n = net.knots.size();
  std::vector<RigidBody> bodies(n);
  for (std::size_t k = 0; k < n; ++k) {
    bodies[k].motion = BodyMotion::Floating;
    bodies[k].state.com = net.knots[k].position;
    // Moving upstream and swinging: the drag changes over the stage's sub-steps.
    const double x = static_cast<double>(k);
    bodies[k].state.vel = {-0.1 - 0.02 * std::sin(3.0 * x), 0.01 * std::cos(2.0 * x), 0};
    bodies[k].start = bodies[k].state;
  }
  // The water at 0.3 m/s, rising at 0.5 m/s per metre along the bar (so each share's drag
  // points its own way), its density 1000 + 1000 x kg/m^3 (so each mass weight tells where it
  // was sampled), coverage 0.9 at the bar and 0.95 downstream. The first sample point on the
  // bar is dry (coverage below 1/2). The reaction goes 3 cm downstream at points at most 2 cm
  // apart along the share (each half share, 5 cm, in three pieces): the second of them is dry
  // and takes no part; the third share has no water downstream at all, and its reaction stays
  // at its sample points on the bar.
  c.reaction_offset = 0.03;
  c.reaction_spacing = 0.02;
  const auto flow = [](const Vec3d& x) { return Vec3d{0.3, 0, 0.5 * x.y}; };
  const auto density = [](const Vec3d& x) { return 1000 + 1000 * x.x; };
  int calls = 0;
  std::vector<int> sampled;
  const FluidSampler sampler = [&](std::span<const Vec3d> points, std::span<ShepardValue> v) {
    ++calls;
    for (std::size_t i = 0; i < points.size(); ++i) {
      v[i].coverage = calls == 1 ? (i == 0 ? 0.3 : 0.9) : (i == 1 || i >= 12 ? 0.2 : 0.95);
      v[i].velocity = flow(points[i]);
      v[i].density = density(points[i]);
    }
    sampled.push_back(static_cast<int>(points.size()));
  };
  sample_sinker_flows(nets, bodies, sampler);
  ASSERT_EQ(calls, 2);  // the bar, then downstream
  // Three bottom knots: three points each on the bar (inset layout), six downstream.
  ASSERT_EQ(sampled, (std::vector<int>{9, 18}));
  int share = 0;
  std::size_t next = 0;  // in c.sinker_reach
  for (std::size_t k = 0; k < n; ++k) {
    const NetKnot& knot = net.knots[k];
    if (knot.sinker_length <= 0) continue;
    SinkerSamples bar;
    ASSERT_EQ(sinker_sample_points(net, knot, bar), 3);  // here, the end at -y, the end at +y
    // The share's flow: the weighted mean over its wet points; the drag's direction from it.
    Vec3d mean{};
    double wet = 0;
    for (int i = 0; i < 3; ++i) {
      if (share == 0 && i == 0) continue;
      mean += flow(bar.points[i]) * bar.weights[i];
      wet += bar.weights[i];
    }
    mean = mean / wet;
    EXPECT_NEAR(norm(c.sinker_flow[k] - mean), 0, 1e-15) << k;
    Vec3d u = mean - bodies[k].state.vel;
    u = u - net.across * dot(u, net.across);
    const Vec3d along = u / norm(u);
    if (share == 2) {
      // No water downstream: at the bar's sample points, by their weights.
      for (int i = 0; i < 3; ++i, ++next) {
        ASSERT_LT(next, c.sinker_reach.size());
        const CoupledNet::ReactionPoint& r = c.sinker_reach[next];
        EXPECT_EQ(r.knot, k);
        EXPECT_NEAR(norm(r.point - bar.points[i]), 0, 1e-15) << i;
        EXPECT_NEAR(r.part_per_mass_weight, bar.weights[i] / (0.9 * density(bar.points[i])), 1e-15)
            << i;
      }
    } else {
      // end -> here -> end in three pieces each, their middles moved downstream; the second
      // point of the first share is dry.
      const Vec3d line[3] = {bar.points[1], bar.points[0], bar.points[2]};
      const double piece = 0.05 / 3, wet_length = share == 0 ? 5 * piece : 6 * piece;
      for (int seg = 0; seg < 2; ++seg) {
        for (int p = 0; p < 3; ++p) {
          if (share == 0 && seg == 0 && p == 1) continue;
          ASSERT_LT(next, c.sinker_reach.size());
          const CoupledNet::ReactionPoint& r = c.sinker_reach[next++];
          const Vec3d expected =
              line[seg] + (line[seg + 1] - line[seg]) * ((p + 0.5) / 3) + along * 0.03;
          EXPECT_EQ(r.knot, k);
          EXPECT_NEAR(norm(r.point - expected), 0, 1e-12) << k << " " << seg << " " << p;
          EXPECT_NEAR(r.part_per_mass_weight, piece / wet_length / (0.95 * density(expected)),
                      1e-12)
              << k << " " << seg << " " << p;
        }
      }
    }
    ++share;
  }
  EXPECT_EQ(next, c.sinker_reach.size());
  EXPECT_EQ(next, 5u + 6u + 3u);
  EXPECT_EQ(c.reactions_at_bar, 1u);  // the third share's, counted for the summary

  const double stage_dt = 2e-3;
  advance_coupled_nets(nets, bodies, stage_dt);
  Vec3d momentum{}, impulse{}, drag{}, end_drag{};
  for (std::size_t k = 0; k < n; ++k) {
    momentum += (bodies[k].state.vel - bodies[k].start.vel) * net.knots[k].mass;
    impulse += (net.knots[k].constant_force + c.sinker_stage_drag[k]) * stage_dt;
    drag += c.sinker_stage_drag[k];
    if (c.sinker_wet[k])
      end_drag += sinker_drag(net, net.knots[k], c.sinker_flow[k], c.water_density);
    // The knot reports the drag the stage applied (what the water takes), not the end's.
    EXPECT_EQ(norm(bodies[k].modelled_force - c.sinker_stage_drag[k]), 0) << k;
  }
  std::printf("stage drag (%.6f, %.6f, %.6f) N, at the stage's end (%.6f, %.6f, %.6f) N\n", drag.x,
              drag.y, drag.z, end_drag.x, end_drag.y, end_drag.z);
  ASSERT_GT(drag.x, 0.1);  // 0.3 m of 6 mm bar at about 0.4 m/s relative: about 0.17 N
  // The sub-steps changed the drag: the end's differs from the stage's mean by far more than
  // the tolerance below, so the mean must be the one the sub-steps applied.
  ASSERT_GT(norm(end_drag - drag) * stage_dt, 100 * 1e-9 * norm(impulse));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(momentum[a], impulse[a], 1e-9 * norm(impulse)) << a;

  // The reaction: minus the stage's drag, at the wet points only; per_weight times the mass
  // weight there (coverage x density) is each point's force.
  std::vector<FluidPointLoad> loads;
  add_sinker_reactions(nets, loads);
  ASSERT_EQ(loads.size(), c.sinker_reach.size());
  Vec3d given{};
  for (std::size_t l = 0; l < loads.size(); ++l)
    given += loads[l].per_weight * ((l < 11 ? 0.95 : 0.9) * density(loads[l].point));
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(given[a], -drag[a], 1e-12) << a;
}

}  // namespace
}  // namespace netsph
