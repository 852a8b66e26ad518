#include "netsph/waves/displacement_record.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <fmt/format.h>

namespace netsph {

std::string displacement_record_problem(const DisplacementRecord& r) {
  const std::size_t n = r.times.size();
  if (r.values.size() != n) {
    return fmt::format("has {} times and {} values: give one value per time", n, r.values.size());
  }
  if (n < 8) return fmt::format("has {} samples: a record needs at least 8", n);
  if (n > kMaxRecordSamples) {
    return fmt::format(
        "has {} samples, more than {} (its transform is direct, O(N^2)): sample it "
        "more coarsely, a hundred samples per period of its shortest wave is "
        "plenty",
        n, kMaxRecordSamples);
  }
  if (r.times[0] != 0) {
    return fmt::format("starts at t = {:g} s: a record starts at t = 0, the run's start",
                       r.times[0]);
  }
  const double dt = r.times[1] - r.times[0];
  if (!(dt > 0) || !std::isfinite(dt)) return "has times that do not increase";
  double low = r.values[0], high = r.values[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (std::fabs(r.times[i] - static_cast<double>(i) * dt) > 1e-6 * dt) {
      return fmt::format(
          "is not equally spaced in time: sample {} is at t = {:.9g} s, and the "
          "first two put it at {:.9g} s (the record's harmonics need equal "
          "spacing; resample it)",
          i + 1, r.times[i], static_cast<double>(i) * dt);
    }
    if (!std::isfinite(r.values[i]))
      return fmt::format("has a value that is not finite at sample {}", i + 1);
    low = std::min(low, r.values[i]);
    high = std::max(high, r.values[i]);
  }
  // A micrometre is far below anything a particle spacing resolves; below it the record's
  // waves are round-off (and their frequencies, scaled by their heights, overflow).
  if (!(high - low > 1e-6)) {
    return fmt::format("never moves: its values span {:.3g} m, under a micrometre", high - low);
  }
  // The paddle repeats the record: from its last sample it goes on, a sample interval later, to
  // its first. That step must be no larger than the record's own steps (three times the
  // largest, for a signal sampled a few times per period): a jump puts energy at every frequency
  // up to the sampling's limit.
  // The step into the last sample is left out: a glitch there would excuse itself.
  double largest_step = 0;
  for (std::size_t i = 1; i + 1 < n; ++i)
    largest_step = std::max(largest_step, std::fabs(r.values[i] - r.values[i - 1]));
  const double closing = std::fabs(r.values[0] - r.values[n - 1]);
  if (closing > 3 * largest_step) {
    return fmt::format(
        "ends at {:.6g} m and starts at {:.6g} m: the paddle repeats the record, "
        "so its end must lead on to its start as its samples lead on to each "
        "other (a step of {:.3g} m, against at most {:.3g} m between its samples; "
        "bring the signal back to its start at the end, as a wavemaker's "
        "ramp-down does)",
        r.values[n - 1], r.values[0], closing, largest_step);
  }
  return {};
}

std::vector<PaddleHarmonic> record_harmonics(const DisplacementRecord& r, double dropped_variance) {
  const std::size_t n = r.times.size();
  const double dt = r.times[1] - r.times[0];
  // cos and sin of 2 pi m / N: the transform's every factor, indexed by n j mod N (exact, and
  // no trigonometric call in the double loop).
  std::vector<double> cosines(n), sines(n);
  for (std::size_t m = 0; m < n; ++m) {
    const double angle = 2 * M_PI * static_cast<double>(m) / static_cast<double>(n);
    cosines[m] = std::cos(angle);
    sines[m] = std::sin(angle);
  }
  // X(t_j) = mean + sum_k a_k cos(omega_k t_j) + b_k sin(omega_k t_j), omega_k = 2 pi k / (N dt),
  // k = 1 .. N/2; a_k = (2/N) sum_j x_j cos(2 pi k j / N), b_k likewise with sin (at k = N/2,
  // for N even, a_k = (1/N) sum_j x_j (-1)^j and b_k = 0).
  std::vector<PaddleHarmonic> all;
  std::vector<double> variance;
  const double inverse = 1.0 / static_cast<double>(n);
  for (std::size_t k = 1; 2 * k <= n; ++k) {
    double a = 0, b = 0;
    std::size_t index = 0;  // k j mod N
    for (std::size_t j = 0; j < n; ++j) {
      a += r.values[j] * cosines[index];
      b += r.values[j] * sines[index];
      index += k;
      if (index >= n) index -= n;
    }
    const bool nyquist = 2 * k == n;
    a *= (nyquist ? 1 : 2) * inverse;
    b = nyquist ? 0 : 2 * b * inverse;
    // a cos + b sin = A sin(omega t - phase) with A = hypot(a, b), phase = atan2(-a, b).
    const double amplitude = std::hypot(a, b);
    const double omega = 2 * M_PI * static_cast<double>(k) / (static_cast<double>(n) * dt);
    all.push_back({2 * amplitude, omega, std::atan2(-a, b)});
    variance.push_back(0.5 * amplitude * amplitude);
  }
  // Drop the smallest while what is dropped stays within the allowance.
  const double total = std::accumulate(variance.begin(), variance.end(), 0.0);
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return variance[x] < variance[y]; });
  std::vector<bool> kept(all.size(), true);
  double dropped = 0;
  for (const std::size_t i : order) {
    if (dropped + variance[i] > dropped_variance * total) break;
    dropped += variance[i];
    kept[i] = false;
  }
  std::vector<PaddleHarmonic> harmonics;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (kept[i]) harmonics.push_back(all[i]);
  return harmonics;
}

}  // namespace netsph
