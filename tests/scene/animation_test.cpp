// glTF node animations: channel sampling, node transforms at given times against hand-computed ones, hostile
// animation data, and renders at two times.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "app/animation_render.h"
#include "app/scene_loading.h"
#include "backends/cpu/cpu_backend.h"
#include "scene/animation_player.h"
#include "scene/cache/scene_cache.h"
#include "scene/gltf_cache_round_trip.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_test_files.h"
#include "support/animated_gltf.h"
#include "support/vector_expectations.h"

namespace candela {
namespace {

using nlohmann::json;
using test::AnimatedFile;
using test::kSqrtHalf;
using test::TempFolder;

using test::expectNear;

AnimationChannel channel(AnimatedProperty property, AnimationInterpolation interpolation, std::vector<float> times,
                         std::vector<Vec4> values) {
  AnimationChannel c;
  c.property = property;
  c.interpolation = interpolation;
  c.times = std::move(times);
  c.values = std::move(values);
  return c;
}

TEST(AnimationSampling, LinearStepAndClampedEnds) {
  const AnimationChannel linear =
      channel(AnimatedProperty::Translation, AnimationInterpolation::Linear, {1, 3}, {{0, 0, 0, 0}, {4, -2, 8, 0}});
  const Vec4 quarter = sampleChannel(linear, 1.5f);
  expectNear({quarter.x, quarter.y, quarter.z}, {1, -0.5f, 2});
  EXPECT_EQ(sampleChannel(linear, 0.0f).x, 0.0f);  // before the first key: the first value
  EXPECT_EQ(sampleChannel(linear, 9.0f).x, 4.0f);  // after the last: the last
  EXPECT_EQ(sampleChannel(linear, std::numeric_limits<float>::quiet_NaN()).x, 0.0f);

  const AnimationChannel step = channel(AnimatedProperty::Scale, AnimationInterpolation::Step, {0, 1, 2},
                                        {{1, 1, 1, 0}, {2, 2, 2, 0}, {3, 3, 3, 0}});
  EXPECT_EQ(sampleChannel(step, 0.999f).x, 1.0f);
  EXPECT_EQ(sampleChannel(step, 1.0f).x, 2.0f);
  EXPECT_EQ(sampleChannel(step, 1.5f).x, 2.0f);
  EXPECT_EQ(sampleChannel(step, 2.5f).x, 3.0f);
}

TEST(AnimationSampling, RotationsSlerpAlongTheShorterArc) {
  // 0 and 90 degrees about z; the second key is given as the negated quaternion, the same rotation.
  const AnimationChannel rotation = channel(AnimatedProperty::Rotation, AnimationInterpolation::Linear, {0, 1},
                                            {{0, 0, 0, 1}, {0, 0, -kSqrtHalf, -kSqrtHalf}});
  const Vec4 half = sampleChannel(rotation, 0.5f);
  const float s = std::sin(kPi / 8), c = std::cos(kPi / 8);  // 45 degrees: half angle 22.5
  EXPECT_NEAR(half.x, 0.0f, 1e-6f);
  EXPECT_NEAR(half.y, 0.0f, 1e-6f);
  EXPECT_NEAR(std::fabs(half.z), s, 1e-6f);
  EXPECT_NEAR(std::fabs(half.w), c, 1e-6f);
  EXPECT_GT(half.z * half.w, 0.0f);  // a positive rotation about z, not the long way round
  // A third of the way: 30 degrees, which a normalised linear blend of the quaternions would not give.
  const Vec4 third = sampleChannel(rotation, 1.0f / 3.0f);
  EXPECT_NEAR(std::fabs(third.z), std::sin(kPi / 12), 1e-5f);
}

TEST(AnimationSampling, CubicSplineUsesTangentsScaledByTheKeyInterval) {
  // Keys at 0 and 2 s with values 0 and 1, out-tangent 3 per second at the first, in-tangent -1 at the second.
  const AnimationChannel cubic =
      channel(AnimatedProperty::Translation, AnimationInterpolation::CubicSpline, {0, 2},
              {{9, 9, 9, 0}, {0, 0, 0, 0}, {3, 0, 0, 0}, {-1, 0, 0, 0}, {1, 0, 0, 0}, {9, 9, 9, 0}});
  // s = 0.5: h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125; tangents times 2 s: 6 and -2.
  EXPECT_NEAR(sampleChannel(cubic, 1.0f).x, 0.5f * 0 + 0.125f * 6 + 0.5f * 1 - 0.125f * -2, 1e-6f);
  EXPECT_EQ(sampleChannel(cubic, 0.0f).x, 0.0f);  // the value, not the in-tangent
  EXPECT_EQ(sampleChannel(cubic, 5.0f).x, 1.0f);
}

Scene loadAnimated(const TempFolder& folder, AnimatedFile file = {}) {
  LoadWarnings warnings;
  return loadGltf(file.write(folder.path()), warnings);
}

// Where the quad's object-space point (1, 0, 0) lands.
Vec3 quadPoint(const Scene& scene) { return scene.instances.at(0).objectToWorld.point({1, 0, 0}); }

TEST(GltfAnimation, NodeTransformsAtGivenTimesAreTheHandComputedOnes) {
  TempFolder folder;
  Scene scene = loadAnimated(folder);
  ASSERT_EQ(scene.animation.clips.size(), 2u);
  EXPECT_EQ(scene.animation.clips[0].name, "Move");
  EXPECT_EQ(scene.animation.clips[0].start, 0.0f);
  EXPECT_EQ(scene.animation.clips[0].end, 2.0f);
  ASSERT_EQ(scene.animation.instances.size(), 1u);
  expectNear(quadPoint(scene), {1, 1, 0});  // the rest pose: node 1's translation only

  const AnimationPlayer player(scene);
  player.pose(scene, 0, 0.0f);
  expectNear(quadPoint(scene), {1, 1, 0});
  // 0.5 s: node 0 at (1, 0, 0), turned 22.5 degrees; node 1 at (0, 1, 0), scale 1. The point (1, 1, 0) turned.
  player.pose(scene, 0, 0.5f);
  const float c = std::cos(kPi / 8), s = std::sin(kPi / 8);
  expectNear(quadPoint(scene), {1 + c - s, s + c, 0});
  // 1 s: node 0 at (2, 0, 0), turned 45 degrees; node 1 scaled by 3: (3, 1, 0) turned is (2, 4, 0) / sqrt 2.
  player.pose(scene, 0, 1.0f);
  expectNear(quadPoint(scene), {2 + 2 * kSqrtHalf, 4 * kSqrtHalf, 0});
  // 2 s and after: node 0 at (2, 4, 0), turned 90 degrees: (3, 1, 0) becomes (-1, 3, 0).
  player.pose(scene, 0, 7.0f);
  expectNear(quadPoint(scene), {1, 7, 0});

  // "Bounce" at 0.5 s: y = h00 * 1 + h10 * 2 + h01 * 1 = 0.5 + 0.25 + 0.5; node 0 at rest.
  player.pose(scene, 1, 0.5f);
  expectNear(quadPoint(scene), {1, 1.25f, 0});
  player.pose(scene, -1, 0.5f);  // the rest pose again
  expectNear(quadPoint(scene), {1, 1, 0});
}

TEST(GltfAnimation, ClipsAreChosenByNameOrIndex) {
  TempFolder folder;
  const Scene scene = loadAnimated(folder);
  EXPECT_EQ(findClip(scene.animation, ""), 0u);
  EXPECT_EQ(findClip(scene.animation, "Bounce"), 1u);
  EXPECT_EQ(findClip(scene.animation, "1"), 1u);
  try {
    findClip(scene.animation, "Walk");
    FAIL() << "an unknown clip was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no animation 'Walk' (animations: 0 'Move', 1 'Bounce')");
  }
}

TEST(GltfAnimation, AnInstanceScaledToNothingAtRestIsHiddenNotDropped) {
  TempFolder folder;
  AnimatedFile file;
  file.gltf["nodes"][1]["scale"] = {0, 0, 0};  // grows to 3 at 1 s
  const std::string path = file.write(folder.path());
  SceneLoadOptions options;
  Scene scene = loadScene(path, options);
  ASSERT_EQ(scene.instances.size(), 1u);  // the scene's repair kept it
  ASSERT_EQ(scene.animation.instances.size(), 1u);
  EXPECT_LT(length(scene.instances[0].objectToWorld.vector({1, 0, 0})), 1e-5f);
  const AnimationPlayer player(scene);
  player.pose(scene, 0, 1.0f);
  expectNear(quadPoint(scene), {2 + 2 * kSqrtHalf, 4 * kSqrtHalf, 0});
}

std::string loadError(AnimatedFile file) {
  TempFolder folder;
  LoadWarnings warnings;
  try {
    loadGltf(file.write(folder.path()), warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(GltfAnimation, HostileKeysAreOneLineNamingTheSampler) {
  {
    AnimatedFile file;
    const int times = file.add({0, std::numeric_limits<float>::quiet_NaN(), 2}, "SCALAR");
    file.gltf["animations"][0]["samplers"][0]["input"] = times;
    EXPECT_NE(loadError(file).find("animations[0].samplers[0].input: key time 1 is not a finite number"),
              std::string::npos)
        << loadError(file);
  }
  {
    AnimatedFile file;
    const int times = file.add({0, 1, 1}, "SCALAR");
    file.gltf["animations"][0]["samplers"][0]["input"] = times;
    EXPECT_NE(loadError(file).find("animations[0].samplers[0].input: key times must increase, but key 2"),
              std::string::npos)
        << loadError(file);
  }
  {
    AnimatedFile file;
    const int values = file.add({0, 0, 0, 1, 1, 1}, "VEC3");  // two values for three keys
    file.gltf["animations"][0]["samplers"][0]["output"] = values;
    EXPECT_NE(loadError(file).find("animations[0].samplers[0].output: 2 values for 3 key times (LINEAR needs 3)"),
              std::string::npos)
        << loadError(file);
  }
  {
    AnimatedFile file;
    file.gltf["animations"][1]["samplers"][0]["output"] = file.add({0, 1, 0, 0, 1, 0}, "VEC3");
    EXPECT_NE(loadError(file).find("animations[1].samplers[0].output: 2 values for 2 key times (CUBICSPLINE needs 6)"),
              std::string::npos)
        << loadError(file);
  }
  {
    AnimatedFile file;
    file.gltf["animations"][0]["samplers"][0]["interpolation"] = "BEZIER";
    EXPECT_NE(loadError(file).find("'BEZIER' is not LINEAR, STEP or CUBICSPLINE"), std::string::npos)
        << loadError(file);
  }
  {
    AnimatedFile file;
    file.gltf["animations"][0]["channels"][0]["target"]["node"] = 17;
    EXPECT_NE(loadError(file).find("animations[0].channels[0].target.node: node 17 does not exist"), std::string::npos)
        << loadError(file);
  }
}

TEST(GltfAnimation, MorphWeightChannelsOfNodesWithoutTargetsAreIgnoredWithOneWarning) {
  TempFolder folder;
  AnimatedFile file;
  const int weights = file.add({0, 1}, "SCALAR");
  file.gltf["animations"][0]["samplers"].push_back({{"input", weights}, {"output", weights}});
  for (int i = 0; i < 2; ++i)
    file.gltf["animations"][0]["channels"].push_back({{"sampler", 3}, {"target", {{"node", 1}, {"path", "weights"}}}});
  LoadWarnings warnings;
  const Scene scene = loadGltf(file.write(folder.path()), warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("2 animation channels of morph target weights are ignored: their nodes have no "
                                      "morph targets"),
            std::string::npos);
  EXPECT_EQ(scene.animation.clips[0].channels.size(), 3u);
}

// Mean brightness of the left and right halves of an image.
std::pair<double, double> halves(const Image& image) {
  double left = 0, right = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) (x < image.width / 2 ? left : right) += image.at(x, y).x;
  const double n = double(image.width / 2) * image.height;
  return {left / n, right / n};
}

TEST(GltfAnimation, RendersAtTwoTimesDifferWhereTheQuadMoved) {
  TempFolder folder;
  AnimatedFile file;
  // "Move" becomes a slide of node 0 from x = -2 to x = 2 over 1 s, without turning or scaling.
  file.gltf["animations"][0]["samplers"][0]["output"] = file.add({-2, -1, 0, 2, -1, 0, 2, -1, 0}, "VEC3");
  file.gltf["animations"][0]["channels"] = {file.gltf["animations"][0]["channels"][0]};
  Scene scene = loadScene(file.write(folder.path()), SceneLoadOptions{});
  const AnimationPlayer player(scene);
  CpuBackend backend;
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.seed = 3;
  backend.setScene(scene);
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(48.0f / 32.0f));
  auto renderAt = [&](float time) {
    player.pose(scene, 0, time);
    backend.setInstanceTransforms(scene);
    backend.render(2);
    return halves(backend.readImage());
  };
  const auto [leftAtStart, rightAtStart] = renderAt(0.0f);
  const auto [leftAtEnd, rightAtEnd] = renderAt(1.0f);
  EXPECT_GT(leftAtStart, 0.01);  // the quad covers about 2% of a half
  EXPECT_EQ(rightAtStart, 0.0);
  EXPECT_EQ(leftAtEnd, 0.0);
  EXPECT_GT(rightAtEnd, 0.01);
}

TEST(GltfAnimation, ASceneFilePlacingAModelTwiceAnimatesBothPlacements) {
  TempFolder folder;
  AnimatedFile file;
  file.write(folder.path());
  const std::string scenePath = folder.write("scene.json", R"({"models": [{"file": "animated.gltf"},
                                   {"file": "animated.gltf", "transform": {"translate": [0, 0, -5]}}]})");
  Scene scene = loadScene(scenePath, SceneLoadOptions{});
  ASSERT_EQ(scene.instances.size(), 2u);
  ASSERT_EQ(scene.animation.instances.size(), 2u);
  ASSERT_EQ(scene.animation.clips.size(), 2u);
  EXPECT_EQ(scene.animation.clips[0].channels.size(), 6u);  // "Move" of both placements plays as one
  AnimationPlayer(scene).pose(scene, 0, 7.0f);
  expectNear(scene.instances[0].objectToWorld.point({1, 0, 0}), {1, 7, 0});
  expectNear(scene.instances[1].objectToWorld.point({1, 0, 0}), {1, 7, -5});
}

