// Mip pyramids, filtered lookups, ray-cone footprints, and what they do to renders: a receding checkerboard
// aliases far less at one sample per pixel, and filtering changes no mean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "kernel/ray_cone.h"
#include "kernel/texture_filtering.h"
#include "render/render_support.h"
#include "scene/flat_scene.h"
#include "scene/loaders/texture_limits.h"
#include "scene/mip_pyramid.h"
#include "support/checkerboard_scene.h"

namespace candela::test {
namespace {

TEST(MipPyramid, LevelSizesHalveRoundingDownToOne) {
  EXPECT_EQ(fullMipLevelCount(1, 1), 1u);
  EXPECT_EQ(fullMipLevelCount(256, 256), 9u);
  EXPECT_EQ(fullMipLevelCount(300, 7), 9u);  // 300, 150, 75, 37, 18, 9, 4, 2, 1
  EXPECT_EQ(fullMipLevelCount(1, 1000), 10u);
  EXPECT_EQ(mipLevelSize(300, 3), 37u);
  EXPECT_EQ(mipLevelSize(7, 3), 1u);
  EXPECT_EQ(mipLevelSize(7, 8), 1u);
  EXPECT_EQ(mipLevelSize(5, 1), 2u);
  TextureView view;
  view.width = 5;
  view.height = 3;
  view.channels = 2;
  view.levels = 3;
  EXPECT_EQ(mipLevelOffset(view, 1), 5u * 3 * 2);
  EXPECT_EQ(mipLevelOffset(view, 2), 5u * 3 * 2 + 2 * 1 * 2);
  // The memory limit counts the levels: 4x4 + 2x2 + 1x1 texels of 3 bytes.
  EXPECT_EQ(textureBytesWithMips({4, 4, 3}), (16u + 4u + 1u) * 3u);
}

// Every level of a float texture of odd sizes has the finest level's mean: each target texel covers its exact
// share of source texels, fractions included.
TEST(MipPyramid, EveryLevelKeepsTheMeanForNonPowerOfTwoSizes) {
  constexpr uint32_t kWidth = 37, kHeight = 11, kChannels = 3;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(0.0f, 4.0f);
  std::vector<float> level0(size_t(kWidth) * kHeight * kChannels);
  for (float& v : level0) v = value(random);
  auto channelMean = [&](const float* texels, size_t count, uint32_t c) {
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) sum += texels[i * kChannels + c];
    return sum / double(count);
  };
  std::vector<float> coarser(coarserMipLevelsSize(kWidth, kHeight, kChannels));
  writeCoarserMipLevels(level0.data(), kWidth, kHeight, kChannels, coarser.data());
  const uint32_t levels = fullMipLevelCount(kWidth, kHeight);
  ASSERT_EQ(levels, 6u);
  size_t offset = 0;
  for (uint32_t l = 1; l < levels; ++l) {
    const size_t count = size_t(mipLevelSize(kWidth, l)) * mipLevelSize(kHeight, l);
    for (uint32_t c = 0; c < kChannels; ++c)
      EXPECT_NEAR(channelMean(coarser.data() + offset, count, c),
                  channelMean(level0.data(), size_t(kWidth) * kHeight, c), 1e-5)
          << "level " << l << " channel " << c;
    offset += count * kChannels;
  }
  EXPECT_EQ(offset, coarser.size());
}

TEST(MipPyramid, ThreeTexelsAverageWithEqualWeights) {
  EXPECT_EQ(downsampleLevel({3, 6, 12}, 3, 1, 1, 1, 1), (std::vector<float>{7}));
  // Five to two: each target texel covers two and a half source texels.
  std::vector<float> two = downsampleLevel({1, 1, 4, 9, 9}, 5, 1, 2, 1, 1);
  EXPECT_NEAR(two[0], (1 + 1 + 0.5 * 4) / 2.5, 1e-6);
  EXPECT_NEAR(two[1], (0.5 * 4 + 9 + 9) / 2.5, 1e-6);
}

std::vector<uint8_t> coarserMipLevels(const std::vector<uint8_t>& level0, uint32_t width, uint32_t height,
                                      uint32_t channels, bool srgb) {
  std::vector<uint8_t> levels(coarserMipLevelsSize(width, height, channels));
  writeCoarserMipLevels(level0.data(), width, height, channels, srgb, levels.data());
  return levels;
}

// sRGB colour averages in linear values (black and white make linear 0.5, sRGB 188), alpha as stored.
TEST(MipPyramid, SrgbColourAveragesInLinearAlphaAsStored) {
  const std::vector<uint8_t> level0 = {0, 0, 0, 0, 255, 255, 255, 255};  // 2 x 1 RGBA: black clear, white opaque
  const std::vector<uint8_t> srgb = coarserMipLevels(level0, 2, 1, 4, true);
  EXPECT_EQ(srgb, (std::vector<uint8_t>{188, 188, 188, 128}));
  const std::vector<uint8_t> linear = coarserMipLevels(level0, 2, 1, 4, false);
  EXPECT_EQ(linear, (std::vector<uint8_t>{128, 128, 128, 128}));
  // A constant sRGB texture stays the same bytes at every level.
  const std::vector<uint8_t> grey(size_t(6) * 5, 77);
  const std::vector<uint8_t> levels = coarserMipLevels(grey, 6, 5, 1, true);
  EXPECT_EQ(levels.size(), size_t(3 * 2 + 1 * 1));
  for (uint8_t v : levels) EXPECT_EQ(v, 77);
  // Every step survives the round trip through linear values.
  for (int v = 0; v < 256; ++v)
    EXPECT_EQ(coarserMipLevels({uint8_t(v), uint8_t(v)}, 2, 1, 1, true), (std::vector<uint8_t>{uint8_t(v)})) << v;
}

// A scene's textures reach the kernel with their pyramids, and a footprint as large as the texture reads its mean.
struct PackedCheckerboard {
  FlatScene flat;
  explicit PackedCheckerboard(uint32_t size, uint32_t square) {
    Scene scene;
    scene.textures = {checkerboardTexture(size, square)};
    flat = FlatScene::build(scene);
  }
  TexelArrays arrays() const { return flat.hostView().texels; }
  Vec4 at(Vec2 uv, Vec2 dx, Vec2 dy, TextureFilter filter) const {
    SceneView view = flat.hostView();
    return sampleTextureFiltered(view.texels, 0, uv, {dx, dy, filter});
  }
};

TEST(TextureFiltering, FootprintsPickTheLevels) {
  PackedCheckerboard t(64, 4);
  const TextureView& view = t.flat.textures[0];
  EXPECT_EQ(view.levels, 7u);
  EXPECT_EQ(t.flat.texelBytes.size(), size_t(64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1));
  const Vec2 uv{18.0f / 64, 34.0f / 64};  // the centre of a black square (texels 16-19, 32-35)
  // No footprint, or the finest filter: the bilinear lookup of level 0.
  EXPECT_EQ(t.at(uv, {}, {}, TextureFilter::Anisotropic).x, sampleTexture(t.arrays(), 0, uv).x);
  EXPECT_EQ(t.at(uv, {1, 0}, {0, 1}, TextureFilter::Finest).x, sampleTexture(t.arrays(), 0, uv).x);
  EXPECT_EQ(sampleTexture(t.arrays(), 0, uv).x, 0.0f);
  // A footprint of the whole texture reads the 1x1 level: the mean, 0.5 (128/255 once stored in 8 bits).
  EXPECT_NEAR(t.at(uv, {1, 0}, {0, 1}, TextureFilter::Trilinear).x, 128.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(t.at(uv, {1, 0}, {0, 1}, TextureFilter::Anisotropic).x, 128.0f / 255.0f, 1e-6f);
  // Two texels across: level 1, whose 4-texel squares are still pure black or white inside.
  EXPECT_NEAR(t.at(uv, {2.0f / 64, 0}, {0, 2.0f / 64}, TextureFilter::Trilinear).x, 0.0f, 1e-6f);
  // Between levels: 8 texels across is level 3 (4-texel squares become half-texels), 0.5 grey wherever it is read;
  // 4 texels, level 2, is black at the square's centre; 5.66 texels lies halfway and blends the two.
  EXPECT_NEAR(t.at(uv, {8.0f / 64, 0}, {0, 8.0f / 64}, TextureFilter::Trilinear).x, 128.0f / 255.0f, 1e-6f);
  EXPECT_NEAR(t.at(uv, {4.0f / 64, 0}, {0, 4.0f / 64}, TextureFilter::Trilinear).x, 0.0f, 1e-6f);
  const float halfway = 4.0f * std::sqrt(2.0f) / 64;
  EXPECT_NEAR(t.at(uv, {halfway, 0}, {0, halfway}, TextureFilter::Trilinear).x, 64.0f / 255.0f, 1e-4f);
}

// A footprint 16 texels long along horizontal stripes 4 texels wide and 1 texel across them (a floor seen at a
// grazing angle): the anisotropic filter stays in the stripe, the trilinear filter, at the longer axis's level,
// blurs it into grey.
TEST(TextureFiltering, AnisotropicKeepsDetailAlongTheShortAxis) {
  Scene scene;
  Texture stripes;
  stripes.width = stripes.height = 64;
  stripes.channels = 1;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) stripes.bytes.push_back((y / 4) % 2 ? 255 : 0);  // horizontal stripes
  scene.textures = {stripes};
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  const Vec2 uv{0.5f, 2.0f / 64};  // the middle of the first (black) stripe
  const Vec2 alongStripes{16.0f / 64, 0}, acrossOneTexel{0, 1.0f / 64};
  const float aniso =
      sampleTextureFiltered(view.texels, 0, uv, {alongStripes, acrossOneTexel, TextureFilter::Anisotropic}).x;
  const float tri =
      sampleTextureFiltered(view.texels, 0, uv, {alongStripes, acrossOneTexel, TextureFilter::Trilinear}).x;
  EXPECT_NEAR(aniso, 0.0f, 1e-6f);
  EXPECT_GT(tri, 0.3f);
}

// The footprint of a cone on a plane: one cone width across, 1/cos of the incidence along; uv per unit of
// length scales it.
TEST(RayCone, FootprintOnAPlaneFollowsTheIncidence) {
  Scene scene;
  Mesh quad;
  quad.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}};
  quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // half a uv unit per world unit
  quad.indices = {0, 2, 1, 0, 3, 2};
  quad.triangleMaterials = {0, 0};
  scene.meshes = {quad};
  scene.instances = {{0, Affine3x4{}}};
  scene.materials = {Material{}};
  FlatScene flat = FlatScene::build(scene);
  SceneView view = flat.hostView();
  Hit hit;
  hit.b1 = 0.2f;
  hit.b2 = 0.3f;
  auto lengthOf = [](Vec2 v) { return std::hypot(v.x, v.y); };
  TextureFootprint headOn = textureFootprint(view, hit, {0, -1, 0}, 0.01f, TextureFilter::Anisotropic);
  EXPECT_NEAR(lengthOf(headOn.dUVdx), 0.005f, 1e-6f);
  EXPECT_NEAR(lengthOf(headOn.dUVdy), 0.005f, 1e-6f);
  EXPECT_NEAR(headOn.dUVdx.x * headOn.dUVdy.x + headOn.dUVdx.y * headOn.dUVdy.y, 0.0f, 1e-9f);
  const float c = std::cos(1.2f), s = std::sin(1.2f);  // about 69 degrees from the normal, travelling along +x
  TextureFootprint slanted = textureFootprint(view, hit, {s, -c, 0}, 0.01f, TextureFilter::Anisotropic);
  EXPECT_NEAR(slanted.dUVdx.x, 0.005f / c, 1e-5f);
  EXPECT_NEAR(slanted.dUVdx.y, 0.0f, 1e-6f);
  EXPECT_NEAR(lengthOf(slanted.dUVdy), 0.005f, 1e-6f);
  EXPECT_EQ(textureFootprint(view, hit, {0, -1, 0}, 0.01f, TextureFilter::Finest).filter, TextureFilter::Finest);
  // A delta bounce hands on the width reached and keeps the spread.
  RayCone cone{0.0f, 0.002f};
  RayCone bounced = cone.afterDeltaBounce(5.0f);
  EXPECT_FLOAT_EQ(bounced.width, 0.01f);
  EXPECT_FLOAT_EQ(bounced.widthAt(5.0f), 0.02f);
}

