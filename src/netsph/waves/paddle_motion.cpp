#include "netsph/waves/paddle_motion.hpp"

#include <cmath>

#include "netsph/waves/dispersion.hpp"

namespace netsph {

PaddleMotion irregular_paddle_motion(PaddleType type, const std::vector<WaveComponent>& components,
                                     double depth, double ramp, double g) {
  PaddleMotion m;
  m.ramp = ramp;
  m.harmonics.reserve(components.size());
  for (const WaveComponent& c : components) {
    const double omega = 2 * M_PI * c.frequency;
    const double kh = wave_number(omega, depth, g) * depth;
    m.harmonics.push_back({2 * c.amplitude / paddle_height_to_stroke(type, kh), omega, c.phase});
  }
  return m;
}

void paddle_state(const PaddleMotion& m, double t, double& displacement, double& velocity) {
  double x = 0, v = 0;
  for (const PaddleHarmonic& h : m.harmonics) {
    const double a = 0.5 * h.stroke, arg = h.omega * t - h.phase;
    x += a * std::sin(arg);
    v += a * h.omega * std::cos(arg);
  }
  // X = r(t) x(t): dX/dt = r' x + r x'.
  const double r = wave_ramp(t, m.ramp);
  displacement = r * x;
  velocity = wave_ramp_rate(t, m.ramp) * x + r * v;
}

}  // namespace netsph
