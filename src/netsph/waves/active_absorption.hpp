#pragma once
// Active absorption at a piston paddle (the AWAS-type absorption of Schaffer & Klopman 2000,
// "Review of multidirectional active wave absorption methods", J. Waterway Port Coastal Ocean
// Eng. 126(2):88-97, as DualSPHysics uses it: Altomare et al. 2017, Coastal Eng. 127:37-54).
// The wave coming back to the paddle (reflected by the far end or by a body) is measured as
// the elevation at a gauge in front of the paddle less the elevation the paddle is meant to
// make there, eta_R. A piston that moves with that wave's own velocity meets it as the water
// would and sends nothing back: the paddle's velocity gets the correction
//   u_c(t) = -G eta_R(t - delay) - X_c(t) / drift_time   (along the waves' direction),
// G = omega / m1(kh), m1 = H / S (piston_height_to_stroke): the paddle velocity per unit
// amplitude of a progressive wave at the waves' frequency, whose shallow-water limit is
// sqrt(g / h), the classical absorber gain (Milgram 1970). The gauge stands d in front of the
// paddle, and the reflected wave reaches the paddle d / c later (c = omega / k): delay. X_c is
// the correction's own excursion; the slow restoring term keeps it from drifting (its effect
// at the waves' frequency is 1 / (omega drift_time), under 2% at ten periods). A steady
// offset of the measured level is no wave to absorb (the still level a fill's particle layers
// make differs from the case's by up to half a spacing; the mean level sets down under waves):
// eta_R is taken relative to its running mean (time scale mean_time, started at the first
// reading), a high-pass whose phase lead at the waves' frequency is 1 / (omega mean_time),
// about 3 degrees at three periods.
// Host code: the paddle's velocity is evaluated on the host once per step for every backend.
#include <span>
#include <vector>

namespace netsph {

struct AbsorberSettings {
  double gain = 0;        ///< G, 1/s (m/s of paddle velocity per m of elevation)
  double delay = 0;       ///< s: from the gauge to the paddle at the phase speed
  double drift_time = 0;  ///< s (0: no drift correction)
  double mean_time = 0;   ///< s: the running mean's time scale (0: no mean removed)
};

class PaddleAbsorber {
 public:
  explicit PaddleAbsorber(const AbsorberSettings& s) : s_(s) {}

  /// At time t (a step's start, increasing from call to call): takes the reflected elevation
  /// eta_R measured at the gauge now, advances the correction's excursion over the time since
  /// the last call, and sets the correction velocity for the step that follows.
  void update(double t, double eta_reflected);
  /// The correction velocity along the waves' direction, m/s (0 before the first update).
  double velocity() const { return velocity_; }
  /// The correction's excursion along the waves' direction, m.
  double excursion() const { return excursion_; }

  /// The state a restart needs, and its restoration (a state from state()).
  std::vector<double> state() const;
  void restore(std::span<const double> state);

 private:
  /// eta_R at time t from the history (linear between records; the first record before it).
  double delayed(double t) const;

  AbsorberSettings s_;
  double velocity_ = 0, excursion_ = 0, last_time_ = 0, mean_ = 0;
  bool started_ = false;
  std::vector<double> times_, etas_;  ///< the records still needed for the delay
};

}  // namespace netsph
