#pragma once
// The host executor of the device-shaped step (device_stepper.hpp): buffers on the heap,
// for_each an OpenMP loop, the sort a stable sort by key. It runs the device kernels' logic on
// the CPU, so that tests check it against the CPU backend where there is no GPU; it is not a
// fast path (the CPU backend is: backend/cpu/).
//
// It also plays a GPU's part where the host would hide a fault: new buffer storage is filled
// with 0xFF bytes (NaN for floats, huge for integers), as memory from cudaMalloc holds
// whatever was there, so a kernel that reads what nobody wrote goes wrong here too; and with
// NETSPH_HOST_EXEC_ORDER=reverse or shuffle every launch visits its indices serially in that
// order, so a kernel whose result depends on the order of its threads (one particle reading
// what another writes in the same launch) differs (tests/physics/device_parity_test.cpp).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <random>
#include <string_view>
#include <vector>

#include "netsph/core/real.hpp"

namespace netsph {

/// A device-like array on the host: the part of std::vector's interface the step uses; growth
/// keeps the contents and fills the new storage with 0xFF bytes.
template <class T>
class HostBuffer {
 public:
  void resize(std::size_t n) {
    if (n > v_.size()) {
      const std::size_t old = v_.size();
      v_.resize(n);
      std::memset(static_cast<void*>(v_.data() + old), 0xFF, (n - old) * sizeof(T));
    } else {
      v_.resize(n);
    }
  }
  T* data() { return v_.data(); }
  const T* data() const { return v_.data(); }
  std::size_t size() const { return v_.size(); }
  std::size_t capacity() const { return v_.capacity(); }

 private:
  std::vector<T> v_;
};

/// The order of a launch's indices: 0 forward (in parallel), 1 reverse, 2 shuffled.
inline int host_exec_order() {
  const char* v = std::getenv("NETSPH_HOST_EXEC_ORDER");
  if (v == nullptr) return 0;
  const std::string_view s(v);
  return s == "reverse" ? 1 : s == "shuffle" ? 2 : 0;
}

struct HostExec {
  template <class T>
  using Buffer = HostBuffer<T>;

  template <class F>
  static void for_each(std::size_t n, F f) {
    const int order = host_exec_order();
    if (order == 1) {
      for (std::size_t i = n; i-- > 0;) f(static_cast<std::uint32_t>(i));
      return;
    }
    if (order == 2) {
      std::vector<std::uint32_t> idx(n);
      std::iota(idx.begin(), idx.end(), 0u);
      static std::mt19937 rng(20261202);
      std::shuffle(idx.begin(), idx.end(), rng);
      for (const std::uint32_t i : idx) f(i);
      return;
    }
    const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::uint32_t>(i));
  }

  /// CudaExec's launch with a register cap; the host has none.
  template <unsigned MinBlocks, class F>
  static void for_each_occupying(std::size_t n, F f) {
    for_each(n, f);
  }

  /// Stable sort of (key, value) pairs by key, as cub::DeviceRadixSort::SortPairs with
  /// double buffers: returns whether the sorted pairs are in the _alt buffers. Like an LSD
  /// radix sort of 8-bit digits, they are there after an odd number of passes, so that tests
  /// on the host take both of the caller's paths.
  static bool sort_pairs(std::uint32_t* keys, std::uint32_t* keys_alt, std::uint32_t* vals,
                         std::uint32_t* vals_alt, std::size_t n, int key_bits) {
    std::vector<std::uint32_t> idx(n);
    std::iota(idx.begin(), idx.end(), 0u);
    std::stable_sort(idx.begin(), idx.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    for (std::size_t i = 0; i < n; ++i) keys_alt[i] = keys[idx[i]], vals_alt[i] = vals[idx[i]];
    const bool odd_passes = ((key_bits + 7) / 8) % 2 == 1;
    if (!odd_passes) {
      std::copy(keys_alt, keys_alt + n, keys);
      std::copy(vals_alt, vals_alt + n, vals);
    }
    return odd_passes;
  }

  /// The largest of x[0..n) and 0; NaNs are passed over (as CudaExec's).
  template <class T>
  static T max_of(const T* x, std::size_t n) {
    T m = 0;
    for (std::size_t i = 0; i < n; ++i) m = x[i] > m ? x[i] : m;
    return m;
  }

  /// combine(...combine(combine(identity, map(0)), map(1))..., map(n - 1)): one pass in
  /// order (CudaExec's groups the terms by blocks; combine must be associative).
  template <class T, class Map, class Combine>
  static T reduce(std::size_t n, T identity, Map map, Combine combine) {
    T acc = identity;
    for (std::size_t i = 0; i < n; ++i) acc = combine(acc, map(static_cast<std::uint32_t>(i)));
    return acc;
  }

  /// Every call has finished when it returns.
  static void synchronize() {}

  static void atomic_add(double* p, double v) {
#pragma omp atomic
    *p += v;
  }

  /// Resizes a buffer whose contents are not needed any more.
  template <class T>
  static void resize_discarding(Buffer<T>& b, std::size_t n) {
    b.resize(n);
  }

  /// out[i] = in[0] + ... + in[i - 1] (in may be out); returns the sum of all.
  static std::size_t exclusive_scan(const std::uint32_t* in, std::uint32_t* out, std::size_t n) {
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t v = in[i];
      out[i] = sum;
      sum += v;
    }
    return sum;
  }

  /// How many of the sorted keys are below `bound`.
  static std::size_t count_below(const std::uint32_t* keys, std::size_t n, std::uint32_t bound) {
    return static_cast<std::size_t>(std::lower_bound(keys, keys + n, bound) - keys);
  }

  template <class T>
  static void upload(Buffer<T>& b, const T* src, std::size_t n) {
    b.resize(n);
    if (n > 0) std::memcpy(static_cast<void*>(b.data()), src, n * sizeof(T));
  }
  template <class T>
  static void download(T* dst, const Buffer<T>& b, std::size_t n) {
    if (n > 0) std::memcpy(static_cast<void*>(dst), b.data(), n * sizeof(T));
  }
};

}  // namespace netsph
