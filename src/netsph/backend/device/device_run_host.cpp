#include "netsph/backend/device/device_run_on.hpp"
#include "netsph/backend/device/host_exec.hpp"

namespace netsph {

std::unique_ptr<DeviceRun> make_host_device_run(DeviceSetup setup, const ParticleSet& p) {
  return std::make_unique<DeviceRunOn<HostExec>>(std::move(setup), p);
}

}  // namespace netsph
