#pragma once
// Marks functions that both backends call: plain inline functions on the CPU, __host__
// __device__ under nvcc. Every physical formula in sph/ and net/ is written once with it.
#if defined(__CUDACC__)
#define NETSPH_HD __host__ __device__ __forceinline__
#else
#define NETSPH_HD inline
#endif

// A lambda the compiler must inline: GCC does not always inline a large lambda called from
// two places, and then its captures go through memory (nvcc inlines device lambdas itself).
#if defined(__CUDACC__)
#define NETSPH_INLINE_LAMBDA
#else
#define NETSPH_INLINE_LAMBDA __attribute__((always_inline))
#endif

/// Whether `p` holds on any thread of the GPU warp that reaches this call together with the
/// caller (on the CPU, one thread: `p` itself). Lets every thread of a warp take a branch when
/// one needs it, so that they run its body together instead of one after another
/// (device_rates_particle's batches).
NETSPH_HD bool any_lane(bool p) {
#if defined(__CUDA_ARCH__)
  return __any_sync(__activemask(), p);
#else
  return p;
#endif
}
