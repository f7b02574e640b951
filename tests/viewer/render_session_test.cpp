#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "app/interactive/animation_clock.h"
#include "app/interactive/render_session.h"
#include "backends/film_display.h"
#include "backends/film_filters.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

// Records what the session asks of it.
struct BackendLog {
  int scenes = 0, cameras = 0, settings = 0, restarts = 0, materialEdits = 0, environmentEdits = 0, transformEdits = 0;
  std::vector<Instance> instances;
  bool acceptMaterials = true;  // whether setMaterials takes the edit or asks for setScene
  uint32_t accumulated = 0;
  std::vector<uint32_t> seeds;
  float intensity = 0.0f, rotation = 0.0f;
  std::vector<Material> materials;
  int renders = 0;
  Camera lastCamera;
  RenderSettings lastSettings;
  bool compiling = false;     // whether startingCompile() says the programs of a frame are still compiling
  bool refuseScenes = false;  // whether setScene throws SceneUnsupported, as a GPU backend does for what it lacks
};

class RecordingBackend final : public Backend {
 public:
  explicit RecordingBackend(BackendLog& log) : log_(log) {}
  std::string name() const override { return "recording"; }
  std::string deviceName() const override { return "none"; }
  void setScene(const Scene& scene) override {
    if (log_.refuseScenes) throw SceneUnsupported("the recording backend refuses every scene");
    ++log_.scenes;
    log_.intensity = scene.environment.intensity;
    log_.rotation = scene.environment.rotationDegrees;
    log_.materials = scene.materials;
    log_.instances = scene.instances;
    restart();
  }
  void setInstanceTransforms(const Scene& scene) override {
    ++log_.transformEdits;
    log_.instances = scene.instances;
    restart();
  }
  bool setMaterials(const std::vector<Material>& materials) override {
    if (!log_.acceptMaterials) return false;
    ++log_.materialEdits;
    log_.materials = materials;
    restart();
    return true;
  }
  void setEnvironment(const Environment& environment) override {
    ++log_.environmentEdits;
    log_.intensity = environment.intensity;
    log_.rotation = environment.rotationDegrees;
    restart();
  }
  void setCamera(const Camera& camera) override {
    ++log_.cameras;
    log_.lastCamera = camera;
    restart();
  }
  void setSettings(const RenderSettings& s) override {
    ++log_.settings;
    log_.seeds.push_back(s.seed);
    log_.lastSettings = s;
    restart();
  }
  FrameStats render(uint32_t spp) override {
    if (log_.compiling) throw std::logic_error("a frame rendered while its programs compile");
    ++log_.renders;
    log_.accumulated += spp;
    return {};
  }
  std::optional<ProgramCompileStatus> startingCompile() const override {
    if (!log_.compiling) return std::nullopt;
    return ProgramCompileStatus{12, 40, 8.1};
  }
  uint32_t accumulatedSamples() const override { return log_.accumulated; }
  void setNextSampleIndex(uint32_t) override {}
  FilmSums readFilm() const override { return {}; }
  void loadFilm(const FilmSums&) override {}
  Image readImage() const override { return {}; }
  Image readEmission() const override { return {}; }
  void setAovsEnabled(bool enabled) override {
    aovs_ = enabled;
    restart();
  }
  bool aovsEnabled() const override { return aovs_; }
  AovImages readAovs() const override { return {}; }
  const FilmFilters& filters() const override { return filters_; }
  const FilmDisplay& display() const override { return display_; }

 private:
  void restart() {
    ++log_.restarts;
    log_.accumulated = 0;
  }
  BackendLog& log_;
  bool aovs_ = false;
  HostFilmFilters filters_{*this};
  HostFilmDisplay display_{*this};
};

struct SessionTest : ::testing::Test {
  BackendLog log;
  RenderSession session{std::make_unique<RecordingBackend>(log)};
  Camera camera = Camera::lookAt({0, 0, -1}, {0, 0, 0}, {0, 1, 0}, 40.0f, 1.0f);
  RenderSettings settings;

  void SetUp() override {
    Scene scene = makeWhiteFurnace();
    session.setScene(scene);
    settings.width = 32;
    settings.height = 24;
  }
};

