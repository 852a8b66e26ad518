// Linear wave theory (waves/): the dispersion relation with and without a current, the
// breaking steepness and the wavemaker transfer functions, against their analytic limits and
// residuals.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "netsph/core/error.hpp"
#include "netsph/waves/active_absorption.hpp"
#include "netsph/waves/dispersion.hpp"
#include "netsph/waves/displacement_record.hpp"
#include "netsph/waves/irregular_waves.hpp"
#include "netsph/waves/paddle_motion.hpp"
#include "netsph/waves/wave_kinematics.hpp"
#include "netsph/waves/wave_record.hpp"
#include "netsph/waves/wave_train.hpp"
#include "netsph/waves/wavemaker_theory.hpp"

namespace netsph {
namespace {

constexpr double g = kStandardGravity;

// The residual of omega^2 = g k tanh(kh) is round-off (a few ulp of omega^2) over depths from
// shallow (kh = 0.01) to deep (kh = 50) water.
TEST(Dispersion, WaveNumberSolvesTheDispersionRelation) {
  for (double h : {0.05, 0.5, 5.0, 500.0}) {
    for (double period : {0.5, 1.0, 2.0, 8.0, 20.0}) {
      const double omega = 2 * M_PI / period;
      const double k = wave_number(omega, h, g);
      EXPECT_NEAR(g * k * std::tanh(k * h), omega * omega, 1e-13 * omega * omega)
          << "h " << h << " T " << period;
    }
  }
}

// Deep water (kh >> 1): k = omega^2 / g. Shallow water (kh << 1): the wave speed omega / k
// tends to sqrt(g h) with relative error (kh)^2 / 6 (tanh x = x - x^3/3 + ...).
TEST(Dispersion, DeepAndShallowWaterLimits) {
  const double omega = 2 * M_PI / 1.0;
  EXPECT_NEAR(wave_number(omega, 100.0, g), omega * omega / g, 1e-12 * omega * omega / g);
  const double h = 0.01, omega_long = 2 * M_PI / 60.0;
  const double k = wave_number(omega_long, h, g);
  const double kh = k * h;
  ASSERT_LT(kh, 0.01);
  EXPECT_NEAR(omega_long / k, std::sqrt(g * h), 0.2 * kh * kh * std::sqrt(g * h));
}

// The tabulated value of Dean & Dalrymple (1991), Appendix C: at h / L0 = 0.1 (deep-water
// wavelength L0 = g T^2 / 2 pi), h / L = 0.1410 and tanh(kh) = 0.7093 (to the table's 4 digits).
TEST(Dispersion, MatchesTheTextbookTable) {
  const double period = 2.0, L0 = g * period * period / (2 * M_PI), h = 0.1 * L0;
  const double L = 2 * M_PI / wave_number(2 * M_PI / period, h, g);
  EXPECT_NEAR(h / L, 0.1410, 0.00006);
  EXPECT_NEAR(std::tanh(2 * M_PI * h / L), 0.7093, 0.00006);
}

// On a current the Doppler-shifted relation (omega - k U)^2 = g k tanh(kh) holds, a following
// current lengthens the wave and an opposing one shortens it, and U = 0 is the plain relation.
TEST(Dispersion, CurrentShiftsTheWaveNumber) {
  const double h = 0.5, omega = 2 * M_PI / 1.2;
  const double k0 = wave_number(omega, h, g);
  EXPECT_EQ(wave_number_on_current(omega, h, 0.0, g), k0);
  for (double U : {-0.3, -0.2, 0.2, 0.5}) {
    const double k = wave_number_on_current(omega, h, U, g);
    const double sigma = omega - k * U;
    EXPECT_GT(sigma, 0);
    EXPECT_NEAR(sigma * sigma, g * k * std::tanh(k * h), 1e-12 * omega * omega) << "U " << U;
    if (U > 0) {
      EXPECT_LT(k, k0);
    } else {
      EXPECT_GT(k, k0);
    }
  }
  // Continuity at U -> 0 (the branch connected to the still-water wave).
  EXPECT_NEAR(wave_number_on_current(omega, h, 1e-9, g), k0, 1e-6 * k0);
  EXPECT_NEAR(wave_number_on_current(omega, h, -1e-9, g), k0, 1e-6 * k0);
}

// Deep water blocking: a wave of frequency omega cannot travel against a current faster than
// U = g / (4 omega) (its relative group velocity g / (2 sigma) equals -U where sigma = 2 omega;
// e.g. Jonsson 1990). Just below that speed it exists; just above it does not.
TEST(Dispersion, OpposingCurrentBlocksTheWave) {
  const double h = 1000.0, omega = 2 * M_PI / 1.0;
  const double U_block = g / (4 * omega);
  EXPECT_NO_THROW(wave_number_on_current(omega, h, -0.999 * U_block, g));
  EXPECT_THROW(wave_number_on_current(omega, h, -1.001 * U_block, g), Error);
  // Shallow water: no wave against a current faster than sqrt(g h).
  EXPECT_THROW(wave_number_on_current(omega, 0.1, -1.1 * std::sqrt(g * 0.1), g), Error);
}

TEST(Dispersion, BadInputIsRefused) {
  EXPECT_THROW(wave_number(0.0, 1.0, g), Error);
  EXPECT_THROW(wave_number(1.0, -1.0, g), Error);
  EXPECT_THROW(wave_number(1.0, 1.0, 0.0), Error);
  EXPECT_THROW(wave_number(std::nan(""), 1.0, g), Error);
}

// Miche's limit: H/L = 0.142 in deep water, 0.142 kh (so H/h = 0.142 * 2 pi = 0.89) in
// shallow water.
TEST(Dispersion, BreakingSteepness) {
  // tanh x = 1 - 2 e^-2x + ... and x - x^3 / 3 + ...: the bounds are the first terms dropped.
  EXPECT_NEAR(breaking_steepness(10.0), 0.142, 0.142 * 2 * std::exp(-20.0) + 1e-15);
  const double kh = 0.01;
  EXPECT_NEAR(breaking_steepness(kh), 0.142 * kh, 0.142 * kh * kh * kh / 3 + 1e-15);
}

// Biesel's transfer functions: shallow-water slopes kh (piston) and kh / 2 (flap), both 2 in
// deep water; the flap always makes the lower wave for the same stroke; the large-kh branch
// joins the formula.
TEST(Wavemaker, BieselTransferFunctionLimits) {
  for (double kh : {1e-3, 1e-2}) {
    EXPECT_NEAR(piston_height_to_stroke(kh), kh, 0.01 * kh);
    EXPECT_NEAR(flap_height_to_stroke(kh), kh / 2, 0.01 * kh);
  }
  // Deep water: the piston's 2 with error 4 (1 + 2kh) e^-2kh, the flap's 2 (1 - 1/kh) with error
  // 2 / (kh cosh kh) (the first terms the limits drop).
  const double x = 15.0;
  EXPECT_NEAR(piston_height_to_stroke(x), 2.0, 1.01 * 4 * (1 + 2 * x) * std::exp(-2 * x) + 1e-15);
  EXPECT_NEAR(flap_height_to_stroke(x), 2 * (1 - 1 / x), 1.01 * 2 / (x * std::cosh(x)) + 1e-12);
  EXPECT_NEAR(piston_height_to_stroke(20.0), piston_height_to_stroke(20.0 + 1e-9), 1e-12);
  EXPECT_NEAR(flap_height_to_stroke(20.0), flap_height_to_stroke(20.0 + 1e-9), 1e-9);
  for (double kh = 0.1; kh < 10; kh *= 1.3) {
    EXPECT_LT(flap_height_to_stroke(kh), piston_height_to_stroke(kh));
    EXPECT_LT(piston_height_to_stroke(kh), piston_height_to_stroke(1.3 * kh));
  }
  // A value from the formula by hand (kh = 1): 2 (cosh 2 - 1) / (sinh 2 + 2) = 0.98179.
  EXPECT_NEAR(piston_height_to_stroke(1.0), 0.98179, 1e-5);
}

// A regular wave of the flumes issue 44 asks for: h = 0.5 m, kh = 1.5, H/L = 0.02, on a
// current U.
RegularWave flume_wave(double U, int order) {
  RegularWave w;
  w.depth = 0.5;
  w.k = 1.5 / w.depth;
  w.current = U;
  w.omega = intrinsic_frequency(w.k, w.depth, g) + w.k * U;  // the absolute frequency
  w.height = 0.02 * 2 * M_PI / w.k;
  w.order = order;
  w.phase = 0.3;
  return w;
}

// Potential flow is incompressible: du/dx + dw/dz = 0 (central differences, error O(d^2)
// relative to k^2 times the velocity's scale), at first and second order, with and without a
// current; and the bottom is impermeable, w(z = -h) = 0.
TEST(WaveKinematics, OrbitalVelocityIsDivergenceFreeAndStopsAtTheBottom) {
  for (double U : {0.0, 0.2, -0.2}) {
    for (int order : {1, 2}) {
      const RegularWave w = flume_wave(U, order);
      const double scale = 0.5 * w.height * intrinsic_omega(w) / std::tanh(w.k * w.depth);
      const double d = 1e-4 / w.k;
      for (double z : {-0.45, -0.25, -0.05}) {
        for (double x : {0.0, 0.37, 1.1}) {
          double u1, w1, u2, w2, u3, w3, u4, w4;
          wave_velocity(w, x + d, z, 0.7, u1, w1);
          wave_velocity(w, x - d, z, 0.7, u2, w2);
          wave_velocity(w, x, z + d, 0.7, u3, w3);
          wave_velocity(w, x, z - d, 0.7, u4, w4);
          const double div = (u1 - u2) / (2 * d) + (w3 - w4) / (2 * d);
          EXPECT_NEAR(div, 0.0, 1e-6 * w.k * scale) << "U " << U << " order " << order;
        }
      }
      double u, up;
      wave_velocity(w, 0.4, -w.depth, 1.3, u, up);
      EXPECT_NEAR(up, 0.0, 1e-15 * scale);
    }
  }
}

// The linear free-surface conditions at z = 0, which tie the kinematics to the dispersion
// relation solved by wave_number_on_current: kinematic, d(eta)/dt + U d(eta)/dx = w; dynamic
// (in the frame moving with the current), the surface velocity amplitude
// (H/2) sigma coth kh equals (H/2) g k / sigma.
TEST(WaveKinematics, LinearWaveSatisfiesTheFreeSurfaceConditions) {
  for (double U : {0.0, 0.2, -0.2}) {
    RegularWave w = flume_wave(U, 1);
    w.k = wave_number_on_current(w.omega, w.depth, U, g);  // from the absolute frequency
    const double sigma = intrinsic_omega(w);
    const double dt = 1e-5 / w.omega, dx = 1e-5 / w.k;
    for (double t : {0.1, 0.55, 1.2}) {
      const double x = 0.8;
      const double deta_dt =
          (wave_elevation(w, x, t + dt) - wave_elevation(w, x, t - dt)) / (2 * dt);
      const double deta_dx =
          (wave_elevation(w, x + dx, t) - wave_elevation(w, x - dx, t)) / (2 * dx);
      double u, up;
      wave_velocity(w, x, 0.0, t, u, up);
      EXPECT_NEAR(deta_dt + U * deta_dx, up, 1e-7 * w.height * sigma) << "U " << U;
    }
    const double kh = w.k * w.depth;
    EXPECT_NEAR(0.5 * w.height * sigma / std::tanh(kh), 0.5 * w.height * g * w.k / sigma,
                1e-12 * w.height * sigma);
  }
}

// Stokes' second order raises the crests and flattens the troughs by its cos 2 theta
// amplitude and leaves the mean level where it was; at this steepness (H/L = 0.02, kh = 1.5)
// that amplitude is a few percent of the first-order one.
TEST(WaveKinematics, StokesSecondOrderSharpensTheCrests) {
  const RegularWave w = flume_wave(0.0, 2);
  const double a2 = second_order_surface_amplitude(w);
  EXPECT_GT(a2, 0.01 * 0.5 * w.height);
  EXPECT_LT(a2, 0.1 * 0.5 * w.height);
  const double T = 2 * M_PI / w.omega, t_crest = w.phase / w.omega;
  EXPECT_NEAR(wave_elevation(w, 0.0, t_crest), 0.5 * w.height + a2, 1e-12);
  EXPECT_NEAR(wave_elevation(w, 0.0, t_crest + T / 2), -0.5 * w.height + a2, 1e-12);
  double mean = 0;
  const int n = 1000;
  for (int i = 0; i < n; ++i) mean += wave_elevation(w, 0.0, T * i / n) / n;
  EXPECT_NEAR(mean, 0.0, 1e-12);
  EXPECT_EQ(second_order_surface_amplitude(flume_wave(0.0, 1)), 0.0);
}

// The ramp rises from 0 to 1 with zero slope at both ends.
TEST(WaveKinematics, RampStartsAndEndsSmoothly) {
  const double ramp = 2.0, e = 1e-6;
  EXPECT_EQ(wave_ramp(0.0, ramp), 0.0);
  EXPECT_EQ(wave_ramp(ramp, ramp), 1.0);
  EXPECT_EQ(wave_ramp(5.0, ramp), 1.0);
  EXPECT_NEAR(wave_ramp(1.0, ramp), 0.5, 1e-15);
  EXPECT_LT(wave_ramp(e, ramp) / e, 1e-5);  // slope pi^2 t / (2 ramp^2) near 0
  EXPECT_LT((1 - wave_ramp(ramp - e, ramp)) / e, 1e-5);
  EXPECT_EQ(wave_ramp(0.3, 0.0), 1.0);  // no ramp
}

// The discrete sea state holds Hm0 = 4 sqrt(m0) = Hs exactly: in its amplitudes, and in the
// variance of the elevation over one repeat period 1 / df, sampled finely enough that the
// components stay orthogonal (frequencies (i + 1/2) df: every product averages to zero).
// A displacement record's Fourier series: harmonics of the record's length come back with
// their strokes, frequencies and phases to round-off, and the series passes through every
// sample (the record's trigonometric interpolation), the mean left out.
TEST(DisplacementRecord, HarmonicsComeBackAndTheSeriesPassesThroughTheSamples) {
  const double dt = 0.01;
  const std::size_t n = 800;  // 8 s: the harmonics below are whole multiples of 1/8 Hz
  DisplacementRecord r;
  const double w1 = 2 * M_PI * 5 / (n * dt), w2 = 2 * M_PI * 13 / (n * dt);
  for (std::size_t j = 0; j < n; ++j) {
    const double t = static_cast<double>(j) * dt;
    r.times.push_back(t);
    r.values.push_back(0.002 + 0.03 * std::sin(w1 * t - 0.4) + 0.01 * std::sin(w2 * t - 2.0));
  }
  ASSERT_EQ(displacement_record_problem(r), "");
  const std::vector<PaddleHarmonic> all = record_harmonics(r, 0.0);
  EXPECT_EQ(all.size(), n / 2);
  const PaddleMotion motion{all, 0.0};
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j) {
    double x = 0, v = 0;
    paddle_state(motion, r.times[j], x, v);
    worst = std::max(worst, std::fabs(x - (r.values[j] - 0.002)));
  }
  EXPECT_LT(worst, 1e-12);
  // The dropped ones are round-off: two harmonics stay.
  const std::vector<PaddleHarmonic> kept = record_harmonics(r);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_NEAR(kept[0].omega, w1, 1e-12);
  EXPECT_NEAR(kept[0].stroke, 0.06, 1e-12);
  EXPECT_NEAR(kept[0].phase, 0.4 - 2 * M_PI * 0, 1e-9);
  EXPECT_NEAR(kept[1].omega, w2, 1e-12);
  EXPECT_NEAR(kept[1].stroke, 0.02, 1e-12);
  EXPECT_NEAR(std::remainder(kept[1].phase - 2.0, 2 * M_PI), 0.0, 1e-9);
}

// Dropping the smallest harmonics keeps the motion within sqrt(allowance) of the record's
// standard deviation (rms over the samples, by Parseval: what is dropped is orthogonal).
TEST(DisplacementRecord, DroppedHarmonicsStayWithinTheirAllowance) {
  const std::vector<WaveComponent> sea =
      jonswap_components({0.05, 1.4, 3.3, 0.07, 0.09}, 0.3, 2.2, 300, 11);
  DisplacementRecord r;
  const std::size_t n = 2000;
  double mean = 0;
  for (std::size_t j = 0; j < n; ++j) {
    r.times.push_back(0.01 * static_cast<double>(j));
    r.values.push_back(irregular_elevation(sea, r.times.back()));
    mean += r.values.back() / n;
  }
  r.values.back() = 0.5 * (r.values[n - 2] + r.values.front());  // leads on to its start
  double variance = 0;
  for (const double x : r.values) variance += (x - mean) * (x - mean) / n;
  const double allowance = 1e-4;
  const PaddleMotion motion{record_harmonics(r, allowance), 0.0};
  EXPECT_LT(motion.harmonics.size(), n / 2);
  double error2 = 0;
  for (std::size_t j = 0; j < n; ++j) {
    double x = 0, v = 0;
    paddle_state(motion, r.times[j], x, v);
    error2 += (x - (r.values[j] - mean)) * (x - (r.values[j] - mean)) / n;
  }
  EXPECT_LE(std::sqrt(error2), std::sqrt(allowance * variance) * (1 + 1e-9));
}

TEST(DisplacementRecord, RecordsThatCannotDriveAPaddleAreRefused) {
  DisplacementRecord r;
  for (int j = 0; j < 20; ++j) {
    r.times.push_back(0.1 * j);
    r.values.push_back(std::sin(2 * M_PI * j / 20.0));
  }
  EXPECT_EQ(displacement_record_problem(r), "");
  DisplacementRecord uneven = r;
  uneven.times[7] += 0.01;
  EXPECT_NE(displacement_record_problem(uneven).find("not equally spaced"), std::string::npos);
  DisplacementRecord jump;  // cut off at a crest: 1.0 back to the start, steps of 0.063
  for (int j = 0; j < 125; ++j) {
    jump.times.push_back(0.01 * j);
    jump.values.push_back(std::sin(2 * M_PI * j / 100.0));
  }
  EXPECT_NE(displacement_record_problem(jump).find("must lead on to its start"), std::string::npos);
  DisplacementRecord late = r;
  for (double& t : late.times) t += 1;
  EXPECT_NE(displacement_record_problem(late).find("starts at t = 1"), std::string::npos);
  DisplacementRecord short_one = r;
  short_one.times.resize(5), short_one.values.resize(5);
  EXPECT_NE(displacement_record_problem(short_one).find("at least 8"), std::string::npos);
}

TEST(IrregularWaves, JonswapSeaStateHoldsItsSignificantHeight) {
  const JonswapSpec s{0.1, 1.6, 3.3};
  const double f_min = 0.2, f_max = 2.0;
  const int n = 90;
  const std::vector<WaveComponent> c = jonswap_components(s, f_min, f_max, n, 7);
  double m0 = 0;
  for (const WaveComponent& w : c) m0 += 0.5 * w.amplitude * w.amplitude;
  EXPECT_NEAR(4 * std::sqrt(m0), s.hs, 1e-12 * s.hs);
  const double df = (f_max - f_min) / n, record = 1 / df;
  const int samples = 4 * static_cast<int>(f_max / df);
  double var = 0;
  for (int i = 0; i < samples; ++i) {
    const double eta = irregular_elevation(c, record * i / samples);
    var += eta * eta / samples;
  }
  EXPECT_NEAR(4 * std::sqrt(var), s.hs, 1e-9 * s.hs);
}

// The shape peaks at fp = 1 / Tp, and the peak is gamma times that of the Pierson-Moskowitz
// shape (gamma = 1) of the same Tp; the energy sits about the peak.
TEST(IrregularWaves, JonswapPeaksAtThePeakPeriod) {
  const JonswapSpec s{0.1, 1.6, 3.3}, pm{0.1, 1.6, 1.0};
  const double fp = 1 / s.tp;
  EXPECT_GT(jonswap_shape(s, fp), jonswap_shape(s, 0.99 * fp));
  EXPECT_GT(jonswap_shape(s, fp), jonswap_shape(s, 1.01 * fp));
  EXPECT_GT(jonswap_shape(pm, fp), jonswap_shape(pm, 0.99 * fp));
  EXPECT_GT(jonswap_shape(pm, fp), jonswap_shape(pm, 1.01 * fp));
  EXPECT_NEAR(jonswap_shape(s, fp) / jonswap_shape(pm, fp), s.gamma, 1e-12 * s.gamma);
  const std::vector<WaveComponent> c = jonswap_components(s, 0.2, 2.0, 90, 1);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].amplitude > c[peak].amplitude) peak = i;
  EXPECT_NEAR(c[peak].frequency, fp, 0.02);  // within one spacing (0.02 Hz)
}

