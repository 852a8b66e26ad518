#pragma once
// A wave train as a case specifies it, set up for the run: its components as regular waves in
// still water (one for a regular wave, many for an irregular sea), the ramp that starts it
// from rest, and what follows from them: the paddle motion that makes it (first-order
// wavemaker theory), the paddle's velocity sampled for a moving wall, and the target surface
// elevation a gauge is compared with.
// Host functions: set-up and output work, not per-particle work.
#include <vector>

#include "netsph/waves/irregular_waves.hpp"
#include "netsph/waves/paddle_motion.hpp"
#include "netsph/waves/wave_kinematics.hpp"

namespace netsph {

struct WaveTrain {
  /// The components, each a RegularWave with its own height, frequency and wave number in
  /// still water of the same depth; their phase is the phase at the paddle.
  std::vector<RegularWave> components;
  double ramp = 0;  ///< s: the paddle's ramp from rest (wave_ramp)
  /// m/s: the speed at which the ramp travels down the flume, the group velocity of the
  /// component with the largest height (energy travels at the group velocity: Dean &
  /// Dalrymple 1991, sec. 4.4), plus the current that carries it.
  double front_speed = 0;
};

/// The component with the largest height (the first of equals); null for an empty train.
const RegularWave* tallest_component(const WaveTrain& train);

/// A train of one regular wave of height H (m) and period T (s, in the earth frame) in water of
/// depth h (m), to first order (order 1) or with the Stokes second-order surface (order 2),
/// ramped over `ramp`, on a uniform current U (m/s) along the waves' direction (0: still
/// water; the wave number then solves the Doppler-shifted dispersion relation).
WaveTrain regular_wave_train(double height, double period, double depth, int order, double ramp,
                             double g, double current = 0);
/// A train of irregular-sea components (irregular_waves.hpp) in water of depth h, linear, on a
/// uniform current U as for regular_wave_train.
WaveTrain irregular_wave_train(const std::vector<WaveComponent>& components, double depth,
                               double ramp, double g, double current = 0);

/// The paddle motion that makes the train. First order: each component's stroke from its own
/// kh through the paddle's transfer function; the Stokes second-order surface then grows in
/// the flume by itself, along with a free second harmonic that travels slower and makes the
/// wave's shape change down the flume. Second order (a regular wave and a piston only:
/// netsph::Error otherwise): the paddle also moves at twice the frequency to cancel that free
/// harmonic (regular_paddle_motion).
PaddleMotion train_paddle_motion(PaddleType type, const WaveTrain& train,
                                 PaddleGeneration generation = PaddleGeneration::FirstOrder);

/// The target surface elevation, m, at `distance` (m) down the flume from the paddle's rest
/// position at time t: the components' linear (or Stokes second-order) elevation, times the
/// ramp delayed by the time the ramp takes to get there (distance / front_speed). Evanescent
/// modes near the paddle (within about one depth) are not included.
double train_elevation(const WaveTrain& train, double distance, double t);

/// The train's orbital velocity, m/s (u along the waves' direction, w up), at `distance` down
/// the flume from the phase origin and height z above the still-water level (z <= the
/// surface), at time t: the components' orbital velocities (wave_velocity, without the current
/// they ride on) summed and ramped as train_elevation ramps the surface.
void train_velocity(const WaveTrain& train, double distance, double z, double t, double& u,
                    double& w);

/// The paddle's velocity (dX/dt, m/s) sampled every `interval` seconds from t = 0 to at least
/// `end_time`, for a moving wall's piecewise-linear velocity history: times and velocities of
/// equal size. Also returns the largest excursion |X| over those samples, m.
struct SampledPaddle {
  std::vector<double> times, velocities;
  double max_excursion = 0;
};
SampledPaddle sample_paddle(const PaddleMotion& m, double end_time, double interval);

/// The sampling interval for sample_paddle: a hundredth of the period of the motion's fastest
/// harmonic, so that the displacement integrated from the piecewise-linear velocity is within
/// about (2 pi / 100)^2 / 12 = 3e-4 of the paddle's own (the trapezoid rule's error on a
/// sinusoid).
double paddle_sample_interval(const PaddleMotion& m);

}  // namespace netsph
