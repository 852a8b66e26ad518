// A case's [waves], [[damping]] and [[gauge]] tables turned into what the run uses: the paddle
// wall's motion (against first-order wavemaker theory), the damping zones' grading and
// relaxation, the gauges' surface from a coverage profile, and the set-up's checks that need
// the fluid model. The reader's messages for bad input: tests/cases/bad/{waves,gauge,damping}_*.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/run/wave_gauges.hpp"
#include "netsph/setup/scene.hpp"
#include "netsph/solver/body_motion.hpp"
#include "netsph/sph/damping_zone.hpp"
#include "netsph/waves/dispersion.hpp"
#include "netsph/waves/wave_train.hpp"
#include "netsph/waves/wavemaker_theory.hpp"

namespace netsph {
namespace {

CaseSpec flume(const std::vector<std::string>& overrides = {}) {
  return read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/regular_piston2d.toml", overrides);
}

const WallSpec& paddle_of(const CaseSpec& spec) {
  return spec.walls.at(spec.waves.wall);
}

/// The paddle's displacement at t from its velocity history (trapezoid rule: exact for the
/// piecewise-linear velocity the wall follows, as the step's wall update is).
double displacement_from_history(const VelocityHistory& h, double t) {
  double x = 0;
  for (std::size_t k = 1; k < h.times.size() && h.times[k - 1] < t; ++k) {
    const double t1 = std::min(h.times[k], t);
    const Vec3d v1 = h.at(t1);
    x += 0.5 * (h.velocities[k - 1].x + v1.x) * (t1 - h.times[k - 1]);
  }
  return x;
}

TEST(WavesCase, PaddleWallFollowsFirstOrderWavemakerTheory) {
  const CaseSpec spec = flume();
  const WaveSpec& w = spec.waves;
  ASSERT_TRUE(w.given);
  EXPECT_EQ(paddle_of(spec).name, "paddle");
  EXPECT_EQ(w.direction, 1);
  EXPECT_DOUBLE_EQ(w.depth, 0.5);
  EXPECT_DOUBLE_EQ(w.still_level, 0.5);
  EXPECT_DOUBLE_EQ(w.ramp, 2 * w.period);
  // The stroke the Biesel transfer function gives for H at this kh.
  const double k = wave_number(2 * M_PI / w.period, w.depth);
  const double stroke = w.height / piston_height_to_stroke(k * w.depth);
  const PaddleMotion m = train_paddle_motion(PaddleType::Piston, w.train);
  ASSERT_EQ(m.harmonics.size(), 1u);
  EXPECT_NEAR(m.harmonics[0].stroke, stroke, 1e-12 * stroke);
  // The sampled velocity integrates to the paddle's displacement: the trapezoid rule's error
  // on a sinusoid sampled 100 times a period is (2 pi / 100)^2 / 12 = 3.3e-4 of its amplitude
  // per unit phase, so over a period (2 pi) under 2.1e-3 of S/2; bounded here by 1% of S/2
  // over the whole run (the error alternates in sign over each period).
  const VelocityHistory& h = paddle_of(spec).motion;
  double worst = 0;
  for (double t = 0; t <= spec.simulation.end_time; t += 0.0371) {
    double x = 0, v = 0;
    paddle_state(m, t, x, v);
    worst = std::max(worst, std::fabs(displacement_from_history(h, t) - x));
    EXPECT_NEAR(h.at(t).x, v, 1e-3 * stroke * m.harmonics[0].omega) << "t = " << t;
    EXPECT_EQ(h.at(t).z, 0.0);
  }
  EXPECT_LT(worst, 0.01 * stroke / 2);
  EXPECT_NEAR(w.max_excursion, stroke / 2, 1e-3 * stroke);
}

TEST(WavesCase, PaddleOnAnXmaxFaceSendsTheWavesTowardsMinusX) {
  const CaseSpec spec = flume(
      {"wall.1.faces=[\"xmax\"]", "wall.1.min=[-0.3, 0, 0]", "wall.1.max=[5.9, 0, 0.9]",
       "wall.0.faces=[\"zmin\", \"xmin\"]", "wall.0.min=[0, 0, 0]", "wall.0.max=[6.05, 0, 0.9]",
       "fill.0.max=[5.9, 0, 0.5]", "damping.0.from=2.4", "damping.0.to=0.0"});
  EXPECT_EQ(spec.waves.direction, -1);
  EXPECT_DOUBLE_EQ(spec.waves.paddle_x, 5.9);
  // The paddle moves in -x when the wave's crest leaves it (the velocity in phase with eta).
  const VelocityHistory& h = paddle_of(spec).motion;
  const double t = spec.waves.ramp + spec.waves.period;  // eta at the paddle at its crest
  EXPECT_LT(h.at(t).x, 0.0);
  EXPECT_GT(spec.waves.target_elevation(5.9, t), 0.0);
}

// theory = "stokes2" makes the paddle second order unless the case says otherwise: the paddle
// wall's velocity then carries Madsen's second harmonic (the difference from the first-order
// paddle is that harmonic's velocity, to the table's sampling error).
TEST(WavesCase, StokesWaveIsGeneratedToSecondOrderByDefault) {
  const CaseSpec linear = flume();
  EXPECT_EQ(linear.waves.generation, PaddleGeneration::FirstOrder);
  const CaseSpec stokes = flume({"waves.theory=\"stokes2\""});
  EXPECT_EQ(stokes.waves.generation, PaddleGeneration::SecondOrder);
  const CaseSpec forced = flume({"waves.theory=\"stokes2\"", "waves.generation=\"first_order\""});
  EXPECT_EQ(forced.waves.generation, PaddleGeneration::FirstOrder);
  const WaveSpec& w = stokes.waves;
  const RegularWave& c = w.train.components.front();
  const double a2 = piston_second_order_amplitude(c.height, c.k * c.depth, c.depth);
  ASSERT_NE(a2, 0.0);
  const VelocityHistory& second = paddle_of(stokes).motion;
  const VelocityHistory& first = paddle_of(forced).motion;
  for (double t = 3 * w.period; t < stokes.simulation.end_time; t += 0.0713) {
    const double expected = 2 * c.omega * a2 * std::cos(2 * c.omega * t - 2 * c.phase);
    // Each table interpolates linearly between samples a hundredth of its fastest harmonic's
    // period apart (T / 100 first order, T / 200 second): the error is at most (2 pi / 100)^2
    // / 8 of a harmonic's velocity amplitude.
    const double tolerance = std::pow(2 * M_PI / 100, 2) / 8 *
                             (std::fabs(2 * c.omega * a2) +
                              c.omega * 0.5 * c.height / piston_height_to_stroke(c.k * c.depth));
    EXPECT_NEAR(second.at(t).x - first.at(t).x, expected, tolerance) << "t = " << t;
  }
}

TEST(WavesCase, DampingRateDefaultsToARoundTripOfOnePercent) {
  const CaseSpec spec = flume();
  ASSERT_EQ(spec.damping.size(), 1u);
  const DampingSpec& d = spec.damping[0];
  const double k = spec.waves.train.components[0].k;
  const double cg = relative_group_velocity(k, spec.waves.depth);
  EXPECT_NEAR(d.rate, 3 * cg * std::log(100.0) / (d.to - d.from), 1e-12 * d.rate);
  // The amplitude's decay over the zone and back at that rate, integrated numerically:
  // exp(-integral of beta / (2 c_g) over 2 L) must be 1%.
  const DampingZone z{d.from, d.to, d.rate, {}};
  double integral = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const double x = d.from + (i + 0.5) * (d.to - d.from) / n;
    integral += damping_rate(z, x) * (d.to - d.from) / n;
  }
  EXPECT_NEAR(std::exp(-2 * integral / (2 * cg)), 0.01, 1e-6);
}

TEST(DampingZone, GradesQuadraticallyAndRelaxesExactly) {
  const DampingZone z{2.0, 4.0, 10.0, {0.2f, 0.0f, 0.0f}};
  EXPECT_EQ(damping_rate(z, 1.9), 0.0);
  EXPECT_EQ(damping_rate(z, 2.0), 0.0);
  EXPECT_NEAR(damping_rate(z, 3.0), 2.5, 1e-12);
  EXPECT_EQ(damping_rate(z, 4.0), 10.0);
  EXPECT_EQ(damping_rate(z, 9.0), 10.0);
  // Facing -x: from > to.
  const DampingZone back{4.0, 2.0, 10.0, {}};
  EXPECT_NEAR(damping_rate(back, 3.0), 2.5, 1e-12);
  EXPECT_EQ(damping_rate(back, 4.5), 0.0);
  // Two steps of dt relax as one of 2 dt (the exact exponential, any dt).
  Vec3f a{1.0f, 0.0f, -0.5f}, b = a;
  damp_velocity(z, Vec3d{3.0, 0, 0.2}, 0.0, 0.1, a);
  damp_velocity(z, Vec3d{3.0, 0, 0.2}, 0.0, 0.1, a);
  damp_velocity(z, Vec3d{3.0, 0, 0.2}, 0.0, 0.2, b);
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.x, 0.2 + 0.8 * std::exp(-2.5 * 0.2), 1e-6);
  EXPECT_NEAR(a.z, -0.5 * std::exp(-2.5 * 0.2), 1e-6);
  Vec3f outside{1.0f, 0.0f, 0.0f};
  damp_velocity(z, Vec3d{1.0, 0, 0.2}, 0.0, 0.1, outside);
  EXPECT_EQ(outside.x, 1.0f);
}