// A seed gives one wave train, another seed another; phases lie in [0, 2 pi).
TEST(IrregularWaves, SeedFixesThePhases) {
  const JonswapSpec s{0.1, 1.6};
  const auto a = jonswap_components(s, 0.2, 2.0, 50, 11);
  const auto b = jonswap_components(s, 0.2, 2.0, 50, 11);
  const auto c = jonswap_components(s, 0.2, 2.0, 50, 12);
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].phase, b[i].phase);
    EXPECT_EQ(a[i].amplitude, c[i].amplitude);
    EXPECT_GE(a[i].phase, 0.0);
    EXPECT_LT(a[i].phase, 2 * M_PI);
    differ += a[i].phase != c[i].phase;
  }
  EXPECT_EQ(differ, static_cast<int>(a.size()));
}

TEST(IrregularWaves, BadSeaStatesAreRefused) {
  EXPECT_THROW(jonswap_components({0.0, 1.6}, 0.2, 2.0, 50, 1), Error);
  EXPECT_THROW(jonswap_components({0.1, 0.0}, 0.2, 2.0, 50, 1), Error);
  EXPECT_THROW(jonswap_components({0.1, 1.6, 0.5}, 0.2, 2.0, 50, 1), Error);
  EXPECT_THROW(jonswap_components({0.1, 1.6}, 2.0, 0.2, 50, 1), Error);
  EXPECT_THROW(jonswap_components({0.1, 1.6}, 0.2, 2.0, 0, 1), Error);
  // No energy in range: far below the peak the shape underflows to zero.
  EXPECT_THROW(jonswap_components({0.1, 0.01}, 0.1, 1.0, 10, 1), Error);
}

