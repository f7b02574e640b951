// The public C++ interface as a program that links only libcandela sees it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "candela/candela.h"

namespace api = candela::api;

namespace {

api::RenderOptions tiny(uint32_t spp = 4) {
  api::RenderOptions options;
  options.width = 32;
  options.height = 24;
  options.samplesPerPixel = spp;
  options.backend = "cpu";
  return options;
}

double mean(const api::Image& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.size(); ++i) sum += image.data()[i];
  return sum / double(image.size());
}

// The message of the Error that `work` throws; fails the test where it throws none.
template <class Work>
std::string errorOf(Work work) {
  try {
    work();
  } catch (const api::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no api::Error thrown";
  return {};
}

// A floor lit by a square light above it, seen from above and to the side.
api::SceneBuilder litFloor() {
  api::SceneBuilder builder("floor");
  const uint32_t white = builder.addMaterial({"diffuse", {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 0.5f, 0.0f, 1.5f});
  const uint32_t lamp = builder.addMaterial({"diffuse", {0, 0, 0}, {10, 10, 10}, 0.5f, 0.0f, 1.5f});
  const float floor[] = {-2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2};
  const float light[] = {-0.5f, 2, -0.5f, -0.5f, 2, 0.5f, 0.5f, 2, 0.5f, 0.5f, 2, -0.5f};
  const uint32_t quad[] = {0, 2, 1, 0, 3, 2};  // the floor faces +y, the light -y
  api::MeshArrays mesh;
  mesh.positions = floor;
  mesh.vertexCount = 4;
  mesh.indices = quad;
  mesh.triangleCount = 2;
  mesh.material = white;
  builder.addMesh(mesh);
  mesh.positions = light;
  mesh.material = lamp;
  builder.addMesh(mesh);
  builder.setCamera({{0, 3, 5}, {0, 0, 0}, {0, 1, 0}, 40});
  return builder;
}

}  // namespace

TEST(Api, RendersABuiltInSceneToLinearFloats) {
  const api::RenderResult result = api::render(api::Scene::load("cornell-box"), tiny());
  ASSERT_EQ(result.image.width(), 32u);
  ASSERT_EQ(result.image.height(), 24u);
  ASSERT_EQ(result.image.channels(), 3u);
  for (size_t i = 0; i < result.image.size(); ++i) ASSERT_TRUE(std::isfinite(result.image.data()[i]));
  EXPECT_GT(mean(result.image), 0.01);
  EXPECT_EQ(result.samplesPerPixel, 4u);
  EXPECT_EQ(result.backend, "cpu");
  EXPECT_GT(result.rays, 32u * 24u * 4u);
}

TEST(Api, TheSameSeedGivesTheSameImageAndAnotherSeedAnother) {
  const api::Scene scene = api::Scene::load("cornell-box");
  api::RenderOptions options = tiny();
  const api::Image a = api::render(scene, options).image;
  const api::Image b = api::render(scene, options).image;
  options.seed = 7;
  const api::Image c = api::render(scene, options).image;
  ASSERT_EQ(a.size(), b.size());
  bool same = true, differs = false;
  for (size_t i = 0; i < a.size(); ++i) {
    same &= a.data()[i] == b.data()[i];
    differs |= a.data()[i] != c.data()[i];
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

TEST(Api, TheCallbackSeesEachSampleAndMayEndTheRender) {
  uint32_t calls = 0;
  uint32_t previewWidth = 0;
  const api::RenderResult result =
      api::render(api::Scene::load("cornell-box"), tiny(16), [&](const api::Progress& progress) {
        ++calls;
        EXPECT_EQ(progress.samples, calls);
        EXPECT_EQ(progress.samplesPerPixel, 16u);
        if (calls == 2) previewWidth = progress.image().width();
        return calls < 3;
      });
  EXPECT_EQ(calls, 3u);
  EXPECT_EQ(result.samplesPerPixel, 3u);
  EXPECT_EQ(previewWidth, 32u);
}

TEST(Api, ReturnsTheAovsAskedFor) {
  api::RenderOptions options = tiny();
  options.aovs = {"albedo", "depth"};
  options.denoiser = "atrous";
  const api::RenderResult result = api::render(api::Scene::load("cornell-box"), options);
  ASSERT_EQ(result.aovs.size(), 2u);
  EXPECT_EQ(result.aovs.at("albedo").channels(), 3u);
  EXPECT_EQ(result.aovs.at("depth").channels(), 1u);
  EXPECT_EQ(result.aovs.at("depth").width(), 32u);
  EXPECT_GT(mean(result.aovs.at("depth")), 0.0);
  EXPECT_GT(mean(result.aovs.at("albedo")), 0.0);
}

TEST(Api, CopiesOfAnImageShareItsPixels) {
  const api::RenderResult result = api::render(api::Scene::load("cornell-box"), tiny(1));
  const api::Image copy = result.image;
  EXPECT_EQ(copy.data(), result.image.data());
}

TEST(Api, ABuiltSceneIsLitByItsEmissiveMesh) {
  const api::Scene scene = litFloor().build();
  EXPECT_EQ(scene.triangleCount(), 4u);
  const api::RenderResult result = api::render(scene, tiny(8));
  // The floor's centre, under the light, is bright; the image's top corner looks past the floor at nothing.
  EXPECT_GT(result.image.at(16, 16, 0), 0.1f);
  EXPECT_EQ(result.image.at(0, 0, 0), 0.0f);
}

TEST(Api, ErrorsAreOneLineAsTheCommandPrintsThem) {
  EXPECT_EQ(errorOf([] { api::Scene::load("nowhere"); })
                .rfind("unknown scene 'nowhere': not a file, nor a built-in "
                       "scene (cornell-box",
                       0),
            0u);
  const api::Scene scene = api::Scene::load("cornell-box");
  api::RenderOptions options = tiny();
  options.denoiser = "magic";
  EXPECT_NE(errorOf([&] { api::render(scene, options); }).find("magic"), std::string::npos);
  options = tiny();
  options.width = 0;
  EXPECT_EQ(errorOf([&] { api::render(scene, options); }), "width 0 is not in [1, 16384]");
  options = tiny();
  options.backend = "vulkan";
  EXPECT_NE(errorOf([&] { api::render(scene, options); }).find("vulkan"), std::string::npos);
  options = tiny();
  options.aovs = {"albedo", "colour"};
  EXPECT_NE(errorOf([&] { api::render(scene, options); }).find("colour"), std::string::npos);
}

TEST(Api, ABuilderRefusesBadArraysNamingThem) {
  api::SceneBuilder builder;
  EXPECT_EQ(errorOf([&] { builder.addMaterial({"velvet"}); }).rfind("unknown material type 'velvet' (use diffuse", 0),
            0u);
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint32_t beyond[] = {0, 1, 3};
  api::MeshArrays mesh;
  mesh.positions = positions;
  mesh.vertexCount = 3;
  mesh.indices = beyond;
  mesh.triangleCount = 1;
  EXPECT_EQ(errorOf([&] { builder.addMesh(mesh); }), "mesh 0: triangle 0 names vertex 3, beyond its 3 vertices");
  const uint32_t triangle[] = {0, 1, 2};
  mesh.indices = triangle;
  mesh.material = 2;
  builder.addMesh(mesh);
  EXPECT_EQ(errorOf([&] { builder.build(); }), "mesh 0: triangle 0 names material 2, but 0 materials were added");
}

TEST(Api, BenchTimesTheRender) {
  const api::BenchResult result = api::bench(api::Scene::load("cornell-box"), tiny(2), 1);
  EXPECT_EQ(result.scene, "cornell-box");
  EXPECT_EQ(result.samplesPerPixel, 2u);
  EXPECT_GT(result.seconds, 0.0);
  EXPECT_GT(result.mraysPerSecond, 0.0);
}

TEST(Api, HasAVersion) { EXPECT_STREQ(candela::api::version(), CANDELA_EXPECTED_VERSION); }
