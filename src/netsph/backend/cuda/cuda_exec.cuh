#pragma once
// The CUDA executor of the device-shaped step (backend/device/device_stepper.hpp): device
// buffers, one thread per particle, CUB's radix sort and reductions. Every call runs on the
// default stream in order; the reductions copy their result back and so synchronise.
#include <cuda_runtime.h>

#include <cub/block/block_reduce.cuh>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "netsph/core/error.hpp"

namespace netsph {

inline void cuda_check(cudaError_t err, const char* what) {
  if (err != cudaSuccess) throw Error("cuda", std::string(what) + ": " + cudaGetErrorString(err));
}

/// Threads per block of every launch.
inline constexpr unsigned kCudaBlock = 256;

template <class F>
__global__ void for_each_kernel(std::uint32_t n, F f) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

/// for_each_kernel compiled to keep MinBlocks blocks resident on a multiprocessor: the
/// compiler caps its registers at 65536 / (kCudaBlock * MinBlocks), spilling if it must.
template <unsigned MinBlocks, class F>
__global__ void __launch_bounds__(kCudaBlock, MinBlocks)
    for_each_bounded_kernel(std::uint32_t n, F f) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

// A template, so that a second .cu including this header does not define it twice.
template <class Key>
__global__ void count_below_kernel(const Key* keys, std::uint32_t n, Key bound,
                                   std::uint32_t* out) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n && keys[i] < bound && (i + 1 == n || keys[i + 1] >= bound)) *out = i + 1;
}

/// The most blocks CudaExec::reduce launches (fewer for fewer particles): about one and a half
/// waves of an H100's 132 multiprocessors at the tally's 44 registers (5 blocks each), few
/// enough that their partial results cost nothing to copy back and combine on the host.
inline constexpr unsigned kReduceBlocks = 1024;

/// partial[block] = the block's combine of map(i) over its threads' strided share of [0, n).
template <class T, class Map, class Combine>
__global__ void reduce_kernel(std::uint32_t n, T identity, Map map, Combine combine, T* partial) {
  using BlockReduce = cub::BlockReduce<T, kCudaBlock>;
  __shared__ typename BlockReduce::TempStorage temp;
  T acc = identity;
  const std::uint32_t stride = gridDim.x * blockDim.x;
  for (std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += stride)
    acc = combine(acc, map(i));
  const T block = BlockReduce(temp).Reduce(acc, combine);
  if (threadIdx.x == 0) partial[blockIdx.x] = block;
}

/// max(a, b) with NaN as the identity, as HostExec::max_of: CUB's own maximum keeps a NaN that
/// comes first, which would then depend on where it falls in the reduction tree.
struct MaxSkippingNan {
  template <class T>
  __host__ __device__ T operator()(const T& a, const T& b) const {
    if (!(a == a)) return b;
    if (!(b == b)) return a;
    return a < b ? b : a;
  }
};

/// NETSPH_CUDA_SYNC=1 waits for every kernel and checks it, so that a fault is reported by the
/// launch that caused it (for bringing the backend up on a new machine; slow).
inline bool sync_each_launch() {
  static const bool on = [] {
    const char* v = std::getenv("NETSPH_CUDA_SYNC");
    return v != nullptr && v[0] == '1';
  }();
  return on;
}

/// A device array with the part of std::vector's interface the step uses.
template <class T>
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  ~DeviceBuffer() { cudaFree(p_); }
  /// Grows by half again at least, so that particles created a few at a time do not
  /// reallocate every step; keeps the contents.
  void resize(std::size_t n) {
    if (n > cap_) {
      const std::size_t cap = size_ > 0 && n < cap_ + cap_ / 2 ? cap_ + cap_ / 2 : n;
      T* q = nullptr;
      cuda_check(cudaMalloc(&q, cap * sizeof(T)), "cudaMalloc");
      if (size_ > 0)
        cuda_check(cudaMemcpy(q, p_, size_ * sizeof(T), cudaMemcpyDeviceToDevice), "resize");
      cudaFree(p_);
      p_ = q, cap_ = cap;
    }
    size_ = n;
  }
  void swap(DeviceBuffer& o) noexcept {
    std::swap(p_, o.p_), std::swap(size_, o.size_), std::swap(cap_, o.cap_);
  }
  T* data() { return p_; }
  const T* data() const { return p_; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return cap_; }

 private:
  T* p_ = nullptr;
  std::size_t size_ = 0, cap_ = 0;
};