// In shallow water a piston moves the whole water column with the wave: its velocity equals
// the progressive wave's depth-averaged velocity at the paddle, (H/2) sigma / (kh) cos theta
// (exact for linear waves), in phase, to the relative O((kh)^4) by which Biesel's H/S differs
// from kh (H/S = kh (1 - (kh)^4 / 45 + ...)).
TEST(PaddleMotion, ShallowWaterPistonMovesWithTheWave) {
  const double h = 0.5, kh = 0.05;
  RegularWave w;
  w.depth = h;
  w.k = kh / h;
  w.omega = intrinsic_frequency(w.k, h, g);
  w.height = 0.01;
  w.phase = 0.4;
  const PaddleMotion m = regular_paddle_motion(PaddleType::Piston, w, 0.0);
  ASSERT_EQ(m.harmonics.size(), 1u);
  for (double t : {0.0, 1.7, 5.2, 11.9}) {
    double x, v;
    paddle_state(m, t, x, v);
    const double u_mean = 0.5 * w.height * w.omega / kh * std::cos(wave_phase(w, 0.0, t));
    const double scale = 0.5 * w.height * w.omega / kh;
    EXPECT_NEAR(v, u_mean, std::pow(kh, 4) / 40 * scale + 1e-15) << "t " << t;
  }
}

