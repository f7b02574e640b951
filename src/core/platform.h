#pragma once
// One qualifier makes kernel code callable on the host and, under nvcc, on the device.
#if defined(__CUDACC__)
#define CANDELA_HD __host__ __device__
#define CANDELA_INLINE __forceinline__
#else
#define CANDELA_HD
#define CANDELA_INLINE inline
#endif

#define CANDELA_FN CANDELA_HD CANDELA_INLINE

// Inlined on the host too, where the compiler would otherwise weigh it: for a function whose only job is to give a
// loop one source for two callers, so that each caller compiles as if the loop were written in it.
#if defined(__CUDACC__)
#define CANDELA_FN_ALWAYS_INLINE CANDELA_HD __forceinline__
#else
#define CANDELA_FN_ALWAYS_INLINE inline __attribute__((always_inline))
#endif

// Called rather than inlined on the device (inlined on the host, as CANDELA_FN): for a function that one GPU program
// calls from many places. Inlined, each place held a copy of it, which multiplied the program's code and the compile
// that a machine's first start waits for (docs/performance.md, 'The first start').
#if defined(__CUDA_ARCH__)
#define CANDELA_FN_CALLED CANDELA_HD inline __noinline__
#else
#define CANDELA_FN_CALLED CANDELA_FN
#endif
