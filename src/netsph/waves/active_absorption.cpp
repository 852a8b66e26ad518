#include "netsph/waves/active_absorption.hpp"

#include <algorithm>
#include <cmath>

#include "netsph/core/error.hpp"

namespace netsph {

void PaddleAbsorber::update(double t, double eta_reflected) {
  // NaN (a gauge that found no water: a deep trough) counts as the mean level rather than
  // poisoning the paddle's motion.
  const double eta = std::isfinite(eta_reflected) ? eta_reflected : (started_ ? mean_ : 0.0);
  if (started_) {
    excursion_ += velocity_ * (t - last_time_);
    if (s_.mean_time > 0) mean_ += (eta - mean_) * std::min(1.0, (t - last_time_) / s_.mean_time);
  } else {
    mean_ = s_.mean_time > 0 ? eta : 0.0;  // the first reading: the water's own level
  }
  started_ = true;
  last_time_ = t;
  times_.push_back(t);
  etas_.push_back(eta - mean_);
  // Keep one record at or before t - delay and everything after it.
  std::size_t drop = 0;
  while (drop + 1 < times_.size() && times_[drop + 1] <= t - s_.delay) ++drop;
  if (drop > 0) {
    times_.erase(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(drop));
    etas_.erase(etas_.begin(), etas_.begin() + static_cast<std::ptrdiff_t>(drop));
  }
  const double drift = s_.drift_time > 0 ? excursion_ / s_.drift_time : 0.0;
  velocity_ = -s_.gain * delayed(t - s_.delay) - drift;
}

double PaddleAbsorber::delayed(double t) const {
  if (times_.empty() || t < times_.front()) return 0;  // before the first record: no wave
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  if (it == times_.end()) return etas_.back();
  const auto k = static_cast<std::size_t>(it - times_.begin());
  const double w = (t - times_[k - 1]) / (times_[k] - times_[k - 1]);
  return etas_[k - 1] * (1 - w) + etas_[k] * w;
}

std::vector<double> PaddleAbsorber::state() const {
  std::vector<double> s = {velocity_, excursion_, last_time_, started_ ? 1.0 : 0.0, mean_};
  for (std::size_t k = 0; k < times_.size(); ++k) s.push_back(times_[k]), s.push_back(etas_[k]);
  return s;
}

void PaddleAbsorber::restore(std::span<const double> s) {
  if (s.size() < 5 || s.size() % 2 != 1)
    throw Error("checkpoint", "the paddle absorber's state is damaged (wrong size)");
  velocity_ = s[0], excursion_ = s[1], last_time_ = s[2], started_ = s[3] != 0, mean_ = s[4];
  times_.clear(), etas_.clear();
  for (std::size_t k = 5; k < s.size(); k += 2) times_.push_back(s[k]), etas_.push_back(s[k + 1]);
}

}  // namespace netsph