// A relaxation wavemaker on an inlet's current: the wave rides the inlet's 0.2 m/s, its wave
// number solves the Doppler-shifted relation, its origin is the zone's end, and the scene's
// first damping zone relaxes towards the current plus the wave's orbital velocity there.
TEST(WavesCase, RelaxationZoneMakesWavesOnTheInletsCurrent) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/current_following2d.toml");
  const WaveSpec& w = spec.waves;
  ASSERT_TRUE(w.relaxation);
  EXPECT_FALSE(w.has_paddle());
  EXPECT_EQ(w.direction, 1);
  EXPECT_DOUBLE_EQ(w.current, 0.2);
  EXPECT_DOUBLE_EQ(w.paddle_x, 2.5);
  EXPECT_DOUBLE_EQ(w.depth, 0.5);
  const RegularWave& c = w.train.components.front();
  const double sigma = c.omega - c.k * 0.2;
  EXPECT_NEAR(sigma * sigma, kStandardGravity * c.k * std::tanh(c.k * 0.5), 1e-10);
  EXPECT_LT(c.k, wave_number(c.omega, 0.5));  // a following current lengthens the wave
  EXPECT_GT(w.relaxation_rate, 0.0);
  const Scene scene = build_scene(spec);
  ASSERT_GE(scene.damping.size(), 2u);
  const DampingZone& z = scene.damping.front();
  EXPECT_EQ(z.from, 2.5);  // s = 0 where the waves leave
  EXPECT_EQ(z.to, 0.1);    // full where the fluid follows the wave
  EXPECT_FLOAT_EQ(z.velocity.x, 0.2f);
  // After the ramp: the target is the current plus the orbital velocity (Airy, on the current:
  // amplitudes with the intrinsic frequency).
  const double t = 5.3, x = 1.2, zc = 0.4;  // 0.1 m below the still water
  const Vec3f target = damping_target(z, Vec3d{x, 0, zc}, t);
  const double theta = c.k * (x - 2.5) - c.omega * t + c.phase;
  // The bed is at z = 0, so k (z' + h) = k zc with z' = zc - 0.5 from the still water.
  const double kh = c.k * 0.5, a = 0.5 * c.height;
  const double u = a * sigma * std::cosh(c.k * zc) / std::sinh(kh) * std::cos(theta);
  const double wv = a * sigma * std::sinh(c.k * zc) / std::sinh(kh) * std::sin(theta);
  EXPECT_NEAR(target.x, 0.2 + u, 1e-6);
  EXPECT_NEAR(target.z, wv, 1e-6);
  // Before the waves start, the target is the current alone.
  const Vec3f at_rest = damping_target(z, Vec3d{x, 0, zc}, 0.0);
  EXPECT_EQ(at_rest.x, 0.2f);
  EXPECT_EQ(at_rest.z, 0.0f);
}

