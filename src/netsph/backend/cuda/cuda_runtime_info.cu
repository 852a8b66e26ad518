#include <cuda_runtime.h>

#include <cmath>
#include <vector>

#include "netsph/backend/cuda/cuda_runtime_info.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph::cuda {

RuntimeInfo runtime_info() {
  RuntimeInfo info;
  int n = 0;
  const cudaError_t err = cudaGetDeviceCount(&n);
  if (err != cudaSuccess) {
    info.error = cudaGetErrorString(err);
    return info;
  }
  if (n == 0) {
    info.error = "no CUDA device";
    return info;
  }
  cudaDeviceProp prop{};
  if (cudaGetDeviceProperties(&prop, 0) == cudaSuccess) info.name = prop.name;
  info.devices = n;
  return info;
}

namespace {
__global__ void kernel_values(KernelScale s, const float* r, float* w, float* f, int n) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) {
    w[i] = kernel_value<WendlandC2>(s, r[i]);
    f[i] = kernel_grad_factor<WendlandC2>(s, r[i]);
  }
}
}  // namespace

double formula_parity_check() {
  if (runtime_info().devices == 0) return -1;
  const int n = 64;
  const KernelScale s = make_kernel_scale<WendlandC2>(3, 0.01);
  std::vector<float> r(n), w(n), f(n);
  for (int i = 0; i < n; ++i) r[i] = 0.02f * static_cast<float>(i) / n;
  float *dr = nullptr, *dw = nullptr, *df = nullptr;
  cudaMalloc(&dr, n * sizeof(float));
  cudaMalloc(&dw, n * sizeof(float));
  cudaMalloc(&df, n * sizeof(float));
  cudaMemcpy(dr, r.data(), n * sizeof(float), cudaMemcpyHostToDevice);
  kernel_values<<<1, n>>>(s, dr, dw, df, n);
  cudaMemcpy(w.data(), dw, n * sizeof(float), cudaMemcpyDeviceToHost);
  cudaMemcpy(f.data(), df, n * sizeof(float), cudaMemcpyDeviceToHost);
  cudaFree(dr), cudaFree(dw), cudaFree(df);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const double hw = kernel_value<WendlandC2>(s, r[i]),
                 hf = kernel_grad_factor<WendlandC2>(s, r[i]);
    worst = std::fmax(worst, std::fabs(w[i] - hw) / (std::fabs(hw) + 1e-30));
    worst = std::fmax(worst, std::fabs(f[i] - hf) / (std::fabs(hf) + 1e-30));
  }
  return worst;
}

}  // namespace netsph::cuda
