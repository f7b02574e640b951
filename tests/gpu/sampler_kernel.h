#pragma once
// The path sampler's numbers drawn on the GPU, for comparison with the host's.
#include <vector>

#include "core/path_sampler.h"

namespace candela::test {

// For every sample index in [0, count): next1D, next2D, next1D, next2D of PathSampler(pixel, index, seed, kind),
// six numbers per index, in one kernel launch.
std::vector<float> drawPathSamplesOnDevice(SamplerKind kind, uint32_t pixel, uint32_t seed, uint32_t count);

}  // namespace candela::test
