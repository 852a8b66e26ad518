#include "netsph/waves/paddle_motion.hpp"

#include <cmath>

#include "netsph/core/error.hpp"

namespace netsph {

PaddleMotion regular_paddle_motion(PaddleType type, const RegularWave& w, double ramp,
                                   PaddleGeneration generation) {
  const double kh = w.k * w.depth;
  PaddleMotion m{{{w.height / paddle_height_to_stroke(type, kh), w.omega, w.phase}}, ramp};
  if (generation == PaddleGeneration::SecondOrder) {
    if (type != PaddleType::Piston)
      throw Error("", "second-order generation is built for a piston paddle only");
    // X2 = A2 sin(2 omega t - 2 phase): stroke 2 A2 at twice the frequency and phase.
    m.harmonics.push_back(
        {2 * piston_second_order_amplitude(w.height, kh, w.depth), 2 * w.omega, 2 * w.phase});
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
