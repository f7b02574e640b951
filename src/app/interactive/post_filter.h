#pragma once
#include "app/interactive/post_settings.h"
#include "image/image.h"

namespace candela {

// The accumulated (perhaps denoised) image as the front ends show it before tone mapping: through the bilateral
// filter when it is on, which keeps `emission` (the part of the image the camera sees emitted,
// Backend::readEmission) out of its sums and adds it back after, unless `emission` is empty (not recorded). The
// viewer's GLSL pass (app/viewer/display_shaders.h) computes the same on the GPU.
Image postFiltered(const Image& accumulated, const Image& emission, const PostSettings& post);

}  // namespace candela
