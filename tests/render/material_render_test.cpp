// Whole renders with known answers: furnaces for the models that conserve energy exactly, the directional
// albedo for the others, the mirror corridor at 100 bounces, and cut-outs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bsdf/bsdf_cases.h"
#include "render/render_support.h"
#include "scene/builtin_scenes.h"

namespace candela::test {
namespace {

// Roulette off: every path of a lossless delta material carries exactly weight 1 to the environment, so the
// image is 1 up to paths still inside the glass at the depth limit (probability below R^64).
TEST(MaterialRender, LosslessDeltaMaterialsVanishInTheFurnace) {
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {1, 1, 1};
  Material glass;
  glass.type = MaterialType::Glass;
  glass.baseColor = {1, 1, 1};
  glass.ior = 1.5f;
  for (const Material& m : {mirror, glass}) {
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.maxDepth = 64;
    settings.rouletteDepth = 1000;
    PixelStatistics s = luminanceStatistics(renderCpu(furnaceSphere(m), settings, 16));
    EXPECT_NEAR(s.min, 1.0, 1e-4) << int(m.type);
    EXPECT_NEAR(s.max, 1.0, 1e-4) << int(m.type);
  }
}

// A transmissive material of ior 1 is index-matched to the air around it: light passes straight through,
// whatever the roughness, so in the furnace the sphere vanishes as lossless glass does. It used to render black
// with invalid samples (TransmissionRoughnessTest's 'Air' row).
TEST(MaterialRender, IndexMatchedTransmissionPassesLightStraightThrough) {
  for (float roughness : {0.0f, 0.3f, 1.0f}) {
    Material air;
    air.type = MaterialType::Disney;
    air.baseColor = {1, 1, 1};
    air.specTrans = 1.0f;
    air.ior = 1.0f;
    air.roughness = roughness;
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.maxDepth = 8;
    settings.rouletteDepth = 1000;
    PixelStatistics s = luminanceStatistics(renderCpu(furnaceSphere(air), settings, 16));
    EXPECT_NEAR(s.min, 1.0, 1e-4) << "roughness " << roughness;
    EXPECT_NEAR(s.max, 1.0, 1e-4) << "roughness " << roughness;
  }
}

// KHR_materials_volume's Beer-Lambert absorption. The furnace sphere is seen head-on: every camera ray crosses
// it along a chord between 1.997 and 2 (its diameter). Index-matched, the ray goes straight through and keeps
// exp(-absorption * chord) of the sky's radiance 1. Smooth glass of ior 1.5 reflects F = 0.04 at normal
// incidence; what enters leaves after k internal reflections with (1 - F)^2 F^k T^(k+1), T = exp(-2 absorption),
// so the pixel sees F + (1 - F)^2 T / (1 - F T).
TEST(MaterialRender, AbsorbingVolumesKeepBeerLambertsTransmittance) {
  const float absorption[3] = {0.1f, 0.5f, 1.5f};
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.maxDepth = 64;
  settings.rouletteDepth = 1000;

  Material air;
  air.type = MaterialType::Disney;
  air.baseColor = {1, 1, 1};
  air.specTrans = 1.0f;
  air.ior = 1.0f;
  air.absorption = {absorption[0], absorption[1], absorption[2]};
  const Image straight = renderCpu(furnaceSphere(air), settings, 2);
  for (int c = 0; c < 3; ++c) {
    float lowest = 1e30f, highest = -1e30f;
    for (const Vec3& p : straight.pixels) {
      const float value = c == 0 ? p.x : c == 1 ? p.y : p.z;
      lowest = std::min(lowest, value);
      highest = std::max(highest, value);
    }
    EXPECT_GE(lowest, std::exp(-absorption[c] * 2.0f) - 1e-4f) << "channel " << c;
    EXPECT_LE(highest, std::exp(-absorption[c] * 1.997f) + 1e-4f) << "channel " << c;
  }

  Material glass;
  glass.type = MaterialType::Glass;
  glass.baseColor = {1, 1, 1};
  glass.ior = 1.5f;
  glass.absorption = air.absorption;
  const Image refracted = renderCpu(furnaceSphere(glass), settings, 256);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0;
    for (const Vec3& p : refracted.pixels) sum += c == 0 ? p.x : c == 1 ? p.y : p.z;
    const double mean = sum / double(refracted.pixels.size());
    const double f = 0.04, t = std::exp(-2.0 * absorption[c]);
    EXPECT_NEAR(mean, f + (1 - f) * (1 - f) * t / (1 - f * t), 4e-3) << "channel " << c;
  }
}

// A quad whose normal map tilts every shading normal 45 degrees towards +x, seen from the -x side at about 37
// degrees from the normal, under a uniform sky of radiance 1: the mirror reflection about the tilted normal
// points into the surface. Those paths used to end black (thick black rims on normal-mapped metal); with the
// shading normal bent just enough to keep the reflection above the surface, a lossless mirror returns the sky
// everywhere, and a smooth white metal nearly so.
Scene normalMappedQuad(const Material& material) {
  Scene scene;
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, Vec3{0, 0, 1});
  quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.tangents.assign(4, Vec4{1, 0, 0, 1});
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.triangleMaterials = {0, 0};
  scene.meshes.push_back(quad);
  scene.instances.push_back({0, Affine3x4{}});
  Texture tilted;  // tangent-space (sin 45, 0, cos 45)
  tilted.name = "tilted";
  tilted.width = tilted.height = 1;
  tilted.channels = 3;
  tilted.bytes = {uint8_t(std::lround(255 * (0.5 + 0.5 * 0.70710678))), 128,
                  uint8_t(std::lround(255 * (0.5 + 0.5 * 0.70710678)))};
  scene.textures.push_back(tilted);
  scene.materials = {material};
  scene.materials[0].normalTexture = 0;
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {-3, 0, 4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 8.0f;
  return scene;
}

TEST(MaterialRender, NormalMappedMirrorKeepsItsReflectionAboveTheSurface) {
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {1, 1, 1};
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.maxDepth = 4;
  PixelStatistics s = luminanceStatistics(renderCpu(normalMappedQuad(mirror), settings, 4));
  EXPECT_NEAR(s.min, 1.0, 1e-4);
  EXPECT_NEAR(s.max, 1.0, 1e-4);

  Material metal;
  metal.type = MaterialType::Pbr;
  metal.baseColor = {1, 1, 1};
  metal.metallic = 1.0f;
  metal.roughness = 0.1f;
  s = luminanceStatistics(renderCpu(normalMappedQuad(metal), settings, 64));
  EXPECT_GT(s.min, 0.8);
  EXPECT_GT(s.mean, 0.9);
}

// Direct lighting only (depth 1) on a convex object under a uniform sky of radiance 1: each pixel estimates
// the directional albedo at its view angle, here within 2 degrees of normal incidence. The reference is the
// quadrature of eval() at normal incidence, which shares no code with light or BSDF sampling. Tolerance:
// 4 standard errors of the image mean plus 3e-3 for the spread of view angles and the quadrature.
TEST(MaterialRender, DirectLightingInTheFurnaceEqualsTheAlbedo) {
  struct Model {
    const char* name;
    Material material;
  };
  std::vector<Model> models;
  Material phong;
  phong.type = MaterialType::BlinnPhong;
  phong.baseColor = {0.7f, 0.5f, 0.3f};
  phong.specularColor = {0.3f, 0.3f, 0.3f};
  phong.shininess = 20.0f;
  models.push_back({"BlinnPhong", phong});
  for (float metallic : {0.0f, 1.0f}) {
    Material pbr;
    pbr.type = MaterialType::Pbr;
    pbr.baseColor = {0.9f, 0.6f, 0.3f};
    pbr.metallic = metallic;
    pbr.roughness = 0.5f;
    models.push_back({"Pbr", pbr});
  }
  Material disney = disneyMaterial(0.5f);
  disney.sheen = 0.5f;
  disney.clearcoat = 0.7f;
  disney.subsurface = 0.3f;
  models.push_back({"Disney", disney});
  Material iridescent = models[1].material;
  iridescent.iridescence = 1.0f;
  iridescent.iridescenceIor = 1.8f;
  iridescent.iridescenceThickness = 350.0f;
  models.push_back({"PbrIridescent", iridescent});
  for (const Model& model : models) {
    RenderSettings settings;
    settings.width = settings.height = 24;
    settings.maxDepth = 1;
    PixelStatistics s = luminanceStatistics(renderCpu(furnaceSphere(model.material), settings, 64));
    SurfaceInteraction si;
    si.shadingNormal = si.geometricNormal = {0, 0, 1};
    Bsdf bsdf(model.material, si, {0, 0, 1});
    double reference = bsdf.visit([](const auto& m) { return albedoByQuadrature(makeCase("", m), {0, 0, 1}); });
    EXPECT_NEAR(s.mean, reference, 4 * s.standardError + 3e-3) << model.name << " metallic " << model.material.metallic;
  }
}

// KHR_materials_iridescence in whole renders: a factor of 0 renders exactly as no film, whatever the film's other
// parameters; a film of factor 1 changes the image; and a white iridescent sphere in the furnace (every bounce,
// roulette off) returns at most the light arriving, in every channel: the image mean stays within 4 standard
// errors of 1 or below it.
TEST(MaterialRender, IridescentFilmsRenderWithinTheFurnace) {
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.maxDepth = 16;
  settings.rouletteDepth = 1000;
  Material plain;
  plain.type = MaterialType::Pbr;
  plain.baseColor = {1, 1, 1};
  plain.metallic = 0.0f;
  plain.roughness = 0.4f;
  plain.specular = 1.0f;
  Material unused = plain;
  unused.iridescenceIor = 2.0f;
  unused.iridescenceThickness = 250.0f;
  const Image a = renderCpu(furnaceSphere(plain), settings, 4), b = renderCpu(furnaceSphere(unused), settings, 4);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    ASSERT_EQ(a.pixels[i].x, b.pixels[i].x) << i;
    ASSERT_EQ(a.pixels[i].y, b.pixels[i].y) << i;
    ASSERT_EQ(a.pixels[i].z, b.pixels[i].z) << i;
  }
  for (float metallic : {0.0f, 1.0f}) {
    Material film = unused;
    film.metallic = metallic;
    film.iridescence = 1.0f;
    const Image image = renderCpu(furnaceSphere(film), settings, 64);
    for (int c = 0; c < 3; ++c) {
      double sum = 0, sum2 = 0;
      for (const Vec3& p : image.pixels) {
        const double value = p[c];
        sum += value;
        sum2 += value * value;
      }
      const double n = double(image.pixels.size()), mean = sum / n;
      const double standardError = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
      EXPECT_LE(mean, 1.0 + 4 * standardError) << "metallic " << metallic << ", channel " << c;
    }
    if (metallic == 0.0f) {
      double difference = 0;
      for (size_t i = 0; i < image.pixels.size(); ++i) difference += std::fabs(image.pixels[i].x - a.pixels[i].x);
      EXPECT_GT(difference / double(image.pixels.size()), 1e-3) << "the film left the image as it was";
    }
  }
}