RenderSettings planeSettings(TextureFilter filter, uint32_t seed) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.maxDepth = 1;
  settings.seed = seed;
  settings.textureFilter = filter;
  return settings;
}

// The receding checkerboard at 1 sample per pixel against a 256-sample render of the same view (the mean of the
// texture under each pixel), by the mean squared error of the luminance. With level 0 alone, a distant pixel is
// black or white at random; with the pyramid, close to the grey its squares average to. Measured (seed 1):
// whole image finest 0.0645, trilinear 0.0135 (4.8 times less), anisotropic 0.0116 (5.6 times less); the rows
// where the plane is far (kFarPlaneFirstRow on) finest 0.140, trilinear 0.0048 (29 times less), anisotropic
// 0.0052 (27 times less). Nearer, where a square spans pixels, what is left is the squares' edges sampled at one
// point per pixel, which no texture filter removes. The bounds leave room for other seeds.
TEST(TextureFilteringRender, RecedingCheckerboardAliasesFarLess) {
  const Scene scene = recedingTexturedPlane(checkerboardTexture(256, 16));
  const Image reference = renderCpu(scene, planeSettings(TextureFilter::Finest, 100), 256);
  double whole[3], far[3];
  for (TextureFilter filter : {TextureFilter::Finest, TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    const Image image = renderCpu(scene, planeSettings(filter, 1), 1);
    whole[int(filter)] = meanSquaredDifference(image, reference);
    far[int(filter)] = meanSquaredDifference(image, reference, kFarPlaneFirstRow, kFarPlaneRows);
    std::printf("filter %d, mean squared error at 1 spp: whole image %.5f, far rows %.5f\n", int(filter),
                whole[int(filter)], far[int(filter)]);
  }
  for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    EXPECT_LT(whole[int(filter)], whole[int(TextureFilter::Finest)] / 4) << int(filter);
    EXPECT_LT(far[int(filter)], far[int(TextureFilter::Finest)] / 15) << int(filter);
  }
}

