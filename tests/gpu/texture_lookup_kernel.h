#pragma once
// sampleTexture (kernel/texture.h) evaluated on the GPU, for comparison with the host's lookups.
#include <vector>

#include "kernel/texture.h"

namespace candela::test {

// Looks texture `index` of `deviceArrays` (device pointers) up at every uv in one kernel launch.
std::vector<Vec4> sampleTextureOnDevice(const TexelArrays& deviceArrays, int32_t index, const std::vector<Vec2>& uvs);

}  // namespace candela::test