TEST(GltfAnimation, TheSceneCacheKeepsTheAnimation) {
  TempFolder folder;
  AnimatedFile file;
  const test::GltfCacheRoundTrip cache(folder, file.write(folder.path()));
  const Scene& scene = cache.loaded();
  CachedScene read;
  ASSERT_EQ(cache.writeAndRead(scene, read), SceneCacheRead::Hit);
  ASSERT_EQ(read.scene.animation.clips.size(), 2u);
  ASSERT_EQ(read.scene.animation.nodes.size(), scene.animation.nodes.size());
  EXPECT_EQ(read.scene.animation.clips[1].name, "Bounce");
  EXPECT_EQ(read.scene.animation.clips[1].channels[0].interpolation, AnimationInterpolation::CubicSpline);
  Scene posed = read.scene;
  AnimationPlayer(posed).pose(posed, 0, 1.0f);
  expectNear(quadPoint(posed), {2 + 2 * kSqrtHalf, 4 * kSqrtHalf, 0});

  // A cache file whose animation refers to a missing instance is not trusted.
  Scene broken = scene;
  broken.animation.instances[0].instance = 5;
  EXPECT_EQ(cache.refusal(broken), "an animated instance refers to a missing instance or node");
}

TEST(FrameSequence, FileNamesReplaceTheLastRunOfHashes) {
  EXPECT_EQ(frameFileName("out_####.png", 7), "out_0007.png");
  EXPECT_EQ(frameFileName("out_##.exr", 123), "out_123.exr");                   // wider numbers are not cut
  EXPECT_EQ(frameFileName("a#b/shot_###_v##.png", 5), "a#b/shot_###_v05.png");  // in the file name only
  EXPECT_EQ(frameFileName("renders/out.png", 12), "renders/out_0012.png");
  EXPECT_EQ(frameFileName("out", 0), "out_0000");
}

TEST(FrameSequence, RangesAreWholeNumbersInOrder) {
  const FrameRange range = parseFrameRange("3:48");
  EXPECT_EQ(range.first, 3);
  EXPECT_EQ(range.last, 48);
  EXPECT_EQ(parseFrameRange("0:0").last, 0);
  for (const char* bad : {"48", "5:2", "-1:3", "1:x", "1.5:3", ":3", "1:", "1:99999999", " 1:2"})
    EXPECT_THROW(parseFrameRange(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace candela
