#include "netsph/waves/paddle_motion.hpp"

#include <cmath>

namespace netsph {

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