// --backend auto: a scene the GPU backend refuses renders on the CPU backend, which takes over the session with the
// AOVs, settings and camera the frames ask for.
TEST(SessionFallBack, AnAutoSessionMovesToTheCpuWhereItsBackendRefusesTheScene) {
  BackendLog log, meanwhileLog;
  log.refuseScenes = true;
  log.compiling = true;  // a GPU backend's first start: the CPU renders meanwhile
  RenderSession session(std::make_unique<RecordingBackend>(log), std::make_unique<RecordingBackend>(meanwhileLog),
                        "auto");
  session.setAovsEnabled(true);
  session.setScene(makeWhiteFurnace());
  RenderSettings settings;
  settings.width = 16;
  settings.height = 8;
  const Camera camera = Camera::lookAt({0, 0, -1}, {0, 0, 0}, {0, 1, 0}, 40.0f, 2.0f);
  session.renderFrame(camera, settings, 2, true);
  EXPECT_EQ(session.backend().name(), "cpu");
  EXPECT_EQ(session.backendChanges(), 1u);
  EXPECT_TRUE(session.backend().aovsEnabled());
  EXPECT_EQ(session.accumulatedSamples(), 2u);
  EXPECT_EQ(session.image().width, 16u);
  EXPECT_EQ(meanwhileLog.renders, 0);  // dropped with the refusing backend
}

TEST(SessionFallBack, ARefusalOfARequestedBackendIsThrownOn) {
  for (const char* requested : {"optix", ""}) {
    BackendLog log;
    log.refuseScenes = true;
    RenderSession session(std::make_unique<RecordingBackend>(log), nullptr, requested);
    session.setScene(makeWhiteFurnace());
    RenderSettings settings;
    settings.width = settings.height = 8;
    EXPECT_THROW(session.renderFrame(Camera{}, settings, 1, true), SceneUnsupported) << requested;
  }
}

TEST_F(SessionTest, AccumulatesWhileNothingChanges) {
  for (int i = 0; i < 5; ++i) session.renderFrame(camera, settings, 2, true);
  EXPECT_EQ(session.accumulatedSamples(), 10u);
  EXPECT_EQ(session.restarts(), 1u);
  EXPECT_EQ(log.scenes, 1);
  EXPECT_EQ(log.cameras, 1);
  EXPECT_EQ(log.settings, 1);
}

TEST_F(SessionTest, CameraChangeRestarts) {
  session.renderFrame(camera, settings, 1, true);
  session.renderFrame(camera, settings, 1, true);
  Camera moved = camera;
  moved.position.x += 1e-6f;
  session.renderFrame(moved, settings, 1, true);
  EXPECT_EQ(session.accumulatedSamples(), 1u);
  EXPECT_EQ(session.restarts(), 2u);
  EXPECT_EQ(log.cameras, 2);
  EXPECT_EQ(log.settings, 1);
}

TEST_F(SessionTest, SettingsAndResolutionChangesRestart) {
  session.renderFrame(camera, settings, 1, true);
  RenderSettings deeper = settings;
  deeper.maxDepth += 1;
  session.renderFrame(camera, deeper, 1, true);
  RenderSettings smaller = deeper;
  smaller.width /= 2;
  session.renderFrame(camera, smaller, 1, true);
  EXPECT_EQ(session.restarts(), 3u);
  EXPECT_EQ(session.appliedSettings().width, 16u);
  EXPECT_EQ(session.accumulatedSamples(), 1u);
}

TEST_F(SessionTest, TurningTheDenoiserGuidesOnOrOffRestarts) {
  session.renderFrame(camera, settings, 1, true);
  session.setAovsEnabled(true);
  session.setAovsEnabled(true);
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(session.restarts(), 2u);
  EXPECT_EQ(session.accumulatedSamples(), 1u);
  session.setAovsEnabled(false);
  EXPECT_EQ(session.restarts(), 3u);
}

// The furnace's first instance sliding along x by 1 over 0..2 s.
Scene slidingScene() {
  Scene scene = makeWhiteFurnace();
  AnimationNode node;
  node.translation = {scene.instances[0].objectToWorld.m[3], 0, 0};
  scene.animation.nodes.push_back(node);
  scene.animation.instances.push_back({0, 0, Affine3x4{}});
  AnimationClip clip;
  clip.name = "slide";
  clip.end = 2.0f;
  AnimationChannel channel;
  channel.times = {0.0f, 2.0f};
  channel.values = {{node.translation.x, 0, 0, 0}, {node.translation.x + 1, 0, 0, 0}};
  clip.channels.push_back(channel);
  scene.animation.clips.push_back(clip);
  return scene;
}

TEST_F(SessionTest, ANewAnimationPoseRestartsThroughSetInstanceTransforms) {
  const Scene scene = slidingScene();
  session.setScene(scene);
  session.renderFrame(camera, settings, 1, true);
  EXPECT_TRUE(session.poseAnimation(0, 1.0f));
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(log.transformEdits, 1);
  EXPECT_EQ(log.scenes, 1);  // the pose rebuilt nothing
  EXPECT_EQ(session.restarts(), 2u);
  EXPECT_NEAR(log.instances[0].objectToWorld.m[3], scene.instances[0].objectToWorld.m[3] + 0.5f, 1e-6f);
  // The same pose again changes nothing.
  EXPECT_FALSE(session.poseAnimation(0, 1.0f));
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(log.transformEdits, 1);
  EXPECT_EQ(session.accumulatedSamples(), 2u);
}