// The same for the reflection of a textured ceiling in a mirror floor: the cone goes on through the mirror, so the
// reflection, a receding checkerboard twice as far below as the ceiling is above, aliases as little as the
// ceiling. Measured (seed 1), rows below the horizon: finest 0.184, anisotropic 0.0211 (8.7 times less); with the
// cone ended at the mirror, as at a diffuse bounce, both 0.184.
TEST(TextureFilteringRender, ConesGoOnThroughMirrors) {
  const Scene scene = mirroredTexturedCeiling(checkerboardTexture(256, 16));
  RenderSettings settings = planeSettings(TextureFilter::Finest, 100);
  settings.maxDepth = 2;
  const Image reference = renderCpu(scene, settings, 256);
  double mirrored[3];
  for (TextureFilter filter : {TextureFilter::Finest, TextureFilter::Anisotropic}) {
    settings.textureFilter = filter;
    settings.seed = 1;
    mirrored[int(filter)] = meanSquaredDifference(renderCpu(scene, settings, 1), reference, 60, 60);
    std::printf("filter %d, mean squared error at 1 spp below the horizon: %.5f\n", int(filter), mirrored[int(filter)]);
  }
  EXPECT_LT(mirrored[int(TextureFilter::Anisotropic)], mirrored[int(TextureFilter::Finest)] / 4);
}

