// The integrator's AOVs on the CPU backend: what they hold on surfaces, through mirrors and where paths escape,
// and that recording them leaves the image alone.
#include <gtest/gtest.h>

#include <cmath>

#include "denoise_support.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

using test::renderWithAovs;

// At 4 samples per pixel the albedo is exactly the card's: the AOVs are means over the samples, like colour.
TEST(Aovs, AlbedoNormalAndDepthOfACardSeenHeadOn) {
  const Scene scene = test::albedoEdgeCard(0.7f, 0.2f);
  const test::RenderWithAovs r = renderWithAovs(scene, 16, 16, 4, 1);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      if (x == 7 || x == 8) continue;  // the pixels the edge runs along
      const size_t i = size_t(y) * 16 + x;
      const float albedo = x < 8 ? 0.7f : 0.2f;
      EXPECT_NEAR(r.aovs.albedo.pixels[i].x, albedo, 1e-6f);
      // The normal faces the camera; depth is the distance to the plane z = 0 along each jittered ray, between
      // 4 (the centre) and 4 / cos(the corner's angle).
      EXPECT_NEAR(r.aovs.normal.pixels[i].z, -1.0f, 1e-6f);
      EXPECT_GE(r.aovs.depth[i], 4.0f - 1e-4f);
      EXPECT_LE(r.aovs.depth[i], 4.0f / std::cos(std::atan(std::sqrt(2.0f) * std::tan(20.0f * kPi / 180.0f))) + 1e-4f);
    }
}

// The camera looks at a mirror (tinted 0.5) 2 units away; the mirror reflects a card (albedo 0.6) 3 units
// behind the camera. The AOVs belong to the card: albedo 0.5 * 0.6, normal towards the arriving ray, depth
// 2 + 5.
TEST(Aovs, FollowMirrors) {
  Scene scene;
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {0.5f, 0.5f, 0.5f};
  scene.materials = {mirror, test::diffuseMaterial({0.6f, 0.6f, 0.6f})};
  Mesh mesh;
  appendQuad(mesh, {-10, -10, 2}, {10, -10, 2}, {10, 10, 2}, {-10, 10, 2}, {0, 0, -1}, 0);
  appendQuad(mesh, {-10, -10, -3}, {10, -10, -3}, {10, 10, -3}, {-10, 10, -3}, {0, 0, 1}, 1);
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, 1};
  scene.camera.verticalFovDegrees = 1.0f;
  const test::RenderWithAovs r = renderWithAovs(scene, 4, 4, 2, 1);
  for (size_t i = 0; i < 16; ++i) {
    EXPECT_NEAR(r.aovs.albedo.pixels[i].y, 0.3f, 1e-6f);
    EXPECT_NEAR(r.aovs.normal.pixels[i].z, 1.0f, 1e-4f);
    EXPECT_NEAR(r.aovs.depth[i], 7.0f, 1e-2f);
  }
}

TEST(Aovs, EscapedPathsSeeAWhiteEnvironmentWithNoNormalAndNoDepth) {
  Scene scene = test::albedoEdgeCard(0.5f, 0.5f);
  scene.camera.target = {0, 0, -8};  // looking away from the card
  const test::RenderWithAovs r = renderWithAovs(scene, 8, 8, 2, 1);
  for (size_t i = 0; i < 64; ++i) {
    EXPECT_EQ(r.aovs.albedo.pixels[i].x, 1.0f);
    EXPECT_EQ(dot(r.aovs.normal.pixels[i], r.aovs.normal.pixels[i]), 0.0f);
    EXPECT_EQ(r.aovs.depth[i], 0.0f);
  }
}

// Inside a closed sphere of albedo 0.5 emitting 1, radiance is 2 everywhere, of which the camera sees 1 emitted by
// the wall it looks at: the rest is reflected. Through a mirror (tint 0.5) the emitter seen is emitted light too
// (0.5 x 2), while the sky that the lit card reflects is not; the sky seen directly is.
TEST(Emission, IsWhatTheCameraSeesEmittedDirectlyOrThroughMirrors) {
  const test::RenderWithAovs sphere = renderWithAovs(makeClosedEmissiveSphere(0.5f, 1.0f), 4, 4, 64, 1);
  for (size_t i = 0; i < 16; ++i) {
    EXPECT_EQ(sphere.aovs.emission.pixels[i].x, 1.0f);
    EXPECT_NEAR(sphere.image.pixels[i].x, 2.0f, 0.3f);
  }

  Scene scene;
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {0.5f, 0.5f, 0.5f};
  Material emitter = test::diffuseMaterial({0.6f, 0.6f, 0.6f});
  emitter.emission = {2, 2, 2};
  scene.materials = {mirror, emitter};
  Mesh mesh;
  appendQuad(mesh, {-10, -10, 2}, {10, -10, 2}, {10, 10, 2}, {-10, 10, 2}, {0, 0, -1}, 0);
  appendQuad(mesh, {-10, -10, -3}, {10, -10, -3}, {10, 10, -3}, {-10, 10, -3}, {0, 0, 1}, 1);
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, Affine3x4{}});
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, 1};
  scene.camera.verticalFovDegrees = 1.0f;
  const test::RenderWithAovs mirrored = renderWithAovs(scene, 4, 4, 2, 1);
  for (size_t i = 0; i < 16; ++i) EXPECT_EQ(mirrored.aovs.emission.pixels[i].x, 1.0f);

  const test::RenderWithAovs card = renderWithAovs(test::albedoEdgeCard(0.5f, 0.5f), 8, 8, 2, 1);
  Scene away = test::albedoEdgeCard(0.5f, 0.5f);
  away.camera.target = {0, 0, -8};  // looking away from the card, at the sky
  const test::RenderWithAovs sky = renderWithAovs(away, 8, 8, 2, 1);
  for (size_t i = 0; i < 64; ++i) {
    EXPECT_EQ(card.aovs.emission.pixels[i].x, 0.0f);
    EXPECT_EQ(sky.aovs.emission.pixels[i].x, 1.0f);
  }
}

TEST(Aovs, RecordingThemLeavesTheImageUnchanged) {
  const Scene scene = makeCornellBox();
  RenderSettings settings;
  settings.width = settings.height = 24;
  CpuBackend plain, withAovs;
  for (CpuBackend* b : {&plain, &withAovs}) {
    b->setScene(scene);
    b->setSettings(settings);
    b->setCamera(scene.camera.toCamera(1.0f));
  }
  withAovs.setAovsEnabled(true);
  plain.render(3);
  withAovs.render(3);
  const Image a = plain.readImage(), b = withAovs.readImage();
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a.pixels[i][c], b.pixels[i][c]) << "pixel " << i;
}

TEST(Aovs, ReadingThemWithoutEnablingThemIsAnError) {
  CpuBackend backend;
  EXPECT_THROW(backend.readAovs(), std::logic_error);
}

}  // namespace
}  // namespace candela
