#pragma once
// The host executor of the device-shaped step (device_stepper.hpp): buffers are std::vectors,
// for_each an OpenMP loop, the sort a stable sort by key. It runs the device kernels' logic on
// the CPU, so that tests check it against the CPU backend where there is no GPU; it is not a
// fast path (the CPU backend is: backend/cpu/).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "netsph/core/real.hpp"

namespace netsph {

struct HostExec {
  template <class T>
  using Buffer = std::vector<T>;

  template <class F>
  static void for_each(std::size_t n, F f) {
    const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::uint32_t>(i));
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
    b.assign(src, src + n);
  }
  template <class T>
  static void download(T* dst, const Buffer<T>& b, std::size_t n) {
    std::copy(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n), dst);
  }
};

}  // namespace netsph
