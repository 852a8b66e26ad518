#pragma once
// Marks functions that both backends call: plain inline functions on the CPU, __host__
// __device__ under nvcc. Every physical formula in sph/ and net/ is written once with it.
#if defined(__CUDACC__)
#define NETSPH_HD __host__ __device__ __forceinline__
#else
#define NETSPH_HD inline
#endif