// Against the current the waves' earth-frame group velocity vanishes as the current nears the
// blocking speed (0.4755 m/s here); the relaxation zone's default rate follows the group
// velocity relative to the water, so it still drives the wave (it fell to 2% of its value at
// 0.2 m/s when it followed the earth-frame one). Past blocking the message names the inlet.
TEST(WavesCase, RelaxationRateHoldsNearTheBlockingSpeed) {
  const std::string file = std::string(NETSPH_CASES_DIR) + "/waves/current_opposing2d.toml";
  const double usual = read_case_file(file).waves.relaxation_rate;
  const double near_blocking =
      read_case_file(file, {"inlet.0.velocity=0.47"}).waves.relaxation_rate;
  EXPECT_GT(near_blocking, 0.4 * usual);
  try {
    read_case_file(file, {"inlet.0.velocity=0.5"});
    FAIL() << "waves past the blocking speed were accepted";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("cannot exist on this current"), std::string::npos) << m;
    EXPECT_NE(m.find("inlet 'inlet1'"), std::string::npos) << m;
    EXPECT_EQ(m.find("[current]"), std::string::npos) << m;
  }
}

// Active absorption: the gauge half a depth in front of the paddle (beyond its travel and the
// kernel's reach), the gain omega / m1 and the gauge-to-paddle delay at the phase speed.
TEST(WavesCase, ActiveAbsorptionIsSetUpFromTheWave) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/absorbing_piston2d.toml");
  const WaveSpec& w = spec.waves;
  const WaveAbsorptionSpec& a = w.absorption;
  ASSERT_TRUE(a.active);
  const double support = 2 * spec.simulation.h_over_dp * spec.simulation.dp;
  const double distance = std::max(0.5 * w.depth, w.max_excursion + 2 * support);
  EXPECT_DOUBLE_EQ(a.gauge_x, w.paddle_x + distance);
  const RegularWave& c = w.train.components.front();
  EXPECT_DOUBLE_EQ(a.gain, c.omega / piston_height_to_stroke(c.k * c.depth));
  EXPECT_DOUBLE_EQ(a.delay, distance * c.k / c.omega);
  EXPECT_GT(a.drift_time, 5 * w.period);
  EXPECT_FALSE(flume().waves.absorption.active);  // none unless asked
}