TEST(AnimationClock, PlayingWrapsAtTheClipsEndAndPausedStays) {
  const Scene scene = slidingScene();
  AnimationControls controls;
  advanceAnimation(controls, scene.animation, 1.5);
  EXPECT_FLOAT_EQ(controls.time, 1.5f);
  advanceAnimation(controls, scene.animation, 1.0);
  EXPECT_FLOAT_EQ(controls.time, 0.5f);  // 2.5 s wraps into the 2 s clip
  controls.playing = false;
  advanceAnimation(controls, scene.animation, 1.0);
  EXPECT_FLOAT_EQ(controls.time, 0.5f);
  controls.clip = 7;  // out of range: back to the last clip
  controls.time = -3.0f;
  advanceAnimation(controls, scene.animation, 0.0);
  EXPECT_EQ(controls.clip, 0);
  EXPECT_FLOAT_EQ(controls.time, 0.0f);
}

TEST_F(SessionTest, WithoutAccumulationEveryFrameStartsAfreshWithItsOwnSeed) {
  for (int i = 0; i < 4; ++i) session.renderFrame(camera, settings, 3, false);
  EXPECT_EQ(session.accumulatedSamples(), 3u);
  EXPECT_EQ(session.restarts(), 4u);
  ASSERT_EQ(log.seeds.size(), 4u);
  for (size_t i = 1; i < log.seeds.size(); ++i) EXPECT_NE(log.seeds[i], log.seeds[i - 1]);
}

TEST_F(SessionTest, EnvironmentAdjustmentsApplyToTheScenesOwn) {
  Scene scene = makeWhiteFurnace();
  scene.environment.intensity = 2.0f;
  scene.environment.rotationDegrees = 30.0f;
  session.setScene(scene);
  session.renderFrame(camera, settings, 1, true);
  session.setEnvironment(1.0f, 0.0f);  // unchanged: no edit
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(log.scenes, 1);  // SetUp's scene was replaced before any frame
  EXPECT_EQ(log.environmentEdits, 0);
  session.setEnvironment(2.5f, -45.0f);
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(log.scenes, 1);  // the backend takes the environment alone
  EXPECT_EQ(log.environmentEdits, 1);
  EXPECT_FLOAT_EQ(log.intensity, 5.0f);
  EXPECT_FLOAT_EQ(log.rotation, -15.0f);
  EXPECT_EQ(session.accumulatedSamples(), 1u);
  EXPECT_EQ(session.restarts(), 2u);
  // A new scene keeps the adjustments, relative to its own values.
  session.setScene(makeWhiteFurnace());
  session.renderFrame(camera, settings, 1, true);
  EXPECT_FLOAT_EQ(log.intensity, 2.5f);
  EXPECT_FLOAT_EQ(log.rotation, -45.0f);
  EXPECT_EQ(session.summary().triangles, session.scene().triangleCount());
}

TEST_F(SessionTest, MaterialOverridesApplyToTheScenesOwnMaterials) {
  Scene scene = makeCornellBox();
  for (Material& m : scene.materials) m.type = MaterialType::Pbr;
  session.setScene(scene);
  session.renderFrame(camera, settings, 1, true);
  MaterialOverrides overrides;
  overrides.roughness = 0.1f;
  session.setMaterialOverrides(overrides);
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(session.restarts(), 2u);
  EXPECT_EQ(log.scenes, 1);  // the materials went alone
  EXPECT_EQ(log.materialEdits, 1);
  ASSERT_EQ(log.materials.size(), scene.materials.size());
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    EXPECT_EQ(log.materials[i].roughness, applyOverrides(scene.materials[i], overrides).roughness);
    EXPECT_FLOAT_EQ(log.materials[i].roughness, 0.1f);
  }
  // Switching an override off brings back each material's own value, not the last override's.
  session.setMaterialOverrides({});
  session.renderFrame(camera, settings, 1, true);
  for (size_t i = 0; i < scene.materials.size(); ++i)
    EXPECT_EQ(log.materials[i].roughness, scene.materials[i].roughness);
}

TEST_F(SessionTest, MaterialsTheBackendRefusesGoWithTheWholeScene) {
  session.renderFrame(camera, settings, 1, true);
  log.acceptMaterials = false;
  MaterialOverrides overrides;
  overrides.shading = ShadingModel::Disney;
  session.setMaterialOverrides(overrides);
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(log.scenes, 2);
  EXPECT_EQ(log.materialEdits, 0);
  EXPECT_EQ(log.materials[0].type, MaterialType::Disney);
  EXPECT_EQ(session.restarts(), 2u);
}

