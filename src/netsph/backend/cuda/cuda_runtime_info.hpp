#pragma once
// What the CUDA runtime reports about GPUs. Compiled only when nvcc is found; callers check
// NETSPH_HAVE_CUDA. Any error from cudaGetDeviceCount (for instance "driver insufficient" on
// a machine without a GPU) means "no usable GPU", never a failure.
#include <string>

namespace netsph::cuda {

struct RuntimeInfo {
  int devices = 0;
  std::string name;   ///< name of device 0
  std::string error;  ///< why no device is usable, when devices == 0
};

RuntimeInfo runtime_info();

/// Evaluates the shared kernel and pair formulas on the GPU for a few distances and compares
/// them with the host results; returns the largest relative difference (or -1 without GPU).
/// It proves that sph/ compiles and agrees on the device before the full backend exists.
double formula_parity_check();

}  // namespace netsph::cuda
