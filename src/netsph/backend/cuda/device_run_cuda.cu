// The device-shaped step on the first CUDA device: the DeviceStepper template of
// backend/device instantiated with the CUDA executor.
#include "netsph/backend/cuda/cuda_exec.cuh"
#include "netsph/backend/cuda/cuda_runtime_info.hpp"
#include "netsph/backend/device/device_run_on.hpp"

namespace netsph {

/// The step compiled with --use_fast_math (device_run_cuda_fast.cu).
std::unique_ptr<DeviceRun> make_cuda_fast_math_device_run(DeviceSetup setup, const ParticleSet& p);

std::unique_ptr<DeviceRun> make_cuda_device_run(DeviceSetup setup, const ParticleSet& p) {
  const cuda::RuntimeInfo info = cuda::runtime_info();
  if (info.devices == 0)
    throw Error("--backend cuda", "no usable CUDA device (" + info.error + "); use --backend cpu");
  if (setup.cuda_fast_math) return make_cuda_fast_math_device_run(std::move(setup), p);
  return std::make_unique<DeviceRunOn<CudaExec>>(std::move(setup), p);
}

}  // namespace netsph
