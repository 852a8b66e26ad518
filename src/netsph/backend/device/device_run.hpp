#pragma once
// A device-shaped run behind a plain interface, so that code compiled by the host compiler
// (Simulation, solver/simulation_device.cpp) drives the CUDA instantiation without seeing
// CUDA, and without parsing the device step's template (DeviceStepper, ~1,800 lines): only the
// executors' sources instantiate it, through device_run_on.hpp.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "netsph/backend/device/device_step_setup.hpp"
#include "netsph/backend/device/phase_profile.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/sph/particle_set.hpp"
#include "netsph/sph/particle_tally.hpp"
#include "netsph/sph/shepard.hpp"

namespace netsph {

class DeviceRun {
 public:
  virtual ~DeviceRun() = default;
  virtual DeviceStepReport step() = 0;
  /// The particles as of the last step (sorted by cell).
  virtual void download(ParticleSet& p) const = 0;
  virtual double time() const = 0;
  virtual std::int64_t steps() const = 0;
  virtual std::size_t size() const = 0;
  virtual double bytes_per_particle() const = 0;
  virtual void download_cell_begin(std::vector<std::uint32_t>& begin) const = 0;
  /// The measures of the particles as of the last step (sph/particle_tally.hpp), reduced on
  /// the device.
  virtual ParticleTally tally() = 0;
  /// The fluid at `points` as of the last step (Shepard-corrected, as the CPU's probes),
  /// sampled on the device.
  virtual void sample_fluid(std::span<const Vec3d> points, std::span<ShepardValue> values) = 0;
  virtual void set_clock(double time, std::int64_t steps, double dt_floor) = 0;
  /// The phase profile (phase_profile.hpp): on restarts its sums.
  virtual void set_profiling(bool on) = 0;
  virtual DevicePhaseTimes phase_times() const = 0;
};

/// The device step's logic on the host (backend/device/device_run_host.cpp).
std::unique_ptr<DeviceRun> make_host_device_run(DeviceSetup setup, const ParticleSet& p);

#if defined(NETSPH_HAVE_CUDA)
/// On the first CUDA device (backend/cuda/device_run_cuda.cu). Throws netsph::Error when
/// there is no usable device.
std::unique_ptr<DeviceRun> make_cuda_device_run(DeviceSetup setup, const ParticleSet& p);
#endif

}  // namespace netsph
