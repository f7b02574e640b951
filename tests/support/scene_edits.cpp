#include "scene_edits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scene/builtin_scenes.h"
#include "scene/material_overrides.h"

namespace candela::test {

namespace {

constexpr uint32_t kSize = 48;
constexpr uint32_t kSamples = 4;

RenderSettings settings() {
  RenderSettings s;
  s.width = s.height = kSize;
  s.seed = 17;
  return s;
}

std::unique_ptr<Backend> start(const BackendFactory& makeBackend, const Scene& scene) {
  std::unique_ptr<Backend> backend = makeBackend();
  backend->setScene(scene);
  backend->setSettings(settings());
  backend->setCamera(scene.camera.toCamera(1.0f));
  return backend;
}

// Renders the original scene first, so that the edit must restart a film that holds samples.
Image renderEdited(const BackendFactory& makeBackend, const Scene& original,
                   const std::function<void(Backend&)>& edit) {
  std::unique_ptr<Backend> backend = start(makeBackend, original);
  backend->render(kSamples);
  edit(*backend);
  EXPECT_EQ(backend->accumulatedSamples(), 0u);
  backend->render(kSamples);
  return backend->readImage();
}

Image renderRebuilt(const BackendFactory& makeBackend, const Scene& edited) {
  std::unique_ptr<Backend> backend = start(makeBackend, edited);
  backend->render(kSamples);
  return backend->readImage();
}

}  // namespace

void expectSameImage(const Image& a, const Image& b) {
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(Vec3)) != 0) ++differing;
  EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " pixels";
}

Scene withMaterialEdit(Scene scene) {
  MaterialOverrides overrides;
  overrides.shading = ShadingModel::Pbr;
  overrides.roughness = 0.2f;
  applyOverrides(scene.materials, overrides);
  return scene;
}

void expectMaterialEditMatchesRebuild(const BackendFactory& makeBackend) {
  const Scene original = makeMaterialGallery();
  const Scene edited = withMaterialEdit(original);
  Image afterEdit =
      renderEdited(makeBackend, original, [&](Backend& b) { EXPECT_TRUE(b.setMaterials(edited.materials)); });
  Image rebuilt = renderRebuilt(makeBackend, edited);
  expectSameImage(afterEdit, rebuilt);
  // The edit must have changed the picture, or this check proves nothing.
  Image unedited = renderRebuilt(makeBackend, original);
  EXPECT_NE(std::memcmp(unedited.pixels.data(), rebuilt.pixels.data(), rebuilt.pixels.size() * sizeof(Vec3)), 0);
}

void expectEnvironmentEditMatchesRebuild(const BackendFactory& makeBackend) {
  const Scene original = makeMaterialGallery();
  Scene edited = original;
  Texture& map = edited.environment.map;
  map.name = "a 16x8 gradient";
  map.width = 16;
  map.height = 8;
  map.channels = 3;
  for (uint32_t y = 0; y < map.height; ++y)
    for (uint32_t x = 0; x < map.width; ++x) map.floats.insert(map.floats.end(), {float(x) / 8, 0.5f, float(y) / 4});
  edited.environment.intensity = 2.0f;
  edited.environment.rotationDegrees = 30.0f;
  Image afterEdit = renderEdited(makeBackend, original, [&](Backend& b) { b.setEnvironment(edited.environment); });
  Image rebuilt = renderRebuilt(makeBackend, edited);
  expectSameImage(afterEdit, rebuilt);
  Image unedited = renderRebuilt(makeBackend, original);
  EXPECT_NE(std::memcmp(unedited.pixels.data(), rebuilt.pixels.data(), rebuilt.pixels.size() * sizeof(Vec3)), 0);
}

void expectInstanceTransformEditMatchesRebuild(const BackendFactory& makeBackend) {
  const Scene original = makeCornellBox();
  Scene edited = original;
  const float c = std::cos(0.05f), s = std::sin(0.05f);
  for (Instance& instance : edited.instances) {
    Affine3x4& m = instance.objectToWorld;
    for (int row = 0; row < 3; ++row) {  // turned a little about y, then moved
      const float x = m.m[4 * row], z = m.m[4 * row + 2];
      m.m[4 * row] = c * x + s * z;
      m.m[4 * row + 2] = -s * x + c * z;
    }
    m.m[3] += 0.05f;
    m.m[7] -= 0.03f;
  }
  Image afterEdit = renderEdited(makeBackend, original, [&](Backend& b) { b.setInstanceTransforms(edited); });
  Image rebuilt = renderRebuilt(makeBackend, edited);
  expectSameImage(afterEdit, rebuilt);
  Image unedited = renderRebuilt(makeBackend, original);
  EXPECT_NE(std::memcmp(unedited.pixels.data(), rebuilt.pixels.data(), rebuilt.pixels.size() * sizeof(Vec3)), 0);
}

}  // namespace candela::test