// The velocity is the displacement's derivative, through the ramp and after it (central
// differences, error O(dt^2)); the paddle starts at rest at X = 0.
TEST(PaddleMotion, VelocityIsTheDisplacementsRate) {
  const JonswapSpec sea{0.05, 1.4};
  const auto components = jonswap_components(sea, 0.3, 2.0, 40, 3);
  for (PaddleType type : {PaddleType::Piston, PaddleType::Flap}) {
    const PaddleMotion m = train_paddle_motion(type, irregular_wave_train(components, 0.5, 3.0, g));
    double x0, v0;
    paddle_state(m, 0.0, x0, v0);
    EXPECT_EQ(x0, 0.0);
    EXPECT_EQ(v0, 0.0);
    double stroke = 0;
    for (const PaddleHarmonic& hm : m.harmonics) stroke += hm.stroke;
    const double dt = 1e-5;
    for (double t : {0.4, 1.5, 2.9, 3.1, 7.3}) {
      double xa, va, xb, vb, x, v;
      paddle_state(m, t + dt, xa, va);
      paddle_state(m, t - dt, xb, vb);
      paddle_state(m, t, x, v);
      EXPECT_NEAR((xa - xb) / (2 * dt), v, 1e-6 * stroke * 2 * M_PI * 2.0) << "t " << t;
    }
  }
}

