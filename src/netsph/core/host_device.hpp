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
