#include "netsph/waves/wave_train.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/error.hpp"
#include "netsph/waves/dispersion.hpp"

namespace netsph {

namespace {

/// The group velocity of the tallest component in the earth frame (relative to the water,
/// plus the current that carries it).
double tallest_group_velocity(const WaveTrain& train, double g) {
  const RegularWave* tallest = tallest_component(train);
  return tallest ? relative_group_velocity(tallest->k, tallest->depth, g) + tallest->current : 0.0;
}

/// The wave number of angular frequency omega on the current (still water: U = 0).
double wave_number_for(double omega, double depth, double current, double g) {
  return current == 0 ? wave_number(omega, depth, g)
                      : wave_number_on_current(omega, depth, current, g);
}

}  // namespace

const RegularWave* tallest_component(const WaveTrain& train) {
  const RegularWave* tallest = nullptr;
  for (const RegularWave& c : train.components)
    if (!tallest || c.height > tallest->height) tallest = &c;
  return tallest;
}

WaveTrain regular_wave_train(double height, double period, double depth, int order, double ramp,
                             double g, double current) {
  RegularWave w;
  w.height = height;
  w.omega = 2 * M_PI / period;
  w.k = wave_number_for(w.omega, depth, current, g);
  w.depth = depth;
  w.current = current;
  w.order = order;
  WaveTrain train{{w}, ramp, 0};
  train.front_speed = tallest_group_velocity(train, g);
  return train;
}

WaveTrain irregular_wave_train(const std::vector<WaveComponent>& components, double depth,
                               double ramp, double g, double current) {
  WaveTrain train;
  train.ramp = ramp;
  train.components.reserve(components.size());
  for (const WaveComponent& c : components) {
    RegularWave w;
    w.height = 2 * c.amplitude;
    w.omega = 2 * M_PI * c.frequency;
    w.k = wave_number_for(w.omega, depth, current, g);
    w.depth = depth;
    w.current = current;
    w.phase = c.phase;
    train.components.push_back(w);
  }
  train.front_speed = tallest_group_velocity(train, g);
  return train;
}

PaddleMotion train_paddle_motion(PaddleType type, const WaveTrain& train,
                                 PaddleGeneration generation) {
  if (generation == PaddleGeneration::SecondOrder) {
    if (train.components.size() != 1)
      throw Error("", "second-order generation is built for regular waves only");
    return regular_paddle_motion(type, train.components.front(), train.ramp, generation);
  }
  PaddleMotion m;
  m.ramp = train.ramp;
  m.harmonics.reserve(train.components.size());
  for (const RegularWave& w : train.components)
    m.harmonics.push_back(regular_paddle_motion(type, w, train.ramp).harmonics.front());
  return m;
}

double train_elevation(const WaveTrain& train, double distance, double t) {
  // Behind the origin (distance < 0) the ramp is the origin's: the waves start there.
  const double arrival = train.front_speed > 0 ? std::fmax(distance, 0.0) / train.front_speed : 0.0;
  const double ramp = wave_ramp(t - arrival, train.ramp);
  if (!(ramp > 0)) return 0;
  double eta = 0;
  for (const RegularWave& w : train.components) eta += wave_elevation(w, distance, t);
  return ramp * eta;
}

void train_velocity(const WaveTrain& train, double distance, double z, double t, double& u,
                    double& w) {
  u = w = 0;
  // Behind the origin (distance < 0) the ramp is the origin's: the waves start there.
  const double arrival = train.front_speed > 0 ? std::fmax(distance, 0.0) / train.front_speed : 0.0;
  const double ramp = wave_ramp(t - arrival, train.ramp);
  if (!(ramp > 0)) return;
  for (const RegularWave& c : train.components) {
    double uc = 0, wc = 0;
    wave_velocity(c, distance, z, t, uc, wc);
    u += uc - c.current;
    w += wc;
  }
  u *= ramp, w *= ramp;
}

SampledPaddle sample_paddle(const PaddleMotion& m, double end_time, double interval) {
  SampledPaddle s;
  const auto n = static_cast<std::size_t>(std::ceil(end_time / interval)) + 2;
  s.times.resize(n);
  s.velocities.assign(n, 0.0);
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) s.times[i] = static_cast<double>(i) * interval;
  // Each harmonic's sine and cosine advance by a rotation through omega * interval from one
  // sample to the next (a JONSWAP sea has thousands of harmonics and a long run millions of
  // samples: two library calls per pair would take minutes). The rotation's round-off grows
  // linearly, so every block starts again from the library's values: within a block of 1024
  // samples it stays below 1e-12.
  constexpr std::size_t kBlock = 1024;
  for (const PaddleHarmonic& h : m.harmonics) {
    const double a = 0.5 * h.stroke, c_step = std::cos(h.omega * interval),
                 s_step = std::sin(h.omega * interval);
    for (std::size_t begin = 0; begin < n; begin += kBlock) {
      const double arg = h.omega * s.times[begin] - h.phase;
      double sn = std::sin(arg), cs = std::cos(arg);
      const std::size_t end = std::min(n, begin + kBlock);
      for (std::size_t i = begin; i < end; ++i) {
        x[i] += a * sn;
        s.velocities[i] += a * h.omega * cs;
        const double next_sn = sn * c_step + cs * s_step;
        cs = cs * c_step - sn * s_step;
        sn = next_sn;
      }
    }
  }
  // X = r(t) x(t): dX/dt = r' x + r x' (paddle_state's rule).
  for (std::size_t i = 0; i < n; ++i) {
    const double t = s.times[i], r = wave_ramp(t, m.ramp);
    s.velocities[i] = wave_ramp_rate(t, m.ramp) * x[i] + r * s.velocities[i];
    s.max_excursion = std::max(s.max_excursion, std::fabs(r * x[i]));
  }
  return s;
}

double paddle_sample_interval(const PaddleMotion& m) {
  double fastest = 0;
  for (const PaddleHarmonic& h : m.harmonics) fastest = std::max(fastest, h.omega);
  return fastest > 0 ? 2 * M_PI / fastest / 100 : 0.0;
}

}  // namespace netsph
