#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "app/scene_loading.h"
#include "io/file_bytes.h"
#include "kernel/camera.h"
#include "scene/cache/scene_cache.h"
#include "scene/flat_scene.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

Scene loadModel(const std::string& path, LoadWarnings& warnings, SharedModelAssets& shared) {
  return path.ends_with(".obj") ? loadObj(path, warnings, OutsidePaths::Refused, &shared)
                                : loadGltf(path, warnings, OutsidePaths::Refused, &shared);
}

const char* kTriangleObj = "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";

std::string errorOf(const TempFolder& dir, const std::string& json) {
  LoadWarnings warnings;
  try {
    loadSceneFile(dir.write("s.json", json), &loadModel, warnings);
  } catch (const LoadError& e) {
    std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "expected a LoadError for " << json;
  return {};
}

TEST(SceneFile, ModelsTransformsOverridesCameraEnvironmentAndSettings) {
  TempFolder dir;
  dir.write("models/t.obj", kTriangleObj);
  dir.write("models/t.mtl", "newmtl red\nKd 1 0 0\n");
  LoadWarnings warnings;
  Scene s = loadSceneFile(dir.write("s.json", R"({
    "models": [
      {"file": "models/t.obj"},
      {"file": "models/t.obj", "transform": {"translate": [10, 0, 0], "rotate_degrees": [0, 90, 0], "scale": 2},
       "materials": {"red": {"type": "glass", "ior": 1.7, "base_color": [1, 1, 1]}, "blue": {}}}
    ],
    "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_degrees": 30, "aperture_radius": 0.05,
               "focus_distance": 4},
    "environment": {"radiance": [0.5, 0.5, 0.5], "intensity": 2, "visible": false},
    "render": {"width": 320, "height": 200, "spp": 8, "max_depth": 4},
    "colour": "unknown keys are warned about"
  })"),
                          &loadModel, warnings);
  validateScene(s);
  ASSERT_EQ(s.meshes.size(), 2u);
  ASSERT_EQ(s.instances.size(), 2u);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].type, MaterialType::Diffuse);
  EXPECT_EQ(s.materials[1].type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(s.materials[1].ior, 1.7f);
  EXPECT_EQ(s.meshes[1].triangleMaterials[0], 1u);
  // (1, 0, 0) scaled by 2, turned 90 degrees about +Y to (0, 0, -2), moved by (10, 0, 0).
  Vec3 p = s.instances[1].objectToWorld.point({1, 0, 0});
  EXPECT_NEAR(p.x, 10.0f, 1e-5f);
  EXPECT_NEAR(p.z, -2.0f, 1e-5f);
  EXPECT_FALSE(s.cameraMissing);
  EXPECT_FLOAT_EQ(s.camera.apertureRadius, 0.05f);
  Camera c = s.camera.toCamera(1.6f);
  EXPECT_FLOAT_EQ(c.lensRadius, 0.05f);
  EXPECT_FLOAT_EQ(c.focusDistance, 4.0f);
  EXPECT_FLOAT_EQ(s.environment.radiance.x, 0.5f);
  EXPECT_FLOAT_EQ(s.environment.intensity, 2.0f);
  EXPECT_FALSE(s.environment.visibleToCamera);
  EXPECT_EQ(s.renderHints.width, 320u);
  EXPECT_EQ(s.renderHints.samplesPerPixel, 8u);
  std::string all;
  for (const auto& w : warnings.messages) all += w + "\n";
  EXPECT_NE(all.find("colour: unknown key"), std::string::npos) << all;
  EXPECT_NE(all.find("materials.blue: no material of that name"), std::string::npos) << all;
}

// Any finite rotation is an angle: 3e38 degrees, which in radians would overflow to infinity and make every
// environment sample NaN, is reduced exactly to the turn it means.
TEST(SceneFile, AHugeEnvironmentRotationIsReducedToOneTurn) {
  TempFolder dir;
  dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  LoadWarnings warnings;
  Scene s = loadSceneFile(dir.write("s.json", R"({"models": [{"file": "t.obj"}],
      "environment": {"radiance": [1, 1, 1], "rotation_degrees": 3e38}})"),
                          &loadModel, warnings);
  EXPECT_EQ(s.environment.rotationDegrees, std::fmod(3e38f, 360.0f));
  EXPECT_GE(s.environment.rotationDegrees, 0.0f);
  EXPECT_LT(s.environment.rotationDegrees, 360.0f);
  // A scene that holds such an angle otherwise (a cache, the viewer) still gets a finite rotation.
  s.environment.rotationDegrees = 3e38f;
  const FlatScene flat = FlatScene::build(s);
  EXPECT_TRUE(std::isfinite(flat.environment.rotationCos) && std::isfinite(flat.environment.rotationSin));
}

