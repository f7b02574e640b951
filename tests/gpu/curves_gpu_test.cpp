// Curves on the OptiX backend: round curves (OptiX's round cubic Bezier primitive) agree with the CPU backend's
// Embree curves, in diffuse white and as hair, and flat and ribbon curves, which OptiX has no primitive for, are
// refused in one line.
#include <gtest/gtest.h>

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

TEST(GpuCurves, HairOnCurvesAgreesWithTheCpuBackend) {
  Scene scene = test::tubeGrid(true, 0.5f, 9, 0.2f, 0.05f);
  Material& m = scene.materials[0];
  m.type = MaterialType::Hair;
  m.fibreAbsorption = HairBsdf::absorptionOfMelanin(0.8f, 0.2f);
  m.roughness = 0.3f;
  m.azimuthalRoughness = 0.3f;
  m.scaleTilt = 2.0f;
  m.ior = 1.55f;
  expectBackendsAgree(scene, 181);
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