// An irregular sea of one component moves the paddle as the regular wave of that component
// does; a flap needs a longer stroke than a piston for the same wave.
TEST(PaddleMotion, OneComponentIsTheRegularWave) {
  const double h = 0.5;
  const WaveComponent c{0.8, 0.02, 1.1};
  RegularWave w;
  w.depth = h;
  w.omega = 2 * M_PI * c.frequency;
  w.k = wave_number(w.omega, h, g);
  w.height = 2 * c.amplitude;
  w.phase = c.phase;
  for (PaddleType type : {PaddleType::Piston, PaddleType::Flap}) {
    const PaddleMotion a = regular_paddle_motion(type, w, 2.0);
    const PaddleMotion b = train_paddle_motion(type, irregular_wave_train({c}, h, 2.0, g));
    for (double t : {0.5, 3.3}) {
      double xa, va, xb, vb;
      paddle_state(a, t, xa, va);
      paddle_state(b, t, xb, vb);
      EXPECT_NEAR(xa, xb, 1e-14);
      EXPECT_NEAR(va, vb, 1e-13);
    }
  }
  EXPECT_GT(regular_paddle_motion(PaddleType::Flap, w, 0).harmonics[0].stroke,
            regular_paddle_motion(PaddleType::Piston, w, 0).harmonics[0].stroke);
}