TEST(SceneFile, AFileNamedByManyModelsIsLoadedOnceAndInstanced) {
  TempFolder dir;
  dir.write("models/t.obj", kTriangleObj);
  dir.write("models/t.mtl", "newmtl red\nKd 1 0 0\n");
  size_t loads = 0;
  ModelLoader counting = [&](const std::string& path, LoadWarnings& w, SharedModelAssets& shared) {
    ++loads;
    return loadModel(path, w, shared);
  };
  LoadWarnings warnings;
  Scene s = loadSceneFile(dir.write("s.json", R"({"models": [
      {"file": "models/t.obj"},
      {"file": "models/t.obj", "transform": {"translate": [10, 0, 0]}},
      {"file": "models/../models/t.obj", "transform": {"translate": [20, 0, 0]}},
      {"file": "models/t.obj", "materials": {"red": {"type": "mirror"}}}
    ]})"),
                          counting, warnings);
  validateScene(s);
  EXPECT_EQ(loads, 2u);  // the one with other material overrides needs its own materials
  ASSERT_EQ(s.meshes.size(), 2u);
  ASSERT_EQ(s.instances.size(), 4u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(s.instances[size_t(i)].meshId, 0u);
  EXPECT_EQ(s.instances[3].meshId, 1u);
  EXPECT_NEAR(s.instances[1].objectToWorld.point({0, 0, 0}).x, 10.0f, 1e-6f);
  EXPECT_NEAR(s.instances[2].objectToWorld.point({0, 0, 0}).x, 20.0f, 1e-6f);
  EXPECT_EQ(s.materials.size(), 2u);
}

// Many OBJ files that all name one material library: the library is parsed once, each model keeps only the
// materials its faces use, and each texture is decoded and held once for the whole scene.
TEST(SceneFile, ModelsSharingAMaterialLibraryShareItsTextures) {
  TempFolder dir;
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  dir.write("tex/a.png", std::string(png.begin(), png.end()));
  dir.write("tex/b.png", std::string(png.begin(), png.end()));
  dir.write("lib.mtl",
            "newmtl a\nKd 1 1 1\nmap_Kd tex/a.png\nnewmtl b\nKd 1 1 1\nmap_Kd tex/b.png\n"
            "newmtl unused\nKd 1 1 1\nmap_Kd tex/missing.png\n");
  std::string models;
  for (int i = 0; i < 6; ++i) {
    std::string name = "m" + std::to_string(i) + ".obj";
    dir.write(name,
              std::string("mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl ") + (i % 2 ? "a" : "b") + "\nf 1 2 3\n");
    models += std::string(i ? "," : "") + R"({"file": ")" + name + R"("})";
  }
  LoadWarnings warnings;
  Scene s = loadSceneFile(dir.write("s.json", R"({"models": [)" + models + "]}"), &loadModel, warnings);
  validateScene(s);
  ASSERT_EQ(s.materials.size(), 6u);  // one used material per model
  EXPECT_EQ(s.textures.size(), 2u);
  for (size_t m = 0; m < s.materials.size(); ++m)
    EXPECT_EQ(s.materials[m].baseColorTexture, s.materials[m % 2].baseColorTexture);
  EXPECT_NE(s.materials[0].baseColorTexture, s.materials[1].baseColorTexture);
  // The unused material's missing texture is never looked for.
  for (const std::string& w : warnings.messages) EXPECT_EQ(w.find("missing.png"), std::string::npos) << w;
}

