#pragma once
// From a case to the device-shaped step (backend/device/): the constants it needs. Simulation
// (simulation_device.cpp) adds the hooks into its bodies and walls and starts the run.
#include "netsph/backend/device/device_run.hpp"
#include "netsph/case/case_spec.hpp"
#include "netsph/setup/scene.hpp"

namespace netsph {

/// The device step's constants for a case whose scene is `scene` (the case with its nets'
/// knots as bodies: spec_with_net_knots), without the hooks.
DeviceSetup device_setup(const CaseSpec& spec, const Scene& scene);

}  // namespace netsph
