// A lone particle under gravity: the symplectic scheme integrates constant acceleration
// exactly (r = r0 + v0 t + g t^2 / 2 for any dt sequence), so the only error left is float
// round-off in the velocity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "case_runs.hpp"
#include "netsph/case/case_reader.hpp"

namespace netsph {
namespace {

constexpr const char* kFreeFall = R"(
[simulation]
name = "free_fall"
dimensions = 3
dp = 0.01
end_time = 0.4
[fluid]
sound_speed = 10.0
gravity = [0.0, 0.0, -9.81]
[domain]
min = [-0.2, -0.2, 0.4]
max = [0.5, 0.2, 1.2]
[[fill]]
min = [0.0, 0.0, 1.0]
max = [0.01, 0.01, 1.01]
velocity = [0.5, 0.0, 1.0]
)";

TEST(FreeFall, MatchesTheExactTrajectory) {
  Simulation sim(read_case_string(kFreeFall, "free_fall"));
  ASSERT_EQ(sim.particles().size(), 1u);
  const Vec3d r0 = sim.particles().pos[0];
  test::run_until(sim, 0.4);
  EXPECT_GT(sim.steps(), 100);
  const double t = sim.time();
  const Vec3d r = sim.particles().pos[0];
  const Vec3f v = sim.particles().vel[0];
  const double g = 9.81;
  EXPECT_NEAR(r.x, r0.x + 0.5 * t, 1e-6);
  EXPECT_NEAR(r.y, r0.y, 1e-12);
  EXPECT_NEAR(r.z, r0.z + 1.0 * t - 0.5 * g * t * t, 1e-5);
  EXPECT_NEAR(v.x, 0.5, 1e-6);
  EXPECT_NEAR(v.z, 1.0 - g * t, 1e-4);
  // With no neighbours: dt = CFL min(sqrt(h / g), h / c0), here the acoustic limit.
  EXPECT_NEAR(sim.last_dt(), 0.2 * std::min(std::sqrt(0.015 / g), 0.015 / 10.0), 1e-9);
}

}  // namespace
}  // namespace netsph
