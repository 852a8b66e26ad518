#pragma once
// DeviceRun on one executor: the DeviceStepper template behind the plain interface. Included
// only where an executor instantiates the step (device_run_host.cpp and backend/cuda/*.cu).
#include <utility>

#include "netsph/backend/device/device_run.hpp"
#include "netsph/backend/device/device_stepper.hpp"

namespace netsph {

template <class Exec>
class DeviceRunOn final : public DeviceRun {
 public:
  DeviceRunOn(DeviceSetup setup, const ParticleSet& p) : s_(std::move(setup), p) {}
  DeviceStepReport step() override { return s_.step(); }
  void download(ParticleSet& p) const override { s_.download(p); }
  double time() const override { return s_.time(); }
  std::int64_t steps() const override { return s_.steps(); }
  std::size_t size() const override { return s_.size(); }
  double bytes_per_particle() const override { return s_.bytes_per_particle(); }
  void download_cell_begin(std::vector<std::uint32_t>& begin) const override {
    s_.download_cell_begin(begin);
  }
  ParticleTally tally() override { return s_.tally(); }
  void sample_fluid(std::span<const Vec3d> points, std::span<ShepardValue> values) override {
    s_.sample_fluid(points, values);
  }
  void set_clock(double time, std::int64_t steps, double dt_floor) override {
    s_.set_clock(time, steps, dt_floor);
  }
  void set_profiling(bool on) override { s_.set_profiling(on); }
  DevicePhaseTimes phase_times() const override { return s_.phase_times(); }

 private:
  DeviceStepper<Exec> s_;
};

}  // namespace netsph