// paddle = "flap": the [[body]] turns about a hinge at the bed under its face at the rate that
// puts its excursion at the still-water level (a depth above the hinge) on first-order flap
// theory's motion for the wave: the angle integrated from the rate, times the depth, follows
// X(t) of the stroke H / (H/S)_flap to the table's sampling error (as for the piston: 1% of
// S/2 bounds the trapezoid rule's error on a sinusoid sampled 100 times a period).
TEST(WavesCase, FlapBodyTurnsAboutItsHingeByFlapTheory) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/waves/regular_flap2d.toml");
  const WaveSpec& w = spec.waves;
  ASSERT_EQ(w.paddle, PaddleType::Flap);
  EXPECT_FALSE(w.paddle_is_wall());
  const BodySpec& flap = spec.bodies.at(w.body);
  EXPECT_EQ(flap.name, "flap");
  EXPECT_EQ(flap.motion, BodyMotion::Prescribed);
  EXPECT_FALSE(flap.velocity.moving());
  EXPECT_EQ(w.direction, 1);
  EXPECT_DOUBLE_EQ(w.paddle_x, 0.0);
  EXPECT_DOUBLE_EQ(flap.hinge.x, 0.0);
  EXPECT_DOUBLE_EQ(flap.hinge.z, 0.0);  // the bed
  const double k = wave_number(2 * M_PI / w.period, w.depth);
  const double stroke = w.height / flap_height_to_stroke(k * w.depth);
  const PaddleMotion m = train_paddle_motion(PaddleType::Flap, w.train);
  ASSERT_EQ(m.harmonics.size(), 1u);
  EXPECT_NEAR(m.harmonics[0].stroke, stroke, 1e-12 * stroke);
  // A flap needs a larger stroke than a piston for the same wave (it moves less water).
  EXPECT_GT(stroke, w.height / piston_height_to_stroke(k * w.depth));
  // The angle from the rate about y (as displacement_from_history integrates x).
  const VelocityHistory& h = flap.angular_velocity;
  VelocityHistory rate_y{h.times, {}};
  for (const Vec3d& r : h.velocities) rate_y.velocities.push_back({r.y, 0, 0});
  double worst = 0;
  for (double t = 0; t <= spec.simulation.end_time; t += 0.0371) {
    double x = 0, v = 0;
    paddle_state(m, t, x, v);
    worst = std::max(worst, std::fabs(displacement_from_history(rate_y, t) * w.depth - x));
    EXPECT_EQ(h.at(t).x, 0.0);
    EXPECT_EQ(h.at(t).z, 0.0);
  }
  EXPECT_LT(worst, 0.01 * stroke / 2);
  EXPECT_NEAR(w.max_excursion, stroke / 2, 1e-3 * stroke);
}