struct CudaExec {
  template <class T>
  using Buffer = DeviceBuffer<T>;
  static constexpr unsigned kBlock = kCudaBlock;

  template <class F>
  static void for_each(std::size_t n, F f) {
    if (n == 0) return;
    const auto blocks = static_cast<unsigned>((n + kBlock - 1) / kBlock);
    for_each_kernel<<<blocks, kBlock>>>(static_cast<std::uint32_t>(n), f);
    checked_launch();
  }

  /// for_each with at most 65536 / (256 MinBlocks) registers a thread, so that MinBlocks
  /// blocks fit on a multiprocessor (more threads to hide memory latency, perhaps spills).
  template <unsigned MinBlocks, class F>
  static void for_each_occupying(std::size_t n, F f) {
    if (n == 0) return;
    const auto blocks = static_cast<unsigned>((n + kBlock - 1) / kBlock);
    for_each_bounded_kernel<MinBlocks><<<blocks, kBlock>>>(static_cast<std::uint32_t>(n), f);
    checked_launch();
  }

  static void checked_launch() {
    cuda_check(cudaGetLastError(), "kernel launch");
    if (sync_each_launch()) cuda_check(cudaDeviceSynchronize(), "kernel (NETSPH_CUDA_SYNC)");
  }

  /// Resizes a buffer whose contents are not needed any more: the old storage is freed first
  /// and nothing is copied (DeviceBuffer::resize keeps the contents).
  template <class T>
  static void resize_discarding(DeviceBuffer<T>& b, std::size_t n) {
    if (n > b.capacity()) DeviceBuffer<T>().swap(b);
    b.resize(n);
  }

  static DeviceBuffer<unsigned char>& temp(std::size_t bytes) {
    static DeviceBuffer<unsigned char> t;
    t.resize(bytes > 0 ? bytes : 1);
    return t;
  }

