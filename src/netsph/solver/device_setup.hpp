#pragma once
// From a case to the device-shaped step (backend/device/): the constants it needs, and the
// run on the host executor or on the CUDA device.
#include <memory>

#include "netsph/backend/device/device_run.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/solver/scene.hpp"

namespace netsph {

/// The device step's constants for a case whose scene is `scene` (the case with its nets'
/// knots as bodies: spec_with_net_knots). Probes are ignored: a device run writes no outputs
/// yet (the caller downloads the particles).
DeviceSetup device_setup(const CaseSpec& spec, const Scene& scene);

enum class DeviceExecutor { Host, Cuda };

/// Builds the case's scene and a device run of it. Throws netsph::Error for
/// DeviceExecutor::Cuda when netsph was built without CUDA or finds no device.
std::unique_ptr<DeviceRun> make_device_run(const CaseSpec& spec, DeviceExecutor exec);

}  // namespace netsph