// type = "displacement": a record of the regular wave's paddle motion (twelve whole periods,
// unramped, sampled 100 times a period), given the same ramp, sets the case up as the regular
// wave does: one component of its height, frequency and phase (the record's other harmonics
// are round-off, dropped), the same stroke, and a wall velocity table that follows the regular
// paddle's to the tables' sampling error.
TEST(WavesCase, DisplacementRecordOfARegularPaddleMakesThatWave) {
  const CaseSpec regular = flume();
  const WaveSpec& w = regular.waves;
  const PaddleMotion m = train_paddle_motion(PaddleType::Piston, w.train);
  const PaddleHarmonic& h = m.harmonics.front();
  const double dt = w.period / 100;
  std::string times, values;
  for (int j = 0; j < 1200; ++j) {
    const double t = j * dt;
    times += fmt::format("{}{:.17g}", j ? ", " : "", t);
    values +=
        fmt::format("{}{:.17g}", j ? ", " : "", 0.5 * h.stroke * std::sin(h.omega * t - h.phase));
  }
  std::ifstream in(std::string(NETSPH_CASES_DIR) + "/waves/regular_piston2d.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t from = text.find("type = \"regular\""), to = text.find("[[damping]]");
  ASSERT_NE(from, std::string::npos);
  text = text.substr(0, from) +
         fmt::format(
             "type = \"displacement\"\nwavemaker = \"paddle\"\nramp = {:.17g}\n\n"
             "[waves.displacement]\ntimes = "
             "[{}]\nvalues = [{}]\n\n",
             w.ramp, times, values) +
         text.substr(to);
  const CaseSpec spec = read_case_string(text, "displacement.toml");
  const WaveSpec& d = spec.waves;
  ASSERT_EQ(d.kind, WaveKind::Displacement);
  ASSERT_EQ(d.train.components.size(), 1u);
  const RegularWave& c = d.train.components.front();
  EXPECT_NEAR(c.height, w.height, 1e-9 * w.height);
  EXPECT_NEAR(c.omega, 2 * M_PI / w.period, 1e-12);
  EXPECT_NEAR(c.phase, w.train.components.front().phase, 1e-9);
  EXPECT_DOUBLE_EQ(d.record_height, 4 * std::sqrt(0.125 * c.height * c.height));
  EXPECT_DOUBLE_EQ(d.record_period, 2 * M_PI / c.omega);
  EXPECT_NEAR(d.max_excursion, w.max_excursion, 1e-6 * w.max_excursion);
  const VelocityHistory &a = paddle_of(regular).motion, &b = paddle_of(spec).motion;
  for (double t = 0; t < spec.simulation.end_time; t += 0.0371)
    EXPECT_NEAR(b.at(t).x, a.at(t).x, 1e-6 * h.stroke * h.omega) << "t = " << t;
}

// A prescribed rotation about a hinge (a flap): the hinge does not move, every point keeps its
// distance from it, and the body turns by the integral of its rate, exactly for a rate linear
// in time over the step (the trapezoid rule), whatever the step; the velocity is the rigid
// rotation's about the hinge.
TEST(BodyMotion, PrescribedRotationTurnsAboutTheHingeByTheIntegralOfItsRate) {
  BodySpec body;
  body.hinge = {0.3, 0, -0.2};
  // rate 0.5 + 2 t rad/s about y over [0, 1] s: the angle is 0.5 t + t^2.
  body.angular_velocity.times = {0.0, 1.0};
  body.angular_velocity.velocities = {{0, 0.5, 0}, {0, 2.5, 0}};
  RigidState s;
  s.com = {0.25, 0, 0.4};
  const Vec3d arm0 = s.com - body.hinge;
  const double dt = 0.0137;
  double t = 0;
  for (int n = 0; n < 50; ++n) {
    const RigidState half = prescribed_rotation(s, body, t, false, dt);
    EXPECT_NEAR(norm(half.com - body.hinge), norm(arm0), 1e-12);
    s = prescribed_rotation(s, body, t, true, dt);
    t += dt;
  }
  const double angle = 0.5 * t + t * t;
  // The rotation about +y by `angle`: (x, z) -> (x cos + z sin, -x sin + z cos).
  const Vec3d expected{body.hinge.x + arm0.x * std::cos(angle) + arm0.z * std::sin(angle), 0,
                       body.hinge.z - arm0.x * std::sin(angle) + arm0.z * std::cos(angle)};
  EXPECT_NEAR(s.com.x, expected.x, 1e-12);
  EXPECT_NEAR(s.com.z, expected.z, 1e-12);
  const Vec3d turned = rotate(s.q, Vec3d{1, 0, 0});
  EXPECT_NEAR(std::atan2(-turned.z, turned.x), angle, 1e-12);
  EXPECT_NEAR(s.omega.y, 0.5 + 2 * t, 1e-12);
  const Vec3d v = cross(s.omega, s.com - body.hinge);
  EXPECT_NEAR(norm(s.vel - v), 0.0, 1e-12);
}