  /// Radix sort of (key, value) pairs with double buffers (O(P) temporary storage instead
  /// of O(n)); returns whether the sorted pairs ended in the _alt buffers.
  static bool sort_pairs(std::uint32_t* keys, std::uint32_t* keys_alt, std::uint32_t* vals,
                         std::uint32_t* vals_alt, std::size_t n, int key_bits) {
    if (n == 0) return false;
    cub::DoubleBuffer<std::uint32_t> k(keys, keys_alt), v(vals, vals_alt);
    std::size_t bytes = 0;
    const int count = static_cast<int>(n);
    cuda_check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, k, v, count, 0, key_bits),
               "radix sort (size)");
    cuda_check(cub::DeviceRadixSort::SortPairs(temp(bytes).data(), bytes, k, v, count, 0, key_bits),
               "radix sort");
    if ((k.Current() == keys_alt) != (v.Current() == vals_alt))
      throw Error("cuda", "radix sort left keys and values in different buffers");
    return k.Current() == keys_alt;
  }

  template <class T>
  static T max_of(const T* x, std::size_t n) {
    if (n == 0) return T(0);
    static DeviceBuffer<T> out;
    out.resize(1);
    std::size_t bytes = 0;
    const int count = static_cast<int>(n);
    const MaxSkippingNan op;
    cuda_check(cub::DeviceReduce::Reduce(nullptr, bytes, x, out.data(), count, op, T(0)),
               "max (size)");
    cuda_check(cub::DeviceReduce::Reduce(temp(bytes).data(), bytes, x, out.data(), count, op, T(0)),
               "max");
    T h{};
    cuda_check(cudaMemcpy(&h, out.data(), sizeof(T), cudaMemcpyDeviceToHost), "max (copy)");
    return h > T(0) ? h : T(0);
  }

  /// The combine of map(i) over [0, n) and identity (HostExec::reduce's, grouped by blocks:
  /// combine must be associative; it runs on the device and on the host, map on the device).
  template <class T, class Map, class Combine>
  static T reduce(std::size_t n, T identity, Map map, Combine combine) {
    if (n == 0) return identity;
    const auto blocks =
        static_cast<unsigned>(std::min<std::size_t>((n + kBlock - 1) / kBlock, kReduceBlocks));
    static DeviceBuffer<T> partial;
    partial.resize(blocks);
    reduce_kernel<<<blocks, kBlock>>>(static_cast<std::uint32_t>(n), identity, map, combine,
                                      partial.data());
    checked_launch();
    std::vector<T> h(blocks);
    cuda_check(cudaMemcpy(h.data(), partial.data(), blocks * sizeof(T), cudaMemcpyDeviceToHost),
               "reduce (copy)");
    T acc = identity;
    for (const T& x : h) acc = combine(acc, x);
    return acc;
  }

  /// out[i] = in[0] + ... + in[i - 1] (in may be out: CUB scans in place); returns the sum of
  /// all.
  static std::size_t exclusive_scan(const std::uint32_t* in, std::uint32_t* out, std::size_t n) {
    if (n == 0) return 0;
    std::size_t bytes = 0;
    const int count = static_cast<int>(n);
    std::uint32_t last_in = 0, last_out = 0;  // the last input before an in-place scan
    cuda_check(cudaMemcpy(&last_in, in + n - 1, sizeof(last_in), cudaMemcpyDeviceToHost), "scan");
    cuda_check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, in, out, count), "scan (size)");
    cuda_check(cub::DeviceScan::ExclusiveSum(temp(bytes).data(), bytes, in, out, count), "scan");
    cuda_check(cudaMemcpy(&last_out, out + n - 1, sizeof(last_out), cudaMemcpyDeviceToHost),
               "scan");
    return static_cast<std::size_t>(last_in) + last_out;
  }

  /// Waits for the device (the phase profile's clock). It does not throw: it runs in
  /// destructors, and an error of the device is sticky, so the step's next checked call
  /// reports it.
  static void synchronize() { static_cast<void>(cudaDeviceSynchronize()); }

  __device__ static void atomic_add(double* p, double v) { atomicAdd(p, v); }

  static std::size_t count_below(const std::uint32_t* keys, std::size_t n, std::uint32_t bound) {
    static DeviceBuffer<std::uint32_t> out;
    out.resize(1);
    cuda_check(cudaMemset(out.data(), 0, sizeof(std::uint32_t)), "count (reset)");
    if (n > 0) {
      const auto blocks = static_cast<unsigned>((n + kBlock - 1) / kBlock);
      count_below_kernel<std::uint32_t>
          <<<blocks, kBlock>>>(keys, static_cast<std::uint32_t>(n), bound, out.data());
      cuda_check(cudaGetLastError(), "count launch");
    }
    std::uint32_t h = 0;
    cuda_check(cudaMemcpy(&h, out.data(), sizeof(h), cudaMemcpyDeviceToHost), "count (copy)");
    return h;
  }

  template <class T>
  static void upload(DeviceBuffer<T>& b, const T* src, std::size_t n) {
    b.resize(n);
    if (n > 0)
      cuda_check(cudaMemcpy(b.data(), src, n * sizeof(T), cudaMemcpyHostToDevice), "upload");
  }
  template <class T>
  static void download(T* dst, const DeviceBuffer<T>& b, std::size_t n) {
    if (n > 0)
      cuda_check(cudaMemcpy(dst, b.data(), n * sizeof(T), cudaMemcpyDeviceToHost), "download");
  }
};

}  // namespace netsph