TEST(SceneFile, ErrorsNameTheJsonPathOrLine) {
  TempFolder dir;
  dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(errorOf(dir, "{\n  \"models\": [\n    {\"file\": \"t.obj\"},,\n  ]\n}").find("s.json:3:23: invalid JSON"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "t.obj", "transform": {"scale": "big"}}]})")
                .find("s.json: models[0].transform.scale: expected 3 numbers"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"camera": {}})").find("s.json: 'models' is missing"), std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "t.obj"}], "camera": {"position": [0,0,0], "target": [0,0,0]}})")
                .find("camera: position and target coincide"),
            std::string::npos);
  EXPECT_NE(
      errorOf(dir, R"({"models": [{"file": "t.obj"}], "render": {"spp": 0}})").find("render.spp: expected a whole"),
      std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "other.json"}]})").find("models[0].file: models must be"),
            std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "missing.obj"}]})").find("missing.obj"), std::string::npos);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "t.obj", "materials": {"default": {"type": "velvet"}}}]})")
                .find("models[0].materials.default.type: unknown material type 'velvet'"),
            std::string::npos);
}

// A material override can make a diffuse transmitter: `base_color` reflects, `transmittance` transmits.
TEST(SceneFile, OverridesMakeDiffuseTransmission) {
  TempFolder dir;
  dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  LoadWarnings warnings;
  Scene s = loadSceneFile(dir.write("s.json", R"({"models": [{"file": "t.obj", "materials": {"default":
      {"type": "diffuse-transmission", "base_color": [0.2, 0.3, 0.4], "transmittance": [0.5, 0.4, 0.3]}}}]})"),
                          &loadModel, warnings);
  ASSERT_FALSE(s.materials.empty());
  const Material& m = s.materials[s.meshes[0].triangleMaterials[0]];
  EXPECT_EQ(m.type, MaterialType::DiffuseTransmission);
  EXPECT_EQ(m.transmittance.y, 0.4f);
  EXPECT_NE(errorOf(dir, R"({"models": [{"file": "t.obj", "materials": {"default": {"transmittance": [1, -1, 1]}}}]})")
                .find("colours must not be negative"),
            std::string::npos);
}

// Rays through one film point from anywhere on the lens meet on the focus plane; a pinhole ignores the lens.
TEST(ThinLensCamera, RaysMeetOnTheFocusPlane) {
  Camera c = Camera::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40.0f, 1.5f);
  c.lensRadius = 0.1f;
  c.focusDistance = 3.0f;
  Vec3 meet{};
  for (int i = 0; i < 16; ++i) {
    Ray r = c.generateRay(30.0f, 12.0f, 64, 48, {float(i % 4) / 4.0f + 0.1f, float(i / 4) / 4.0f + 0.1f});
    float t = (-3.0f - r.origin.z) / r.direction.z;
    Vec3 p = r.origin + r.direction * t;
    if (i == 0) meet = p;
    EXPECT_NEAR(p.x, meet.x, 1e-5f);
    EXPECT_NEAR(p.y, meet.y, 1e-5f);
    EXPECT_LE(length(Vec3{r.origin.x, r.origin.y, 0}), 0.1f + 1e-6f);
  }
  Camera pinhole = Camera::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 40.0f, 1.5f);
  EXPECT_EQ(pinhole.generateRay(30.0f, 12.0f, 64, 48, {0.9f, 0.9f}).origin.x, 0.0f);
}