TEST(WaveGauge, SurfaceIsWhereTheCoverageCrossesOneHalf) {
  std::vector<double> z, c;
  for (int k = 0; k <= 40; ++k) {
    z.push_back(0.01 * k);
    // Water to 0.2 m, a linear fall over a kernel's width around it, spray above.
    const double s = 0.5 - (z.back() - 0.2) / 0.03;
    c.push_back(std::clamp(s, 0.0, 1.0));
  }
  c[35] = 0.3;  // a drop: below one half, not a surface
  EXPECT_NEAR(surface_from_coverage(z, c), 0.2, 1e-12);
  // A bottom wall's half-empty kernel near z = 0 does not count: the highest crossing does.
  c[0] = 0.45;
  EXPECT_NEAR(surface_from_coverage(z, c), 0.2, 1e-12);
  EXPECT_TRUE(std::isnan(surface_from_coverage(z, std::vector<double>(z.size(), 0.1))));
  // Water up to the line's top: the top.
  EXPECT_EQ(surface_from_coverage(z, std::vector<double>(z.size(), 1.0)), z.back());
}

// Without [waves] a gauge measures from the highest fill's surface: still water reads the
// lattice's surface, which lies within dp/2 of the fill's top (its top row sits dp/2 below it,
// and the kernel sum crosses 1/2 within a spacing of that row).
TEST(WaveGauge, WithoutWavesStillWaterReadsNearZero) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_CASES_DIR) + "/hydrostatic2d.toml", {"gauge=[{x=0.5}]"});
  ASSERT_FALSE(spec.waves.given);
  Simulation sim(spec);
  sim.step();  // the samples read the step's neighbour grid, as a run's do
  const auto dir = std::filesystem::temp_directory_path() / "netsph_gauge_still_water";
  std::filesystem::create_directories(dir);
  GaugeRecorder gauges(sim, dir);
  SimulationParticles particles(sim);
  gauges.after_step(sim, particles);
  std::ifstream in(dir / "gauges.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "time [s],gauge1 [m]");
  const double eta = std::stod(row.substr(row.find(',') + 1));
  EXPECT_LT(std::fabs(eta), 0.5 * spec.simulation.dp) << row;
}

TEST(WaveGauge, TargetIsTheLinearWaveOnceTheRampHasArrived) {
  const CaseSpec spec = flume();
  const WaveSpec& w = spec.waves;
  const RegularWave& c = w.train.components[0];
  const double x = 2.094, arrival = x / w.train.front_speed;
  EXPECT_EQ(w.target_elevation(x, 0.5 * arrival), 0.0);
  const double t = arrival + w.ramp + 0.3;
  EXPECT_NEAR(w.target_elevation(x, t), wave_elevation(c, x, t), 1e-15);
  EXPECT_GT(gauge_interval(spec), 0.0);
  EXPECT_LE(gauge_interval(spec), w.period / 40);
}

TEST(WavesSetup, TooFewStepsPerPeriodStopsTheRun) {
  // A 2 ms period: the first time step at dp = 0.02 m is cfl h / c0 = 0.2 * 0.03 / 22 =
  // 2.7e-4 s (the acoustic limit), so only 7 steps fit in a period.
  const CaseSpec spec = flume({"waves.period=0.002", "waves.height=1e-7", "simulation.dp=0.02"});
  try {
    build_scene(spec);
    FAIL() << "a 2 ms period was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("time steps per period"), std::string::npos) << e.what();
    EXPECT_NE(e.where().find("regular_piston2d.toml"), std::string::npos) << e.where();
  }
}

TEST(WavesSetup, WarnsOfACoarseWaveAndAShortDampingZone) {
  const CaseSpec spec = flume({"simulation.dp=0.02", "damping.0.from=5.2"});
  const Scene scene = build_scene(spec);
  bool coarse = false, short_zone = false;
  for (const std::string& w : scene.warnings) {
    coarse |= w.find("is 3 particle spacings") != std::string::npos;
    short_zone |= w.find("damping zone 'beach'") != std::string::npos &&
                  w.find("under half the wavelength") != std::string::npos;
  }
  EXPECT_TRUE(coarse);
  EXPECT_TRUE(short_zone);
  ASSERT_EQ(scene.damping.size(), 1u);
  EXPECT_EQ(scene.damping[0].from, 5.2);
}

}  // namespace
}  // namespace netsph
