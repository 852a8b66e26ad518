// The paddle's active absorption in the step (waves/active_absorption.hpp): at each step's
// start the surface is measured on a vertical line at the absorber's gauge (the kernel
// coverage falling through one half, as wave gauges read it: sph/free_surface.hpp), the target
// elevation there is subtracted, and the absorber sets the paddle's correction velocity for the
// step. Both the CPU step and the device step take the correction through the wall's velocity
// (update_wall_kinematics; the device's wall_velocity), so the paddle's particles move with it.
#include <cmath>

#include "netsph/backend/cpu/probe_pass.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/sph/free_surface.hpp"

namespace netsph {

void Simulation::setup_absorber() {
  const WaveSpec& w = spec_.waves;
  if (!w.given || !w.absorption.active) return;
  absorber_ = std::make_unique<PaddleAbsorber>(AbsorberSettings{
      w.absorption.gain, w.absorption.delay, w.absorption.drift_time, w.absorption.mean_time});
  // From the bed to two wave heights above the still water, every quarter spacing (the
  // gauges' sampling: the surface interpolated between samples to a fraction of that).
  const double dz = spec_.simulation.dp / 4;
  const double bottom = w.still_level - w.depth, top = w.still_level + 2 * w.reference_height();
  const auto n = static_cast<std::size_t>(std::ceil((top - bottom) / dz)) + 1;
  const double y = w.absorption.gauge_y;
  for (std::size_t k = 0; k < n; ++k) {
    const double z = std::min(bottom + static_cast<double>(k) * dz, top);
    absorber_z_.push_back(z);
    absorber_points_.push_back({w.absorption.gauge_x, y, z});
  }
  absorber_values_.resize(n);
  absorber_sums_.resize(n);
  absorber_coverage_.resize(n);
}

void Simulation::update_absorber() {
  // At the first step the water is at rest, and the grid not yet sorted: the first reading,
  // which sets the water's own level, is the second step's.
  if (!absorber_ || steps_ == 0) return;
  // The device samples with the cell table of its last step; the CPU step calls this right
  // after its sort, so that a restarted run (which sorts afresh) reads the same sums.
  if (sample_on_device(absorber_points_, absorber_values_)) {
    for (std::size_t k = 0; k < absorber_values_.size(); ++k)
      absorber_coverage_[k] = absorber_values_[k].coverage;
  } else {
    // The coverage is the sums' volume weight (sph/shepard.hpp: shepard_value).
    point_sums(scene_.model, grid_, p_, absorber_points_, absorber_sums_);
    for (std::size_t k = 0; k < absorber_sums_.size(); ++k)
      absorber_coverage_[k] = absorber_sums_[k].volume_weight;
  }
  const WaveSpec& w = spec_.waves;
  const double eta = surface_from_coverage(absorber_z_, absorber_coverage_) - w.still_level;
  absorber_->update(time_, eta - w.target_elevation(w.absorption.gauge_x, time_));
}

Vec3f Simulation::paddle_correction(std::size_t wall) const {
  if (!absorber_ || wall != spec_.waves.wall) return {};
  return Vec3f(Vec3d{spec_.waves.direction * absorber_->velocity(), 0, 0});
}

}  // namespace netsph