// Madsen's second-order piston correction against an independent derivation: the paddle's
// second-order volume flux, X2' h + d(X1 eta1)/dt at 2 omega (the moving face's flux, carried
// to x = 0), equal to the Stokes bound harmonic's flux omega a2 / k (from continuity), with the
// progressive mode only, gives A2 = H^2 / (32 h) (cosh kh (2 + cosh 2kh) / sinh^3 kh - 4 / m1).
// The two agree as kh -> 0, their difference 0.22 (kh)^4 of A2 (series expansion), and both
// tend to 3 H^2 / (32 k^3 h^4), the stroke that makes the bound harmonic alone, with relative
// error (2/3) (kh)^2.
TEST(SecondOrderGeneration, MadsenCorrectionIsTheShallowWaterFluxBalance) {
  const double h = 0.5, height = 0.01;
  for (double kh : {0.02, 0.05, 0.1, 0.2}) {
    const double k = kh / h, m1 = piston_height_to_stroke(kh);
    const double a2 = piston_second_order_amplitude(height, kh, h);
    const double flux =
        height * height / (32 * h) *
        (std::cosh(kh) * (2 + std::cosh(2 * kh)) / std::pow(std::sinh(kh), 3) - 4 / m1);
    EXPECT_NEAR(a2, flux, 0.3 * std::pow(kh, 4) * a2) << "kh " << kh;
    const double shallow = 3 * height * height / (32 * std::pow(k, 3) * std::pow(h, 4));
    EXPECT_NEAR(a2, shallow, 0.7 * kh * kh * shallow) << "kh " << kh;
    EXPECT_GT(a2, 0.0);
  }
  // Deep water: no bound term, -H^2 / (32 h); finite past the overflow of cosh.
  EXPECT_NEAR(piston_second_order_amplitude(height, 400.0, h), -height * height / (32 * h), 1e-18);
}

