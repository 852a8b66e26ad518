#pragma once
// A paddle driven by a displacement series ([waves] type = "displacement"): the record a
// laboratory's wavemaker signal or another program gives, X at equally spaced times from
// t = 0, turned into the sum of harmonics that passes through every sample (its discrete
// Fourier series, the record's trigonometric interpolation). The paddle then moves as any
// other (paddle_motion.hpp: one definition of the motion, its sampled velocity and its
// largest excursion), repeating the record when the run is longer, and each harmonic, through
// the paddle's transfer function, is a linear wave component whose sum is the target the
// gauges are compared with (wave_train.hpp). Host functions: set-up work.
#include <string>
#include <vector>

#include "netsph/waves/irregular_waves.hpp"
#include "netsph/waves/paddle_motion.hpp"

namespace netsph {

/// The displacement series: times (s) from 0, equally spaced, and X (m) at each.
struct DisplacementRecord {
  std::vector<double> times, values;
};

/// Why a record cannot be a paddle's motion (empty when it can): at least 8 samples, times from
/// 0 equally spaced (to 1e-6 of the spacing), finite values, and an end that leads on to the
/// start (the step from the last sample to the first no larger than three of the record's
/// largest steps, so that repeating it makes no jump: a jump puts energy at every frequency up
/// to the sampling's limit).
std::string displacement_record_problem(const DisplacementRecord& r);

/// The record's Fourier series X(t) = sum (S/2) sin(omega t - phase) (the mean left out: the
/// paddle starts where the case puts it), its harmonics at multiples of 2 pi / (N dt) up to the
/// sampling's limit. Harmonics too small to matter are dropped, the smallest first, as long as
/// what is dropped stays under `dropped_variance` of the record's variance (so the motion is
/// within sqrt(dropped_variance) of the record's standard deviation, rms). A direct transform:
/// O(N^2) for N samples (displacement_record_problem bounds N).
std::vector<PaddleHarmonic> record_harmonics(const DisplacementRecord& r,
                                             double dropped_variance = 1e-6);

/// The most samples a record may hold: its direct transform then takes about a second.
inline constexpr std::size_t kMaxRecordSamples = 20000;

}  // namespace netsph
