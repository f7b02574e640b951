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