// Second-order generation adds one harmonic at twice the frequency and phase with stroke 2 A2;
// the first harmonic is first order's. A flap or an irregular sea is refused. The velocity
// table's sampling follows the fastest harmonic.
TEST(SecondOrderGeneration, PaddleMotionGetsTheSecondHarmonic) {
  RegularWave w;
  w.depth = 0.5;
  w.k = 1.6;
  w.omega = intrinsic_frequency(w.k, w.depth, g);
  w.height = 0.078;
  w.phase = 0.3;
  const PaddleMotion first = regular_paddle_motion(PaddleType::Piston, w, 2.0);
  const PaddleMotion second =
      regular_paddle_motion(PaddleType::Piston, w, 2.0, PaddleGeneration::SecondOrder);
  ASSERT_EQ(second.harmonics.size(), 2u);
  EXPECT_EQ(second.harmonics[0].stroke, first.harmonics[0].stroke);
  EXPECT_EQ(second.harmonics[1].omega, 2 * w.omega);
  EXPECT_EQ(second.harmonics[1].phase, 2 * w.phase);
  EXPECT_DOUBLE_EQ(second.harmonics[1].stroke,
                   2 * piston_second_order_amplitude(w.height, w.k * w.depth, w.depth));
  // X(t) - X1(t) = ramp (A2) sin(2 omega t - 2 phase) after the ramp.
  for (double t : {4.1, 7.77}) {
    double x1, v1, x2, v2;
    paddle_state(first, t, x1, v1);
    paddle_state(second, t, x2, v2);
    const double a2 = 0.5 * second.harmonics[1].stroke;
    EXPECT_NEAR(x2 - x1, a2 * std::sin(2 * w.omega * t - 2 * w.phase), 1e-15);
    EXPECT_NEAR(v2 - v1, 2 * w.omega * a2 * std::cos(2 * w.omega * t - 2 * w.phase), 1e-14);
  }
  EXPECT_THROW(regular_paddle_motion(PaddleType::Flap, w, 2.0, PaddleGeneration::SecondOrder),
               Error);
  const WaveTrain regular = regular_wave_train(w.height, 2 * M_PI / w.omega, w.depth, 2, 2.0, g);
  const PaddleMotion m =
      train_paddle_motion(PaddleType::Piston, regular, PaddleGeneration::SecondOrder);
  ASSERT_EQ(m.harmonics.size(), 2u);
  EXPECT_NEAR(paddle_sample_interval(m),
              0.5 * paddle_sample_interval(train_paddle_motion(PaddleType::Piston, regular)),
              1e-15);
  const auto sea = jonswap_components(JonswapSpec{0.05, 1.4}, 0.3, 2.0, 10, 3);
  EXPECT_THROW(train_paddle_motion(PaddleType::Piston, irregular_wave_train(sea, 0.5, 3.0, g),
                                   PaddleGeneration::SecondOrder),
               Error);
}

// Active absorption: the correction follows the reflected elevation measured at the gauge,
// delayed by the gauge-to-paddle travel time and scaled by the gain, to the linear
// interpolation's error between updates; the gain omega / m1 is the classical shallow-water
// gain sqrt(g / h) in shallow water (relative error (kh)^2 / 3 or less at kh = 0.05).
TEST(ActiveAbsorption, CorrectionIsTheDelayedReflectedWaveTimesTheGain) {
  const double h = 0.5, kh = 0.05, k = kh / h;
  const double omega = intrinsic_frequency(k, h, g);
  EXPECT_NEAR(omega / piston_height_to_stroke(kh), std::sqrt(g / h),
              kh * kh / 3 * std::sqrt(g / h));
  const double gain = 2.7, delay = 0.137, w = 5.0, a = 0.01, dt = 1e-3;
  PaddleAbsorber absorber({gain, delay, 0.0});
  for (int n = 0; n <= 3000; ++n) {
    const double t = n * dt;
    absorber.update(t, a * std::cos(w * t));
    if (t < delay) {
      EXPECT_EQ(absorber.velocity(), 0.0) << "t " << t;  // nothing has reached the paddle
    } else {
      // Linear interpolation of a cos sampled every dt: error a (w dt)^2 / 8 at most.
      EXPECT_NEAR(absorber.velocity(), -gain * a * std::cos(w * (t - delay)),
                  gain * a * (w * dt) * (w * dt) / 8 + 1e-15)
          << "t " << t;
    }
  }
}