TEST(SceneLoading, FramesScenesWithoutCamera) {
  TempFolder dir;
  Scene s = loadScene(dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_FALSE(s.cameraMissing);
  // The camera looks at the centre of the bounds from outside them.
  EXPECT_NEAR(s.camera.target.x, 0.5f, 1e-6f);
  EXPECT_GT(s.camera.eye.z, 1.0f);
  EXPECT_THROW(loadScene(dir.write("t.abc", "")), std::runtime_error);
  EXPECT_THROW(loadScene("no-such-scene"), std::runtime_error);
}

// With the scene cache, a scene file is cached as a whole: one cache file, holding each shared texture once,
// that goes stale when the JSON or any file of its models changes.
TEST(SceneLoading, SceneFilesAreCachedAsAWhole) {
  TempFolder dir;
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  dir.write("tex.png", std::string(png.begin(), png.end()));
  dir.write("lib.mtl", "newmtl a\nKd 1 1 1\nmap_Kd tex.png\n");
  const std::string obj = "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
  dir.write("a.obj", obj);
  dir.write("b.obj", obj);
  const std::string json = dir.write("s.json", R"({"models": [{"file": "a.obj"}, {"file": "b.obj"}],
      "environment": {"radiance": [1, 1, 1]}})");
  SceneLoadOptions options;
  options.cache = {true, dir.file("cache")};
  Scene first = loadScene(json, options);
  CachedScene cached;
  const std::string cacheFile = sceneCacheFile(dir.file("cache"), json);
  ASSERT_EQ(readSceneCache(cacheFile, json, cached), SceneCacheRead::Hit);
  EXPECT_EQ(cached.scene.textures.size(), 1u);
  EXPECT_EQ(
      std::distance(std::filesystem::directory_iterator(dir.file("cache")), std::filesystem::directory_iterator()), 1);
  Scene second = loadScene(json, options);
  EXPECT_EQ(second.meshes.size(), 2u);
  EXPECT_EQ(second.textures.size(), 1u);
  for (const std::string& input : {dir.file("b.obj"), dir.file("tex.png"), json}) {
    std::filesystem::last_write_time(input, std::filesystem::last_write_time(input) + std::chrono::seconds(1));
    EXPECT_EQ(readSceneCache(cacheFile, json, cached), SceneCacheRead::Stale) << input;
    loadScene(json, options);
    EXPECT_EQ(readSceneCache(cacheFile, json, cached), SceneCacheRead::Hit) << input;
  }
}

// A glTF with two named cameras and no light: the first camera is taken with a warning naming it and how to
// choose; --camera takes another by name or index; an unknown one is an error listing them; the missing light
// source is a warning.
TEST(SceneLoading, NamesTheCameraTakenAndWarnsWhenNothingEmitsLight) {
  TempFolder dir;
  std::string gltf = R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "cameras": [{"name": "front", "type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}},
                {"name": "side", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}, {"camera": 1, "translation": [3, 0, 0]}],
    "scenes": [{"nodes": [0, 1, 2]}]})";
  std::string path = dir.write("two.gltf", gltf);
  SceneLoadOptions options;
  options.cache.enabled = false;
  testing::internal::CaptureStderr();
  Scene first = loadScene(path, options);
  std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_FLOAT_EQ(first.camera.eye.z, 3.0f);
  EXPECT_NE(warnings.find("2 cameras; taking 0 'front' (choose with --camera NAME|INDEX: 0 'front', 1 'side')"),
            std::string::npos)
      << warnings;
  EXPECT_NE(warnings.find("the scene has no light source"), std::string::npos) << warnings;

  for (const char* choice : {"side", "1"}) {
    options.camera = choice;
    testing::internal::CaptureStderr();
    Scene side = loadScene(path, options);
    warnings = testing::internal::GetCapturedStderr();
    EXPECT_FLOAT_EQ(side.camera.eye.x, 3.0f) << choice;
    EXPECT_EQ(warnings.find("cameras; taking"), std::string::npos) << warnings;
  }
  options.camera = "top";
  testing::internal::CaptureStderr();
  try {
    loadScene(path, options);
    ADD_FAILURE() << "expected an error for an unknown camera";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no camera 'top' (cameras: 0 'front', 1 'side')"), std::string::npos)
        << e.what();
  }
  testing::internal::GetCapturedStderr();

  // Lit by an environment, through a scene file whose own camera comes first: no warning about light.
  options.camera = "models[0]: side";
  testing::internal::CaptureStderr();
  Scene lit = loadScene(dir.write("s.json", R"({"models": [{"file": "two.gltf", "transform": {"translate": [0, 1, 0]}}],
      "camera": {"position": [0, 0, 9], "target": [0, 0, 0]}, "environment": {"radiance": [1, 1, 1]}})"),
                        options);
  warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warnings.find("no light source"), std::string::npos) << warnings;
  ASSERT_EQ(lit.cameras.size(), 3u);
  EXPECT_EQ(lit.cameras[0].name, "camera");
  EXPECT_FLOAT_EQ(lit.camera.eye.x, 3.0f);
  EXPECT_FLOAT_EQ(lit.camera.eye.y, 1.0f);
}

}  // namespace
}  // namespace candela