// Two facing mirrors of reflectance R that also emit e, the camera between them looking straight at one: the
// camera ray and its 100 reflections each collect e, so the pixel is e (1 - R^101) / (1 - R). Any leak through
// a mirror or self-intersection along the way would lose the rest of the series. Roulette is off so every
// sample is the same number.
TEST(MaterialRender, MirrorCorridorSumsAHundredReflections) {
  constexpr float kR = 0.99f, kE = 0.01f, kHalf = 100.0f;
  Scene scene;
  scene.name = "emissive-mirrors";
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {kR, kR, kR};
  mirror.emission = {kE, kE, kE};
  scene.materials = {mirror};
  Mesh mesh;
  appendQuad(mesh, {-kHalf, -kHalf, 0.5f}, {kHalf, -kHalf, 0.5f}, {kHalf, kHalf, 0.5f}, {-kHalf, kHalf, 0.5f},
             {0, 0, 0}, 0);
  appendQuad(mesh, {-kHalf, -kHalf, -0.5f}, {kHalf, -kHalf, -0.5f}, {kHalf, kHalf, -0.5f}, {-kHalf, kHalf, -0.5f},
             {0, 0, 0}, 0);
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, Affine3x4{}});
  scene.camera.eye = {0.1f, 0.2f, 0.0f};
  scene.camera.target = {0.1f, 0.2f, 1.0f};
  scene.camera.verticalFovDegrees = 0.5f;
  RenderSettings settings;
  settings.width = settings.height = 8;
  settings.maxDepth = 100;
  settings.rouletteDepth = 1000;
  PixelStatistics s = luminanceStatistics(renderCpu(scene, settings, 4));
  double expected = kE * (1.0 - std::pow(double(kR), 101.0)) / (1.0 - kR);
  EXPECT_NEAR(s.min, expected, 1e-3 * expected);
  EXPECT_NEAR(s.max, expected, 1e-3 * expected);
}