// The drift correction holds the correction's excursion: under a constant reflected elevation
// c it settles at -G c tau instead of growing without bound (the first-order lag
// X' = -G c - X / tau, integrated by the explicit updates with step dt << tau); a state saved
// and restored continues exactly.
TEST(ActiveAbsorption, DriftCorrectionBoundsTheExcursionAndStateRestores) {
  const double gain = 2.0, tau = 5.0, c = 0.003, dt = 0.01;
  PaddleAbsorber absorber({gain, 0.1, tau});
  std::vector<double> saved;
  PaddleAbsorber copy({gain, 0.1, tau});
  for (int n = 0; n <= 6000; ++n) {
    absorber.update(n * dt, c);
    if (n == 2500) saved = absorber.state();
  }
  // After 60 s = 12 tau the lag has settled to within exp(-12) and the explicit steps' error,
  // of order dt / tau.
  EXPECT_NEAR(absorber.excursion(), -gain * c * tau, 2 * dt / tau * gain * c * tau);
  copy.restore(saved);
  PaddleAbsorber again({gain, 0.1, tau});
  again.restore(saved);
  for (int n = 2501; n <= 6000; ++n) again.update(n * dt, c);
  EXPECT_EQ(again.excursion(), absorber.excursion());
  EXPECT_EQ(again.velocity(), absorber.velocity());
  EXPECT_THROW(copy.restore(std::vector<double>{1.0, 2.0}), Error);
}

// A sampled sine about a raised mean: every wave's period is T (the crossings interpolated
// linearly where the sine is nearly straight: error far below 1e-6 T at 200 samples a
// period) and its height 2A less at most the sampling loss A (omega dt)^2 / 4; the mean level
// is found to within A / (samples) (the record holds whole periods plus one sample), and the
// crests and troughs, measured from it, to that plus their sampling loss A (omega dt)^2 / 8.
TEST(WaveRecord, ZeroUpcrossingOfASine) {
  const double T = 1.3, A = 0.02, level = 0.1, dt = T / 200;
  const double w = 2 * M_PI / T;
  std::vector<double> t, eta;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(i * dt);
    eta.push_back(level + A * std::sin(w * t.back() + 0.9));
  }
  const WaveRecordSummary s = zero_upcrossing_waves(t, eta);
  EXPECT_NEAR(s.mean_level, level, A / 2000);
  ASSERT_GE(s.waves.size(), 9u);
  const double loss = A * (w * dt) * (w * dt) / 4;
  for (const RecordWave& r : s.waves) {
    EXPECT_NEAR(r.period, T, 1e-6 * T);
    EXPECT_NEAR(r.height(), 2 * A, loss + 1e-12);
    EXPECT_LE(r.height(), 2 * A + 1e-12);
  }
  EXPECT_NEAR(s.mean_period, T, 1e-6 * T);
  EXPECT_NEAR(s.mean_crest, A, loss / 2 + A / 2000);
  EXPECT_NEAR(s.mean_trough, A, loss / 2 + A / 2000);
  EXPECT_NEAR(s.h_third, 2 * A, loss + 1e-12);
}

// The record before t_from (a ramp, a transient) is left out; a record too short for two
// up-crossings has no waves.
TEST(WaveRecord, StartTimeAndShortRecords) {
  const double T = 1.0, dt = 0.01;
  std::vector<double> t, eta;
  for (int i = 0; i <= 1000; ++i) {
    t.push_back(i * dt);
    const double a = t.back() < 4 ? 0.2 : 0.02;  // large waves first
    eta.push_back(a * std::sin(2 * M_PI * t.back() / T));
  }
  const WaveRecordSummary late = zero_upcrossing_waves(t, eta, 4.0);
  ASSERT_FALSE(late.waves.empty());
  EXPECT_NEAR(late.mean_height, 0.04, 0.001);
  EXPECT_GT(zero_upcrossing_waves(t, eta).mean_height, 0.05);
  // 0.9 periods: one up-crossing of the record's mean, no whole wave.
  const std::vector<double> t3(t.begin(), t.begin() + 90), e3(eta.begin(), eta.begin() + 90);
  EXPECT_TRUE(zero_upcrossing_waves(t3, e3).waves.empty());
}

}  // namespace
}  // namespace netsph
