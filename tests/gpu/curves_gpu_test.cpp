// Curves on the OptiX backend: round curves (OptiX's round cubic Bezier primitive) agree with the CPU backend's
// Embree curves, in diffuse white and as hair, a backend switches between the full kernel they need and the lean
// one, and flat and ribbon curves, which OptiX has no primitive for, are refused in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "backend_agreement.h"
#include "curves/curve_scenes.h"
#include "kernel/bsdf/hair.h"

namespace candela {
namespace {

// Thin curves cover few pixels: half the other agreement tests' samples a batch suffice.
void expectBackendsAgree(const Scene& scene, uint32_t seed) {
  test::AgreementRun run;
  run.samplesPerBatch = 16;
  test::expectBackendsAgree(scene, seed, run);
}

TEST(GpuCurves, RoundCurvesAgreeWithTheCpuBackend) { expectBackendsAgree(test::tubeGrid(true, 0.5f), 171); }

Scene hairOnCurves() {
  Scene scene = test::tubeGrid(true, 0.5f, 9, 0.2f, 0.05f);
  Material& m = scene.materials[0];
  m.type = MaterialType::Hair;
  m.fibreAbsorption = HairBsdf::absorptionOfMelanin(0.8f, 0.2f);
  m.roughness = 0.3f;
  m.azimuthalRoughness = 0.3f;
  m.scaleTilt = 2.0f;
  m.ior = 1.55f;
  return scene;
}

TEST(GpuCurves, HairOnCurvesAgreesWithTheCpuBackend) { expectBackendsAgree(hairOnCurves(), 181); }

// A scene of curves needs the full kernel and one of triangles does not (backends/optix/program_use.h): a backend
// that switches between them renders each as a fresh backend does, sample for sample.
TEST(GpuCurves, SwitchingBetweenTheLeanAndTheFullKernelGivesTheImagesOfAFreshBackend) {
  const Scene lean = test::tubeGrid(false, 0.5f), full = hairOnCurves();
  const RenderSettings settings = test::squareImage(32, 191);
  auto render = [&](OptixBackend& backend, const Scene& scene) {
    backend.setScene(scene);
    backend.setCamera(scene.camera.toCamera(1.0f));
    backend.setPathSchedule(PathSchedule::Megakernel);  // the same programs on both sides
    backend.render(8);
    return backend.readImage();
  };
  auto fresh = [&](const Scene& scene) {
    OptixBackend backend;
    backend.setSettings(settings);
    return render(backend, scene);
  };
  const Image freshLean = fresh(lean), freshFull = fresh(full);
  OptixBackend switching;
  switching.setSettings(settings);
  for (const Scene* scene : {&lean, &full, &lean}) {
    const Image image = render(switching, *scene);
    const Image& expected = scene == &lean ? freshLean : freshFull;
    ASSERT_EQ(image.pixels.size(), expected.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) {
      const Vec3 a = image.pixels[i], b = expected.pixels[i];
      ASSERT_LE(fmaxf(fabsf(a.x - b.x), fmaxf(fabsf(a.y - b.y), fabsf(a.z - b.z))), 1e-5f * (1.0f + maxComponent(b)))
          << scene->name << ", pixel " << i;
    }
  }
}

TEST(GpuCurves, FlatAndRibbonCurvesAreRefused) {
  for (CurveType type : {CurveType::Flat, CurveType::Ribbon}) {
    Scene scene = test::tubeGrid(true, 0.5f);
    scene.meshes[0] = test::straightCurve(type, 4.0f, 0.15f);
    OptixBackend backend;
    try {
      backend.setScene(scene);
      ADD_FAILURE() << "a scene of curve type " << int(type) << " was taken";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("flat and ribbon curves are rendered by the CPU backend only"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace candela
