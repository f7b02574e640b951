// Texture filtering on the GPU: the OptiX backend reads the same mip pyramid through CUDA mipmapped arrays
// (trilinear with tex2DLod, anisotropic with tex2DGrad), so its renders of the receding checkerboard match the
// CPU's, and its 1-sample image aliases as little.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gpu_render.h"
#include "support/checkerboard_scene.h"

namespace candela {
namespace {

RenderSettings planeSettings(TextureFilter filter, uint32_t seed) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.maxDepth = 1;
  settings.seed = seed;
  settings.textureFilter = filter;
  return settings;
}

template <class BackendType>
Image render(const Scene& scene, TextureFilter filter, uint32_t seed, uint32_t spp) {
  auto backend = test::makeBackend<BackendType>(scene, planeSettings(filter, seed));
  backend->render(spp);
  return backend->readImage();
}

// Same seed, same camera rays on both backends: the images differ only by the texture unit's arithmetic (its
// 8-bit bilinear weights and its own level and anisotropy choices), a few hundredths at most per pixel on average.
TEST(TextureFilteringGpu, CheckerboardMatchesTheCpu) {
  const Scene scene = test::recedingTexturedPlane(test::checkerboardTexture(256, 16));
  for (TextureFilter filter : {TextureFilter::Finest, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    const Image gpu = render<OptixBackend>(scene, filter, 1, 1);
    const Image cpu = render<CpuBackend>(scene, filter, 1, 1);
    const double rms = std::sqrt(test::meanSquaredDifference(gpu, cpu));
    std::printf("filter %d: GPU against CPU, rms difference %.4f\n", int(filter), rms);
    EXPECT_LT(rms, filter == TextureFilter::Anisotropic ? 0.05 : 0.02) << int(filter);
  }
}

// As TextureFilteringRender.RecedingCheckerboardAliasesFarLess and ConesGoOnThroughMirrors on the CPU, with the
// same bounds: the texture unit's filtering reduces aliasing as much as the host's.
TEST(TextureFilteringGpu, RecedingCheckerboardAliasesFarLess) {
  const Scene scene = test::recedingTexturedPlane(test::checkerboardTexture(256, 16));
  const Image reference = render<OptixBackend>(scene, TextureFilter::Finest, 100, 1024);
  double whole[3], far[3];
  for (TextureFilter filter : {TextureFilter::Finest, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    const Image image = render<OptixBackend>(scene, filter, 1, 1);
    whole[int(filter)] = test::meanSquaredDifference(image, reference);
    far[int(filter)] = test::meanSquaredDifference(image, reference, test::kFarPlaneFirstRow, test::kFarPlaneRows);
    std::printf("GPU filter %d, mean squared error at 1 spp: whole image %.5f, far rows %.5f\n", int(filter),
                whole[int(filter)], far[int(filter)]);
    if (filter == TextureFilter::Anisotropic) {
      EXPECT_NEAR(test::meanLuminance(image), test::meanLuminance(reference), 0.01 * test::meanLuminance(reference));
    }
  }
  for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    EXPECT_LT(whole[int(filter)], whole[int(TextureFilter::Finest)] / 4) << int(filter);
    EXPECT_LT(far[int(filter)], far[int(TextureFilter::Finest)] / 15) << int(filter);
  }
}

TEST(TextureFilteringGpu, ConesGoOnThroughMirrors) {
  const Scene scene = test::mirroredTexturedCeiling(test::checkerboardTexture(256, 16));
  RenderSettings settings = planeSettings(TextureFilter::Finest, 100);
  settings.maxDepth = 2;
  auto renderMirror = [&](uint32_t spp) {
    auto backend = test::makeBackend<OptixBackend>(scene, settings);
    backend->render(spp);
    return backend->readImage();
  };
  const Image reference = renderMirror(1024);
  double mirrored[3];
  for (TextureFilter filter : {TextureFilter::Finest, TextureFilter::Anisotropic}) {
    settings.textureFilter = filter;
    settings.seed = 1;
    mirrored[int(filter)] = test::meanSquaredDifference(renderMirror(1), reference, 60, 60);
    std::printf("GPU filter %d, mean squared error at 1 spp below the horizon: %.5f\n", int(filter),
                mirrored[int(filter)]);
  }
  EXPECT_LT(mirrored[int(TextureFilter::Anisotropic)], mirrored[int(TextureFilter::Finest)] / 4);
}

}  // namespace
}  // namespace candela
