// The CPU and GPU backends draw the same random numbers: the path sampler evaluated in a CUDA kernel equals the
// host's, bit for bit, for both kinds.
#include <gtest/gtest.h>

#include <cstring>

#include "sampler_kernel.h"

namespace candela::test {
namespace {

TEST(GpuPathSampler, DrawsTheHostsNumbers) {
  const uint32_t count = 1u << 14;
  for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent})
    for (uint32_t pixel : {0u, 4097u, 2073599u}) {
      std::vector<float> device = drawPathSamplesOnDevice(kind, pixel, 11, count);
      size_t differing = 0;
      for (uint32_t i = 0; i < count; ++i) {
        PathSampler sampler(pixel, i, 11, kind);
        float host[6];
        host[0] = sampler.next1D();
        Vec2 a = sampler.next2D();
        host[1] = a.x;
        host[2] = a.y;
        host[3] = sampler.next1D();
        Vec2 b = sampler.next2D();
        host[4] = b.x;
        host[5] = b.y;
        differing += std::memcmp(host, &device[6 * size_t(i)], sizeof host) != 0;
      }
      EXPECT_EQ(differing, 0u) << (kind == SamplerKind::Sobol ? "sobol" : "independent") << ", pixel " << pixel;
    }
}

}  // namespace
}  // namespace candela::test
