// Whole renders of curves on the CPU backend: a white furnace (curves of albedo 1 under a uniform white light stay
// exactly as bright as the light, whatever their type), and round curves against the same tubes as triangle meshes
// (their image means agree within the renders' noise).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/scene_loading.h"
#include "backends/cpu/cpu_backend.h"
#include "curves/curve_scenes.h"
#include "support/render_statistics.h"

namespace candela::test {
namespace {

PixelStatistics renderScene(const Scene& scene, uint32_t batches, uint32_t samplesPerBatch, uint32_t size = 32) {
  CpuBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.maxDepth = 16;
  settings.sampler = SamplerKind::Independent;
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.0f));
  return renderBatches(backend, batches, samplesPerBatch);
}

TEST(CurveRender, WhiteFurnaceOfEveryType) {
  for (CurveType type : {CurveType::Flat, CurveType::Cylinder, CurveType::Ribbon}) {
    Scene scene = tubeGrid(true, 1.0f);
    for (Mesh& mesh : scene.meshes) {
      const float y = mesh.curveVertices[0].y;
      mesh = straightCurve(type, 4.0f, 0.15f, y);
    }
    constexpr uint32_t kBatches = 8;
    const PixelStatistics stats = renderScene(scene, kBatches, 4);
    EXPECT_EQ(stats.invalidSamples, 0u);
    std::string worst;
    EXPECT_EQ(countRejectedPixels(stats, {1, 1, 1}, kBatches, 1e-3, worst), 0u) << int(type) << ": " << worst;
    const ImageMean mean = imageMean(stats);
    EXPECT_NEAR(mean.mean, 1.0, 5e-3) << int(type);
  }
}

TEST(CurveRender, RoundCurvesMatchTriangleTubes) {
  const PixelStatistics curves = renderScene(tubeGrid(true, 0.5f), 16, 16);
  const PixelStatistics triangles = renderScene(tubeGrid(false, 0.5f), 16, 16);
  const ImageMean a = imageMean(curves), b = imageMean(triangles);
  EXPECT_LT(a.mean, 0.9) << "the tubes are seen and darker than the light";
  const double z =
      std::fabs(a.mean - b.mean) / std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
  EXPECT_LT(z, 4.0) << "curves " << a.mean << " +- " << a.standardError << ", triangles " << b.mean << " +- "
                    << b.standardError;
}

// A scene without a camera is framed around its curves too.
TEST(CurveRender, ASceneOfCurvesIsFramedAroundThem) {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(straightCurve(CurveType::Cylinder, 1.0f, 0.1f, 5.0f));
  scene.instances.push_back({0, Affine3x4{}, {}});
  scene.cameraMissing = true;
  frameSceneBounds(scene);
  EXPECT_NEAR(scene.camera.target.x, 0.0f, 1e-5f);
  EXPECT_NEAR(scene.camera.target.y, 5.0f, 1e-5f);
  EXPECT_GT(length(scene.camera.eye - scene.camera.target), 1.0f);
}

}  // namespace
}  // namespace candela::test
