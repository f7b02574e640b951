// CPU and GPU renders of the scenes that exercise the other material models, textures, normal maps and
// environment maps must agree (see expectRendersAgree): the GPU runs the same kernel on its own traversal.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/scene_loading.h"
#include "gpu_render.h"
#include "render_comparison.h"
#include "support/cutout_screen.h"

namespace candela {
namespace {

constexpr uint32_t kSize = 64;
constexpr uint32_t kBatches = 32;
constexpr uint32_t kSamplesPerBatch = 32;
constexpr uint32_t kBlock = 4;
constexpr double kAlpha = 0.01;

void expectBackendsAgree(const Scene& scene, uint32_t seed) {
  test::PixelStatistics cpu = test::batchStatistics<CpuBackend>(scene, test::squareImage(kSize, seed), kBatches,
                                                                kSamplesPerBatch);
  test::PixelStatistics gpu = test::batchStatistics<OptixBackend>(scene, test::squareImage(kSize, seed + 1),
                                                                  kBatches, kSamplesPerBatch);
  test::expectRendersAgree(cpu, gpu, kBlock, kBatches, kAlpha);
}

// Disney BSDF rows (metallic, sheen, clearcoat, subsurface, transmission) and a diffuse floor and wall.
TEST(GpuMaterialGallery, AgreesWithTheCpuBackend) { expectBackendsAgree(makeMaterialGallery(), 41); }

// Mirrors: delta lobes, paths that reach the light only by reflection.
TEST(GpuMirrorCorridor, AgreesWithTheCpuBackend) { expectBackendsAgree(makeMirrorCorridor(), 51); }

// Cut-outs (support/cutout_screen.h): an alpha-tested checker or alpha blending, and culled back faces, in
// one mesh with an opaque floor; shadow and bounce rays cross them.
TEST(GpuCutoutScreen, AgreesWithTheCpuBackend) {
  expectBackendsAgree(test::makeCutoutScreen(test::ScreenCoverage::CheckerMask), 71);
  expectBackendsAgree(test::makeCutoutScreen(test::ScreenCoverage::HalfBlend), 81);
}

// Textured glTF materials with a normal map, lit by an importance-sampled environment map.
TEST(GpuDamagedHelmet, AgreesWithTheCpuBackendUnderAnEnvironmentMap) {
  std::filesystem::path shared = CANDELA_SHARED_SCENES;
  std::filesystem::path model = shared / "damaged_helmet/glTF-Binary/DamagedHelmet.glb";
  std::filesystem::path environment = shared / "envmaps/royal_esplanade_1k.hdr";
  if (!std::filesystem::exists(model) || !std::filesystem::exists(environment))
    GTEST_SKIP() << "shared scenes not found at " << shared;
  expectBackendsAgree(loadScene(model.string(), {environment.string()}), 61);
}

}  // namespace
}  // namespace candela
