// The device-shaped step on the first CUDA device: the DeviceStepper template of
// backend/device instantiated with the CUDA executor.
#include "netsph/backend/cuda/cuda_exec.cuh"
#include "netsph/backend/cuda/cuda_runtime_info.hpp"
#include "netsph/backend/device/device_run.hpp"

namespace netsph {

std::unique_ptr<DeviceRun> make_cuda_device_run(DeviceSetup setup, const ParticleSet& p) {
  const cuda::RuntimeInfo info = cuda::runtime_info();
  if (info.devices == 0)
    throw Error("--backend cuda", "no usable CUDA device (" + info.error + "); use --backend cpu");
  return std::make_unique<DeviceRunOn<CudaExec>>(std::move(setup), p);
}

}  // namespace netsph
