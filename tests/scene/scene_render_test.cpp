#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include "app/render_job.h"
#include "app/scene_loading.h"
#include "io/file_bytes.h"
#include "io/images/image_decoding.h"
#include "io/load_diagnostics.h"
#include "scene/environment_distribution.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

// Renders a few samples of a loaded scene on the CPU and checks that every pixel is a finite, non-negative value
// and that no sample was dropped as invalid.
void expectCleanRender(const std::string& spec, const std::string& environment = {}) {
  Scene scene = loadScene(spec, {environment});
  RenderJob job;
  job.settings.width = 48;
  job.settings.height = 32;
  job.samplesPerPixel = 4;
  job.backend = "cpu";
  RenderOutcome out = renderLoadedScene(job, scene, false);
  EXPECT_EQ(out.stats.invalidSamples, 0u) << spec;
  double sum = 0;
  for (Vec3 p : out.image.pixels) {
    ASSERT_TRUE(isFinite(p) && p.x >= 0 && p.y >= 0 && p.z >= 0) << spec;
    sum += p.x + p.y + p.z;
  }
  EXPECT_GT(sum, 0.0) << spec << " rendered black";
}

TEST(SceneRenderSharedScenes, LoadedScenesRenderWithoutNaN) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  expectCleanRender((scenes / "cornell_box/CornellBox-Sphere.obj").string());
  expectCleanRender((scenes / "cornell_box/CornellBox-Water.obj").string());
  expectCleanRender((scenes / "damaged_helmet/glTF-Binary/DamagedHelmet.glb").string(),
                    (scenes / "envmaps/studio_small_09_1k.hdr").string());
  expectCleanRender((scenes / "gltf_material_tests/NegativeScaleTest/glTF/NegativeScaleTest.gltf").string(),
                    (scenes / "envmaps/venice_sunset_1k.hdr").string());
}

TEST(SceneRenderSharedScenes, EnvironmentMapsLoad) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  size_t maps = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes / "envmaps")) {
    if (entry.path().extension() != ".hdr") continue;
    Texture map = loadEnvironmentImage(entry.path().string());
    EXPECT_EQ(map.width, 1024u);
    EXPECT_EQ(map.height, 512u);
    EXPECT_EQ(map.channels, 3u);
    std::vector<Vec3> texels = environmentTexels(map);
    EnvironmentDistribution d = EnvironmentDistribution::build(texels, map.width, map.height);
    EXPECT_GT(d.funcAverage, 0.0f) << entry.path();
    ++maps;
  }
  EXPECT_EQ(maps, 6u);
}

TEST(EnvironmentLoading, TruncatedRadianceFilesAreRejected) {
  test::TempFolder dir;
  std::vector<float> pixels(64 * 32 * 3);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % 97) * 0.1f;
  std::string path = dir.file("full.hdr");
  ASSERT_TRUE(stbi_write_hdr(path.c_str(), 64, 32, 3, pixels.data()));
  Texture full = loadEnvironmentImage(path);
  EXPECT_NEAR(full.floats[3 * 70 + 1], pixels[3 * 70 + 1], 0.01f);
  std::vector<uint8_t> bytes = readFileBytes(path);
  for (size_t cut : {bytes.size() - 1, bytes.size() / 2, size_t(80)}) {
    std::string part(bytes.begin(), bytes.begin() + std::ptrdiff_t(cut));
    EXPECT_THROW(loadEnvironmentImage(dir.write("cut.hdr", part)), LoadError) << cut;
  }
}

TEST(EnvironmentLoading, RejectsNonHdrAndBrokenFiles) {
  test::TempFolder dir;
  EXPECT_THROW(loadEnvironmentImage(dir.write("a.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 512 +X 1024\n")),
               LoadError);
  EXPECT_THROW(loadEnvironmentImage(dir.write("b.hdr", "not an image")), LoadError);
  EXPECT_THROW(loadEnvironmentImage(dir.write("c.exr", "not an image")), LoadError);
  EXPECT_THROW(loadEnvironmentImage(dir.file("missing.hdr")), LoadError);
  try {
    loadEnvironmentImage(dir.write("d.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n"));
    ADD_FAILURE();
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("d.hdr: "), std::string::npos);
  }
}

}  // namespace
}  // namespace candela