// A GPU backend whose programs compile for the first `compilingFrames` frames, with a CPU backend meanwhile.
struct MeanwhileTest : ::testing::Test {
  BackendLog gpu, cpu;
  RenderSession session{std::make_unique<RecordingBackend>(gpu), std::make_unique<RecordingBackend>(cpu)};
  Camera camera = Camera::lookAt({0, 0, -1}, {0, 0, 0}, {0, 1, 0}, 40.0f, 1.0f);
  RenderSettings settings;
  static constexpr int compilingFrames = 3;

  void SetUp() override {
    gpu.compiling = true;
    session.setScene(makeWhiteFurnace());
    settings.width = 32;
    settings.height = 24;
    settings.maxDepth = 5;
  }
};

TEST_F(MeanwhileTest, RendersMeanwhileThenHandsOverOnceWithTheSameViewAndAFreshFilm) {
  for (int i = 0; i < compilingFrames; ++i) {
    camera.position.x = 0.1f * float(i);  // the camera moves while the programs compile
    session.renderFrame(camera, settings, 2, true);
    EXPECT_EQ(session.backendChanges(), 0u);
    EXPECT_EQ(meanwhileNote(session),
              "GPU programs compiling, 12/40, 8.1 s: frames on the recording backend meanwhile");
  }
  EXPECT_EQ(cpu.renders, compilingFrames);
  EXPECT_EQ(gpu.renders, 0);
  session.renderFrame(camera, settings, 2, true);  // still compiling: the CPU's film accumulates
  EXPECT_EQ(session.accumulatedSamples(), 4u);
  const uint64_t restartsBefore = session.restarts();

  gpu.compiling = false;
  for (int i = 0; i < 3; ++i) session.renderFrame(camera, settings, 2, true);
  EXPECT_EQ(session.backendChanges(), 1u);
  EXPECT_EQ(gpu.renders, 3);
  EXPECT_EQ(cpu.renders, compilingFrames + 1);
  EXPECT_EQ(session.restarts(), restartsBefore + 1);  // the GPU's film starts at the handover
  EXPECT_EQ(session.accumulatedSamples(), 6u);
  EXPECT_TRUE(meanwhileNote(session).empty());
  EXPECT_FALSE(session.startingCompile());
  // The GPU backend had every change while it compiled: the scene, the settings and the last camera.
  EXPECT_EQ(gpu.scenes, 1);
  EXPECT_EQ(gpu.lastSettings.maxDepth, settings.maxDepth);
  EXPECT_EQ(gpu.lastSettings.width, settings.width);
  EXPECT_TRUE(sameCamera(gpu.lastCamera, camera));
  EXPECT_TRUE(sameCamera(cpu.lastCamera, gpu.lastCamera));
}

TEST_F(MeanwhileTest, AovsTurnedOnMeanwhileReachTheGpuBackend) {
  session.renderFrame(camera, settings, 1, true);
  session.setAovsEnabled(true);
  gpu.compiling = false;
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(session.backendChanges(), 1u);
  EXPECT_TRUE(session.backend().aovsEnabled());
}

TEST_F(MeanwhileTest, ABackendReadyAtOnceRendersFromTheFirstFrame) {
  gpu.compiling = false;
  session.renderFrame(camera, settings, 1, true);
  EXPECT_EQ(gpu.renders, 1);
  EXPECT_EQ(cpu.renders, 0);
  EXPECT_EQ(session.backendChanges(), 1u);
  EXPECT_EQ(session.restarts(), 1u);
}

TEST(SceneSummary, CountsOverInstancesAndBoundsInWorldSpace) {
  Scene scene = makeCornellBox();
  Instance copy = scene.instances[0];
  copy.objectToWorld.m[3] = 10.0f;  // shifted 10 m along x
  scene.instances.push_back(copy);
  SceneSummary s = summarizeScene(scene);
  EXPECT_EQ(s.instances, 2u);
  EXPECT_EQ(s.meshes, 1u);
  EXPECT_EQ(s.triangles, 2 * scene.meshes[0].triangleCount());
  EXPECT_EQ(s.vertices, 2 * scene.meshes[0].positions.size());
  EXPECT_EQ(s.materials, 4u);
  EXPECT_NEAR(s.bounds.lo.x, 0.0f, 1e-6f);
  EXPECT_NEAR(s.bounds.hi.x, 10.556f, 1e-4f);
}

}  // namespace
}  // namespace candela
