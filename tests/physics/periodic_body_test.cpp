// A floating body carried across a periodic end (cases/poiseuille2d.toml, periodic in x, with a
// neutrally buoyant box drifting along the channel at 0.5 m/s, below the centre line so that the
// shear turns it). A periodic channel filled with a lattice is the same everywhere along x, so
// the run must not depend on where along x the box starts: one box starting across the end (its
// particles wrapped into the period at set-up, the fluid under it removed on both sides) whose
// centre then crosses it (the particles are wrapped with the fluid, the centre is not:
// place_rigid_particle, rigid_lever_arm), and one starting 10 dp earlier (the lattice is the
// same a whole number of dp along), which stays inside, must feel the same force and torque and
// move the same way, up to the round-off of positions measured from another origin. On both
// backends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "case_runs.hpp"
#include "netsph/core/periodic_image.hpp"
#include "netsph/geometry/shapes.hpp"

namespace netsph {
namespace {

constexpr double kSide = 0.02;    // m, the box
constexpr double kPeriod = 0.1;   // m, the channel's length (poiseuille2d.toml)
constexpr double kShift = 0.05;   // m, between the two starts: 10 dp
constexpr double kEndTime = 0.1;  // s: the centre, 0.006 m from the end, crosses at 0.058 s

struct BodyTrack {
  std::vector<double> fx, fz, torque;  // fluid loads on the box, each step
  Vec3d com{}, vel{};
  double angle = 0, omega = 0;
  std::size_t fluid_inside = 0;  // fluid particles inside the box at the end
  double crossed_at = -1;        // s, when the centre passed the period's end (-1: never)
};

BodyTrack drift_box(double centre_x, StepBackend backend) {
  const std::vector<std::string> box = {fmt::format(
      "body=[{{name=\"box\", shape=\"box\", size=[{0}, {0}, {0}], center=[{1}, 0, 0.035], "
      "motion=\"floating\", density=1000, initial_velocity=[0.5, 0, 0]}}]",
      kSide, centre_x)};
  Simulation sim(test::load_case("poiseuille2d.toml", box), backend);
  BodyTrack t;
  while (sim.time() < kEndTime) {
    sim.step();
    const RigidBody& b = sim.bodies()[0];
    t.fx.push_back(b.fluid_force.x), t.fz.push_back(b.fluid_force.z);
    t.torque.push_back(b.fluid_torque.y);
    if (t.crossed_at < 0 && b.state.com.x >= kPeriod) t.crossed_at = sim.time();
  }
  const RigidBody& b = sim.bodies()[0];
  t.com = b.state.com, t.vel = b.state.vel, t.omega = b.state.omega.y;
  t.angle = 2 * std::atan2(b.state.q.y, b.state.q.w);
  const Shape shape = Shape::box({kSide, kSide, kSide});
  const ParticleSet& p = sim.particles();
  const Vec3d period{kPeriod, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_fluid(p.kind[i])) continue;
    const Vec3d local =
        rotate_inverse(b.state.q, nearest_image_offset(p.pos[i] - b.state.com, period));
    t.fluid_inside += shape.inside(local);
  }
  return t;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (const double x : v) m = std::max(m, std::fabs(x));
  return m;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    m = std::max(m, std::fabs(a[k] - b[k]));
  return m;
}

TEST(PeriodicBody, AFloatingBoxAcrossThePeriodicEndMovesAsOneInside) {
  for (const StepBackend backend : {StepBackend::Cpu, StepBackend::HostDevice}) {
    SCOPED_TRACE(backend == StepBackend::Cpu ? "cpu" : "host-device");
    const BodyTrack across = drift_box(0.094, backend);
    const BodyTrack inside = drift_box(0.094 - kShift, backend);
    std::printf(
        "%s: centre crossed x = %.2f m at t = %.4f s; end: x %.9f / %.9f m (+%.2f), z %.9f / "
        "%.9f m, u %.7f / %.7f m/s, angle %.7e / %.7e rad; steps %zu / %zu\n",
        backend == StepBackend::Cpu ? "cpu" : "host-device", kPeriod, across.crossed_at,
        across.com.x, inside.com.x, kShift, across.com.z, inside.com.z, across.vel.x, inside.vel.x,
        across.angle, inside.angle, across.fx.size(), inside.fx.size());
    std::printf(
        "  largest |F_x| %.4g N/m, |F_z| %.4g N/m, |T_y| %.4g N; differences %.3g, %.3g, "
        "%.3g; fluid inside the box %zu / %zu\n",
        max_abs(across.fx), max_abs(across.fz), max_abs(across.torque),
        max_difference(across.fx, inside.fx), max_difference(across.fz, inside.fz),
        max_difference(across.torque, inside.torque), across.fluid_inside, inside.fluid_inside);
    ASSERT_GT(across.crossed_at, 0.0) << "the box never crossed the end: the test tests nothing";
    EXPECT_LT(across.crossed_at, 0.7 * kEndTime);
    ASSERT_EQ(across.fx.size(), inside.fx.size());
    // The motion: the same, a shift apart (the box turns by 0.07 rad).
    EXPECT_NEAR(across.com.x - inside.com.x, kShift, 1e-7);
    EXPECT_NEAR(across.com.z, inside.com.z, 1e-7);
    EXPECT_NEAR(across.vel.x, inside.vel.x, 1e-4 * std::fabs(inside.vel.x));
    EXPECT_NEAR(across.angle, inside.angle, 1e-3 * std::fabs(inside.angle));
    EXPECT_GT(std::fabs(inside.angle), 0.01);
    // The loads, step by step, to 0.1% of their largest value (measured: 1e-6 of F_x, 6e-5 of
    // F_z, 1e-4 of the torque).
    EXPECT_LT(max_difference(across.fx, inside.fx), 1e-3 * max_abs(inside.fx));
    EXPECT_LT(max_difference(across.fz, inside.fz), 1e-3 * max_abs(inside.fz));
    EXPECT_LT(max_difference(across.torque, inside.torque), 1e-3 * max_abs(inside.torque));
    // No fluid went through it.
    EXPECT_EQ(across.fluid_inside, 0u);
    EXPECT_EQ(inside.fluid_inside, 0u);
  }
}

}  // namespace
}  // namespace netsph