// Filtering moves no mean: the 1-sample image's mean matches the reference's, and a constant texture (an odd size,
// sRGB) renders the same, pixel for pixel, with every filter.
TEST(TextureFilteringRender, MeansStayTheSame) {
  const Scene checker = recedingTexturedPlane(checkerboardTexture(256, 16));
  const double reference = meanLuminance(renderCpu(checker, planeSettings(TextureFilter::Finest, 100), 64));
  const double filtered = meanLuminance(renderCpu(checker, planeSettings(TextureFilter::Anisotropic, 1), 1));
  EXPECT_NEAR(filtered, reference, 0.01 * reference);

  Texture grey;
  grey.width = 45;
  grey.height = 23;
  grey.channels = 3;
  grey.srgb = true;
  grey.bytes.assign(size_t(45) * 23 * 3, 100);
  const Scene flat = recedingTexturedPlane(grey);
  const Image finest = renderCpu(flat, planeSettings(TextureFilter::Finest, 3), 1);
  for (TextureFilter filter : {TextureFilter::Trilinear, TextureFilter::Anisotropic}) {
    const Image image = renderCpu(flat, planeSettings(filter, 3), 1);
    double largest = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i)
      largest = std::max(largest, double(std::fabs(luminance(image.pixels[i]) - luminance(finest.pixels[i]))));
    EXPECT_LT(largest, 1e-6) << int(filter);
  }
}

// A white diffuse sphere whose base colour comes from a white texture (an odd size) vanishes in the furnace with
// the filtered lookups as without: the image mean is 1 within 4 standard errors.
TEST(TextureFilteringRender, TexturedWhiteSphereVanishesInTheFurnace) {
  Material white;
  white.baseColor = {1, 1, 1};
  white.baseColorTexture = 0;
  Scene scene = furnaceSphere(white);
  Texture texture;
  texture.width = 37;
  texture.height = 19;
  texture.channels = 3;
  texture.srgb = true;
  texture.bytes.assign(size_t(37) * 19 * 3, 255);
  scene.textures = {texture};
  Mesh& sphere = scene.meshes[0];
  for (const Vec3& p : sphere.positions)
    sphere.uvs.push_back({std::atan2(p.z, p.x) / (2 * kPi) + 0.5f, std::acos(std::clamp(p.y, -1.0f, 1.0f)) / kPi});
  RenderSettings settings;
  settings.width = settings.height = 16;
  settings.rouletteDepth = 1000;
  settings.maxDepth = 64;
  PixelStatistics s = luminanceStatistics(renderCpu(scene, settings, 16));
  EXPECT_NEAR(s.mean, 1.0, 4 * s.standardError + 1e-4);
}

}  // namespace
}  // namespace candela::test