TEST(MaterialRender, BuiltinMirrorCorridorRendersCleanlyAtDepth100) {
  Scene scene;
  ASSERT_TRUE(makeBuiltinScene("mirror-corridor", scene));
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.maxDepth = 100;
  CpuBackend backend;
  backend.setScene(scene);
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(1.5f));
  FrameStats stats = backend.render(4);
  EXPECT_EQ(stats.invalidSamples, 0u);
}

// An emissive wall of radiance 1 seen through a black quad with opacity 0.3: alpha blending shows 70% of the
// wall (stochastic transparency: binomial noise, 4 standard errors); an alpha mask with cutoff 0.5 removes
// the quad entirely, and at opacity 0.6 keeps it entirely.
TEST(MaterialRender, CutoutsLetTheRightShareThrough) {
  auto scene = [](AlphaMode mode, float opacity) {
    Scene s;
    s.name = "cutout";
    Material wall;
    wall.baseColor = {0, 0, 0};
    wall.emission = {1, 1, 1};
    Material cover;
    cover.baseColor = {0, 0, 0};
    cover.alphaMode = mode;
    cover.opacity = opacity;
    s.materials = {wall, cover};
    Mesh mesh;
    appendQuad(mesh, {-5, -5, 2}, {5, -5, 2}, {5, 5, 2}, {-5, 5, 2}, {0, 0, 0}, 0);
    appendQuad(mesh, {-5, -5, 1}, {5, -5, 1}, {5, 5, 1}, {-5, 5, 1}, {0, 0, 0}, 1);
    s.meshes.push_back(mesh);
    s.instances.push_back({0, Affine3x4{}});
    s.camera.eye = {0, 0, 0};
    s.camera.target = {0, 0, 1};
    s.camera.verticalFovDegrees = 20.0f;
    return s;
  };
  RenderSettings settings;
  settings.width = settings.height = 32;
  PixelStatistics blend = luminanceStatistics(renderCpu(scene(AlphaMode::Blend, 0.3f), settings, 16));
  double sigma = std::sqrt(0.7 * 0.3 / (32.0 * 32.0 * 16.0));
  EXPECT_NEAR(blend.mean, 0.7, 4 * sigma);
  PixelStatistics through = luminanceStatistics(renderCpu(scene(AlphaMode::Mask, 0.3f), settings, 1));
  EXPECT_EQ(through.min, 1.0);
  PixelStatistics kept = luminanceStatistics(renderCpu(scene(AlphaMode::Mask, 0.6f), settings, 1));
  EXPECT_EQ(kept.max, 0.0);
}

}  // namespace
}  // namespace candela::test
